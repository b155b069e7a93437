#include "ui/tabs/layout/coverage_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/common/paths.h"
#include "ui/scene/colour_maps.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {
ImU32 cell_colour(double share, float alpha) {
  const Rgba c = viridis(share);
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, alpha));
}
}  // namespace

void CoveragePanel::draw() {
  const LayoutState& s = *state_;
  ImGui::TextUnformatted("Coverage");
  ImGui::SameLine();
  if (!draw_status()) return;
  const CoverageSnapshotPtr snap = s.coverage().latest();
  if (!snap || snap->all.devices == 0) return;
  draw_table(snap->all);
  draw_metric(*snap);
  draw_histogram(snap->all);
}

// The pose set, Report..., and whether the numbers are being updated; false while there is no
// pose set to count on.
bool CoveragePanel::draw_status() {
  LayoutState& s = *state_;
  const PoseSetPtr poses = s.poses.current();
  if (!poses) {
    ImGui::TextDisabled(s.poses.error().empty() ? "- loading the pose set..." : "- pose set failed to load");
    if (!s.poses.error().empty()) ImGui::TextColored(palette::kError, "%s", s.poses.error().c_str());
    return false;
  }
  ImGui::TextDisabled("on %d pose-set frames", poses->size());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", poses->set.description.c_str());
  ImGui::SameLine();
  ImGui::BeginDisabled(s.report_job().running());
  if (ImGui::SmallButton("Report...")) report_browser_.open(FileBrowser::Mode::kSave, sessions_dir(), "layout-report");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Write the one-page layout report (report.md, a top view and per-pose redundancy as SVG with their data), "
        "as lmc evaluate --report does, for this layout and pose set");
  }
  if (const auto chosen = report_browser_.draw()) s.start_report(*chosen);
  if (const std::string m = s.report_job().message(); !m.empty()) ImGui::TextDisabled("%s", m.c_str());
  if (!s.coverage().up_to_date()) {
    ImGui::SameLine();
    ImGui::TextColored(palette::kWarning, "updating");
  }
  if (!s.coverage().error().empty()) ImGui::TextColored(palette::kError, "%s", s.coverage().error().c_str());
  return true;
}

// Controllers × fingers, then the frames in which nobody sees each finger.
void CoveragePanel::draw_table(const Coverage& c) const {
  const LayoutState& s = *state_;
  const Layout& l = s.layout();
  const ImGuiTableFlags flags = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchSame;
  if (!ImGui::BeginTable("##coverage", kNumDigits + 1, flags)) return;
  ImGui::TableSetupColumn("seen by", ImGuiTableColumnFlags_WidthFixed, 86.0f);
  for (int k = 0; k < kNumDigits; ++k) ImGui::TableSetupColumn(std::string(digit_name(k)).c_str());
  ImGui::TableHeadersRow();
  for (int d = 0; d < c.devices; ++d) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    const char* slot = d < l.device_count() ? l.devices[static_cast<size_t>(d)].slot.c_str() : "?";
    if (d == s.selected()) {
      ImGui::TextColored(palette::kAttention, "%s", slot);
    } else {
      ImGui::TextUnformatted(slot);
    }
    for (int k = 0; k < kNumDigits; ++k) {
      ImGui::TableSetColumnIndex(k + 1);
      const double f = c.device_finger_fraction(d, k);
      ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, cell_colour(f, 0.45f));
      ImGui::Text("%5.1f %%", f * 100.0);
    }
  }
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextColored(palette::kError, "nobody");
  for (int k = 0; k < kNumDigits; ++k) {
    ImGui::TableSetColumnIndex(k + 1);
    const double f = c.finger_unseen_fraction(k);
    if (f > 0) ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, palette::unseen_cell(f));
    ImGui::Text("%5.1f %%", f * 100.0);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%lld of %lld frames: no controller sees the %s",
                        static_cast<long long>(c.finger_unseen[static_cast<size_t>(k)]),
                        static_cast<long long>(c.frames), std::string(digit_name(k)).c_str());
    }
  }
  ImGui::EndTable();
}

void CoveragePanel::draw_metric(const CoverageSnapshot& snap) {
  ImGui::Text("M = %.4g", snap.all.metric);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "M = sum c_i / N^(i+1) over i < D (docs/algorithms/metric.md): lower is better, 0 when every\n"
        "controller sees every finger in every frame. One frame with an unseen finger\n"
        "outweighs any number of frames seen by a single controller.");
  }
  ImGui::SameLine(0, 18);
  ImGui::TextDisabled("horizontal M %.3g · vertical M %.3g", snap.horizontal.metric, snap.vertical.metric);
}

// The c_i histogram: frames whose worst-seen finger is seen by exactly i controllers.
void CoveragePanel::draw_histogram(const Coverage& c) {
  const float label_w = 46, full_w = std::max(60.0f, ImGui::GetContentRegionAvail().x - label_w - 120);
  const std::int64_t n = std::max<std::int64_t>(1, c.frames);
  for (size_t i = 0; i < c.c.size(); ++i) {
    ImGui::Text("c_%zu", i);
    ImGui::SameLine(label_w);
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float frac = static_cast<float>(c.c[i]) / static_cast<float>(n);
    const float h = ImGui::GetTextLineHeight() - 2;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->AddRectFilled(ImVec2(p.x, p.y + 1), ImVec2(p.x + full_w, p.y + 1 + h), palette::kTableBar, 2.0f);
    const Rgba col = seen_count_colour(static_cast<int>(i));
    dl->AddRectFilled(ImVec2(p.x, p.y + 1), ImVec2(p.x + full_w * frac, p.y + 1 + h),
                      ImGui::ColorConvertFloat4ToU32(ImVec4(col.r, col.g, col.b, 0.9f)), 2.0f);
    ImGui::Dummy(ImVec2(full_w, h));
    ImGui::SameLine();
    ImGui::Text("%6lld  %5.1f %%", static_cast<long long>(c.c[i]), frac * 100.0);
  }
}

}  // namespace lmc::ui
