#include "ui/tabs/review/review_trial_view_panel.h"

#include <imgui.h>

#include <algorithm>
#include <string>

#include "core/common/paths.h"
#include "core/processing/measures.h"
#include "core/review/review_figures.h"
#include "ui/widgets/figure_view.h"
#include "ui/widgets/flow_row.h"
#include "ui/widgets/label_strips.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {

constexpr const char* kFingerWords[] = {"thumb", "index", "middle", "ring", "pinky"};
// Palette slots: fused and Vicon keep theirs whatever else is shown; controllers follow.
constexpr int kFusedColour = 0, kViconColour = 7, kFirstDeviceColour = 1;

std::vector<PlotSeries> series_for(const TrialSeries& s, bool angle, int index, bool each_controller) {
  const auto pick = [&](const MeasureSeries& m) -> const std::vector<double>& {
    return angle ? m.angle_deg[static_cast<size_t>(index)] : m.finger_mm[static_cast<size_t>(index)];
  };
  std::vector<PlotSeries> out;
  out.push_back({"fused LMC", s.time_s, pick(s.fused), kFusedColour});
  if (s.has_vicon) out.push_back({"Vicon", s.time_s, pick(s.vicon), kViconColour});
  if (each_controller) {
    for (size_t d = 0; d < s.devices.size(); ++d) {
      out.push_back({"LMC" + std::to_string(s.devices[d].device_id), s.time_s, pick(s.devices[d].measures),
                     kFirstDeviceColour + static_cast<int>(d)});
    }
  }
  return out;
}

}  // namespace

SeriesPlot& ReviewTrialViewPanel::plot(const std::string& id, const std::shared_ptr<LinkedXRange>& range) {
  auto& p = plots_[id];
  if (!p || p->x_range() != range) p = std::make_unique<SeriesPlot>(range);
  return *p;
}

void ReviewTrialViewPanel::draw(const PictureRenderer& renderer) {
  anchors_.clear();  // only what this frame drew
  ReviewState& state = *state_;
  const auto view = state.view();
  if (!view) {
    if (state.view_job().running()) {
      ImGui::TextDisabled("Processing %s...", state.view_job().trial().c_str());
    } else if (state.selected() < 0) {
      ImGui::TextDisabled("Click a trial in the table to see it against Vicon.");
    } else if (state.view_job().state() == JobState::kFailed) {
      ImGui::TextColored(palette::kError, "%s", state.view_job().error().c_str());
    }
    return;
  }
  draw_header(view, renderer);
  // Plots on the left, the 3D replay at the cursor's time on the right.
  const float replay_width = std::clamp(ImGui::GetContentRegionAvail().x * 0.36F, 280.0F, 560.0F);
  ImGui::BeginChild("plots", ImVec2(ImGui::GetContentRegionAvail().x - replay_width - 6, 0), false);
  draw_plots(view->series);
  ImGui::EndChild();
  ImGui::SameLine();
  if (const auto window =
          replay_.window(ImVec2(0, 0), false, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse))
    replay_.draw();
}

// The trial's name and length, the fusion, "each controller", Export trial..., the PNG, and its
// warnings.
void ReviewTrialViewPanel::draw_header(const std::shared_ptr<const TrialView>& view, const PictureRenderer& renderer) {
  ReviewState& state = *state_;
  const TrialSeries& s = view->series;
  ImGui::Text("%s", s.trial.c_str());
  ImGui::SameLine();
  ImGui::TextDisabled("%.2f s, %s fusion%s%s", s.time_s.empty() ? 0.0 : s.time_s.back(),
                      fusion_method_name(view->result->method),
                      view->result->length_correction ? " with the subject's finger-length correction" : "",
                      s.has_vicon ? ", against Vicon" : ", no Vicon file");
  ImGui::SameLine(0, 20);
  ImGui::Checkbox("each controller", &each_controller_);
  anchors_.remember("each_controller");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Also draw each controller's own angles after realignment (LMC1-LMC4)");
  ImGui::SameLine();
  ImGui::BeginDisabled(state.exporting());
  if (ImGui::Button("Export trial...")) {
    export_browser_.open(FileBrowser::Mode::kSave, sessions_dir(), "review-" + figure_stem(s.trial));
  }
  anchors_.remember("export_trial");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("SVG of every plot, the CSV behind it, a JSON sidecar, and every series and label as one CSV");
  if (const auto chosen = export_browser_.draw()) state.export_trial(*chosen, each_controller_);
  ImGui::SameLine();
  // The PNG shows what the SVG export shows: every panel of the trial's figure, stacked. The
  // figure is built only when a picture is taken, not every frame.
  png_.draw("trial_png", renderer, figure_stem("trial-" + s.trial),
            [view, each = each_controller_] { draw_figure_grid_filling(trial_figure(view->series, each)); });
  if (!state.export_message().empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", state.export_message().c_str());
  }
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Every plot shares one time axis: wheel zooms, drag pans, double-click shows the whole trial.\n"
        "The cursor shows each series' value; missing values are gaps over a faint band, never 0.\n"
        "Click a legend entry to hide or show its series.");
  }
  if (!view->warnings.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(palette::kWarning, "%zu warning(s)", view->warnings.size());
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (const auto& w : view->warnings) ImGui::TextUnformatted(w.c_str());
      ImGui::EndTooltip();
    }
  }
}

