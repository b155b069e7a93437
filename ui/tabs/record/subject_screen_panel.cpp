#include "ui/tabs/record/subject_screen_panel.h"

#include <imgui.h>

#include <algorithm>

#include "ui/model/record/subject_text_scale.h"
#include "ui/widgets/hand_pictogram.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {

// Text in `font` drawn at `scale` times its size (subject_text_scale.h: the window decides).
void text_at(ImFont* font, float scale, ImVec2 pos, ImU32 colour, const std::string& text, float wrap_width = 0.0F) {
  ImGui::GetWindowDrawList()->AddText(font, font->FontSize * scale, pos, colour, text.c_str(), nullptr, wrap_width);
}

float text_height(ImFont* font, float scale, const std::string& text, float wrap_width) {
  return font->CalcTextSizeA(font->FontSize * scale, 1e9F, wrap_width, text.c_str()).y;
}

}  // namespace

void SubjectScreenPanel::draw(const SubjectFonts& fonts) {
  const SubjectView& v = link_.view;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(size);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, palette::kSubjectBackground);
  ImGui::Begin("##subject", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::PopStyleColor();
  const float w = size.x, h = size.y;
  const float scale = subject_text_scale(w, h);
  const float margin = 0.04F * h;  // kept free below the last line
  const ImU32 white = palette::kSubjectText;
  const ImU32 grey = palette::kSubjectDim;
  if (v.stage == SubjectStage::kDone || v.stage == SubjectStage::kNoSession) {
    const float top = 0.25F * h;
    const float s = fit_subject_text_scale(scale, h - margin - top, [&](float k) {
      return fonts.huge->FontSize * k * 1.1F + text_height(fonts.large, k, v.cue, 0.88F * w);
    });
    text_at(fonts.huge, s, ImVec2(0.06F * w, top), white, v.headline);
    text_at(fonts.large, s, ImVec2(0.06F * w, top + fonts.huge->FontSize * s * 1.1F), white, v.cue, 0.88F * w);
    ImGui::End();
    return;
  }
  ImDrawList* dl = ImGui::GetWindowDrawList();
  // The circle: red and filled while recording, a grey ring otherwise (the countdown inside it).
  const float r = std::min(0.19F * h, 0.14F * w);
  const ImVec2 c(0.05F * w + r, 0.05F * h + r);
  if (v.red_circle) {
    dl->AddCircleFilled(c, r, palette::kSubjectCircle, 96);
  } else {
    dl->AddCircle(c, r, grey, 96, 6.0F);
  }
  if (v.stage == SubjectStage::kCountdown) {
    const float size_px = fonts.huge->FontSize * scale;
    const ImVec2 t = fonts.huge->CalcTextSizeA(size_px, 1e9F, 0.0F, v.headline.c_str());
    text_at(fonts.huge, scale, ImVec2(c.x - 0.5F * t.x, c.y - 0.5F * t.y), white, v.headline);
  }
  const float right_of_circle = c.x + r + 0.04F * w;
  const float large_px = fonts.large->FontSize * scale;
  const std::string headline = v.stage == SubjectStage::kCountdown ? std::string("Starting") : v.headline;
  text_at(fonts.large, scale, ImVec2(right_of_circle, c.y - large_px),
          v.red_circle ? palette::kSubjectRecordingText : white, headline);
  if (!v.time_text.empty())
    text_at(fonts.large, scale, ImVec2(right_of_circle, c.y + 0.1F * large_px), white, v.time_text);
  // The cue on the left, the pictogram on the right; the cue and the hand line below it shrink
  // together until the last line is inside the window.
  const float top = c.y + r + 0.06F * h;
  const float cue_width = v.pictogram ? 0.50F * w : 0.90F * w;
  const std::string pose_line = v.pose_cue.empty() ? std::string() : "Hand: " + v.pose_cue;
  const auto cue_block_height = [&](float k) {
    float y = text_height(fonts.large, k, v.cue, cue_width);
    if (!pose_line.empty()) y += 0.03F * h + text_height(fonts.normal, k, pose_line, cue_width);
    return y;
  };
  const float cue_scale = fit_subject_text_scale(scale, h - margin - top, cue_block_height);
  text_at(fonts.large, cue_scale, ImVec2(0.05F * w, top), palette::kSubjectCue, v.cue, cue_width);
  if (!pose_line.empty()) {
    const float cue_h = text_height(fonts.large, cue_scale, v.cue, cue_width);
    text_at(fonts.normal, cue_scale, ImVec2(0.05F * w, top + cue_h + 0.03F * h), grey, pose_line, cue_width);
  }
  if (v.pictogram) {
    const float px = 0.58F * w, py = 0.30F * h;
    ImGui::SetCursorScreenPos(ImVec2(px, py));
    draw_hand_pictogram(*v.pictogram, ImVec2(0.38F * w, 0.64F * h));
  }
  ImGui::End();
}

}  // namespace lmc::ui
