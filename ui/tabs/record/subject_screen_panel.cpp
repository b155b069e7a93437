#include "ui/tabs/record/subject_screen_panel.h"

#include <imgui.h>

#include <algorithm>

#include "ui/widgets/hand_pictogram.h"

namespace lmc::ui {
namespace {

void text_at(ImFont* font, ImVec2 pos, ImU32 colour, const std::string& text, float wrap_width = 0.0F) {
  ImGui::GetWindowDrawList()->AddText(font, font->FontSize, pos, colour, text.c_str(), nullptr, wrap_width);
}

}  // namespace

void draw_subject_screen(const SubjectView& v, const SubjectFonts& fonts) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(size);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(0, 0, 0, 255));
  ImGui::Begin("##subject", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::PopStyleColor();
  const float w = size.x, h = size.y;
  const ImU32 white = IM_COL32(235, 235, 235, 255);
  const ImU32 grey = IM_COL32(130, 130, 135, 255);
  if (v.stage == SubjectStage::kNoSession) {
    text_at(fonts.normal, ImVec2(0.05F * w, 0.45F * h), grey, "Subject screen: waiting for the operator to open a session.");
    ImGui::End();
    return;
  }
  if (v.stage == SubjectStage::kDone) {
    text_at(fonts.huge, ImVec2(0.06F * w, 0.25F * h), white, v.headline);
    text_at(fonts.large, ImVec2(0.06F * w, 0.25F * h + fonts.huge->FontSize * 1.1F), white, v.cue, 0.88F * w);
    ImGui::End();
    return;
  }
  ImDrawList* dl = ImGui::GetWindowDrawList();
  // The circle: red and filled while recording, a grey ring otherwise (the countdown inside it).
  const float r = std::min(0.19F * h, 0.14F * w);
  const ImVec2 c(0.05F * w + r, 0.05F * h + r);
  if (v.red_circle) {
    dl->AddCircleFilled(c, r, IM_COL32(230, 30, 30, 255), 96);
  } else {
    dl->AddCircle(c, r, grey, 96, 6.0F);
  }
  if (v.stage == SubjectStage::kCountdown) {
    const ImVec2 t = fonts.huge->CalcTextSizeA(fonts.huge->FontSize, 1e9F, 0.0F, v.headline.c_str());
    text_at(fonts.huge, ImVec2(c.x - 0.5F * t.x, c.y - 0.5F * t.y), white, v.headline);
  }
  const float right_of_circle = c.x + r + 0.04F * w;
  const std::string headline = v.stage == SubjectStage::kCountdown ? std::string("Starting") : v.headline;
  text_at(fonts.large, ImVec2(right_of_circle, c.y - fonts.large->FontSize), v.red_circle ? IM_COL32(255, 80, 70, 255) : white,
          headline);
  if (!v.time_text.empty()) text_at(fonts.large, ImVec2(right_of_circle, c.y + 0.1F * fonts.large->FontSize), white, v.time_text);
  // The cue on the left, the pictogram on the right.
  const float top = c.y + r + 0.06F * h;
  const float cue_width = v.pictogram ? 0.50F * w : 0.90F * w;
  text_at(fonts.large, ImVec2(0.05F * w, top), IM_COL32(255, 230, 130, 255), v.cue, cue_width);
  const ImVec2 cue_size = fonts.large->CalcTextSizeA(fonts.large->FontSize, 1e9F, cue_width, v.cue.c_str());
  if (!v.pose_cue.empty())
    text_at(fonts.normal, ImVec2(0.05F * w, top + cue_size.y + 0.03F * h), grey, "Hand: " + v.pose_cue, cue_width);
  if (v.pictogram) {
    const float px = 0.58F * w, py = 0.30F * h;
    ImGui::SetCursorScreenPos(ImVec2(px, py));
    draw_hand_pictogram(*v.pictogram, ImVec2(0.38F * w, 0.64F * h));
  }
  ImGui::End();
}

}  // namespace lmc::ui