// The six angles and a finger's length against one time axis, then the label strips that
// explain every gap in them.
void ReviewTrialViewPanel::draw_plots(const TrialSeries& s) {
  ReviewState& state = *state_;
  const auto& range = state.x_range();
  std::vector<LabelStrip> strips;
  for (const auto& d : s.devices) {
    for (int k = 0; k < kNumFingers; ++k) {
      strips.push_back({"LMC" + std::to_string(d.device_id), kFingerWords[k], d.label[static_cast<size_t>(k)]});
    }
  }
  // The label strips explain every gap in the curves, so they keep their room at the foot: the
  // curves scroll in what is left when the window is small (at 1280 × 800 they fit).
  constexpr float kStripPx = 4.0F;
  const ImGuiStyle& style = ImGui::GetStyle();
  const float strips_block = ImGui::GetTextLineHeightWithSpacing() + label_strips_height(strips, kStripPx) +
                             style.ItemSpacing.y + style.WindowPadding.y;
  const float curves_px = std::max(120.0F, ImGui::GetContentRegionAvail().y - strips_block);
  ImGui::BeginChild("curves", ImVec2(0, curves_px), false);
  const float curves_top = ImGui::GetCursorPosY();
  // Index joints on the left, thumb and wrist on the right: six angles in three rows, so the
  // finger length and the label strips that explain every gap stay on screen at 1280 x 800.
  // Four plot areas share what the legends and axes leave: 46 px each when there is room, down
  // to 34 px (the trial table above may take more of the tab) before the curves scroll.
  SeriesPlotOptions o;
  o.height_px = curves_chrome_px_ > 0.0F ? std::clamp((curves_px - curves_chrome_px_) / 4.0F, 34.0F, 46.0F) : 46.0F;
  if (ImGui::BeginTable("angles", 2, ImGuiTableFlags_SizingStretchSame)) {
    for (int row = 0; row < 3; ++row) {
      for (int a : {row, row + 3}) {
        ImGui::TableNextColumn();
        o.y_label = std::string(angle_name(a)) + " (deg)";
        const std::string id = "angle" + std::to_string(a);
        plot(id, range).draw(id.c_str(), series_for(s, true, a, each_controller_), o);
      }
    }
    ImGui::EndTable();
  }
  ImGui::SetNextItemWidth(90);
  ImGui::Combo("##finger", &finger_, "thumb\0index\0middle\0ring\0pinky\0");
  ImGui::SameLine();
  o.y_label = "length (mm)";
  o.x_label = "time (s)";
  plot("finger", range).draw("finger", series_for(s, false, finger_, each_controller_), o);
  curves_chrome_px_ = ImGui::GetCursorPosY() - curves_top - 4.0F * o.height_px;
  ImGui::EndChild();

  ImGui::TextDisabled("Ray-traced labels per controller (thumb at the top):");
  same_line_or_wrap(ImGui::GetTextLineHeight() + ImGui::CalcTextSize("seen (ray-traced)").x);
  draw_label_legend();
  draw_label_strips("labels", s.time_s, strips, *range, kStripPx);
}

}  // namespace lmc::ui
