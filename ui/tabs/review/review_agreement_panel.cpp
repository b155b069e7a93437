#include "ui/tabs/review/review_agreement_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "core/common/number_format.h"
#include "core/common/paths.h"
#include "core/review/review_figures.h"
#include "ui/scene/colour_maps.h"
#include "ui/widgets/figure_view.h"
#include "ui/widgets/imgui_colour.h"
#include "ui/widgets/palette.h"

namespace lmc::ui {
namespace {

std::string num(double v, int decimals, bool signed_value = false) {
  if (!std::isfinite(v)) return "-";
  return format_readable(v, decimals, signed_value);
}

std::string with_ci(double v, const Interval& ci, int decimals, bool signed_value = false) {
  if (!std::isfinite(v)) return "-";
  // One subject gives a bias but no interval for it: the value alone, the tooltip says why.
  if (!std::isfinite(ci.low) || !std::isfinite(ci.high)) return num(v, decimals, signed_value) + "  [no CI]";
  return num(v, decimals, signed_value) + "  [" + num(ci.low, decimals, signed_value) + ", " +
         num(ci.high, decimals, signed_value) + "]";
}

std::string group_label(const AgreementGroup& g) {
  const std::string name = g.layout == "all" ? std::string("all trials") : g.layout + " layout, " + g.pose;
  return name + " (" + std::to_string(g.n_trials) + " trials, " + std::to_string(g.n_subjects) + " subj.)";
}

void draw_measure_table(const AgreementGroup& g, int& measure, WidgetAnchors& anchors) {
  const ImGuiTableFlags flags =
      ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollY;
  // Every measure's row and the header, no more: the plot below takes what is left.
  const float row_px = ImGui::GetFontSize() + 2.0F * ImGui::GetStyle().CellPadding.y;
  const float height = row_px * static_cast<float>(g.measures.size() + 1) + 4.0F;
  if (!ImGui::BeginTable("agreement", 8, flags, ImVec2(0, height))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("measure");
  ImGui::TableSetupColumn("n (subj.)");
  ImGui::TableSetupColumn("bias LMC-Vicon [95% CI]");
  ImGui::TableSetupColumn("lower limit [CI]");
  ImGui::TableSetupColumn("upper limit [CI]");
  ImGui::TableSetupColumn("RMSE");
  ImGui::TableSetupColumn("r");
  ImGui::TableSetupColumn("ICC(2,1) [CI]");
  ImGui::TableHeadersRow();
  for (size_t m = 0; m < g.measures.size(); ++m) {
    const MeasureAgreement& a = g.measures[m];
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::PushID(static_cast<int>(m));
    const std::string name =
        a.measure.part + " " + (a.measure.quantity == "finger length" ? "length" : "ROM") + " (" + a.measure.unit + ")";
    if (ImGui::Selectable(name.c_str(), measure == static_cast<int>(m), ImGuiSelectableFlags_SpanAllColumns)) {
      measure = static_cast<int>(m);
    }
    anchors.remember("measure." + std::to_string(m));
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      ImGui::TextUnformatted(a.bland_altman.method.c_str());
      ImGui::TextUnformatted(a.icc.description.c_str());
      if (!a.bland_altman.reason.empty()) ImGui::TextDisabled("Bland-Altman: %s", a.bland_altman.reason.c_str());
      if (!a.icc_reason.empty()) ImGui::TextDisabled("ICC: %s", a.icc_reason.c_str());
      if (a.n_skipped > 0) ImGui::TextDisabled("%zu trial(s) without a value on one side were left out", a.n_skipped);
      ImGui::EndTooltip();
    }
    ImGui::PopID();
    const auto& b = a.bland_altman;
    const int d = 1;  // tenths of a mm or a degree: finer than either system measures
    ImGui::TableNextColumn();
    ImGui::Text("%zu (%zu)", a.n_trials, a.n_subjects);
    // A missing number says why rather than showing a dash where it can (one subject gives no
    // between-subject variance, so no limits); the row's tooltip has the whole reason.
    const auto cell = [&a](double v, const Interval& ci, int decimals, bool signed_value) {
      ImGui::TableNextColumn();
      if (std::isfinite(v)) {
        ImGui::TextUnformatted(with_ci(v, ci, decimals, signed_value).c_str());
      } else {
        ImGui::TextDisabled("%s", a.n_subjects == 1 ? "needs 2+ subjects" : "-");
      }
    };
    cell(b.bias, b.bias_ci, d, true);
    cell(b.loa_low, b.loa_low_ci, d, true);
    cell(b.loa_high, b.loa_high_ci, d, true);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(num(a.differences.rmse, d).c_str());
    ImGui::TableNextColumn();
    if (std::isfinite(a.pearson.r))
      ImGui::TextUnformatted(num(a.pearson.r, 2).c_str());
    else  // the line under the table gives the whole reason
      ImGui::TextDisabled("%s", a.n_trials < 3 ? "needs 3+ trials" : "n/a (below)");
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(with_ci(a.icc.value, a.icc.ci, 2).c_str());
  }
  ImGui::EndTable();
}

// The study's map: rows are controllers, columns motion × layout, each cell the mean rate (−1
// "never saw the hand" averaged in, as the paper does) on the viridis scale.
void draw_visibility_map(const VisibilityMap& map) {
  std::set<std::string> devices, columns_seen;
  std::vector<std::pair<std::string, std::string>> columns;  // (layout, motion) in first-seen order
  std::map<std::pair<std::string, std::string>, const VisibilityCell*> cell_at;
  for (const auto& c : map.cells) {
    devices.insert(c.device);
    if (columns_seen.insert(c.layout + "\n" + c.motion).second) columns.emplace_back(c.layout, c.motion);
  }
  std::sort(columns.begin(), columns.end());
  if (devices.empty()) {
    ImGui::TextDisabled("No trials to map.");
    return;
  }
  const int n_columns = 1 + static_cast<int>(columns.size());
  if (!ImGui::BeginTable("visibility_map", n_columns, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingFixedFit)) return;
  ImGui::TableSetupColumn("");
  for (const auto& [layout, motion] : columns) ImGui::TableSetupColumn((layout + "\n" + motion).c_str());
  ImGui::TableHeadersRow();
  for (const auto& device : devices) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(device.c_str());
    for (const auto& [layout, motion] : columns) {
      ImGui::TableNextColumn();
      const VisibilityCell* cell = nullptr;
      for (const auto& c : map.cells) {
        if (c.device == device && c.layout == layout && c.motion == motion) cell = &c;
      }
      if (cell == nullptr || !std::isfinite(cell->rate_mean)) {
        ImGui::TextDisabled("-");
        continue;
      }
      // Rates run from −1 (never saw the hand) to 1; the colour spans that whole range.
      const Rgba colour = viridis((cell->rate_mean + 1.0) / 2.0);
      ImGui::TableSetBgColor(ImGuiTableBgTarget_CellBg, to_u32(colour, 0.85F));
      const bool light = colour.r * 0.3 + colour.g * 0.6 + colour.b * 0.1 > 0.55;
      ImGui::TextColored(light ? palette::kBlack : palette::kWhite, "%s",
                         format_readable(cell->rate_mean, 2, true).c_str());
      if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "%s, %s, %s: %.2f +/- %.2f over %d value(s) from %zu trial(s); %zu of them -1 (never saw the hand)",
            device.c_str(), layout.c_str(), motion.c_str(), cell->rate_mean, cell->rate_sd, cell->values, cell->trials,
            cell->never_saw);
      }
    }
  }
  ImGui::EndTable();
}

}  // namespace

void ReviewAgreementPanel::draw(const PictureRenderer& renderer) {
  anchors_.clear();  // only what this frame drew
  ReviewState& state = *state_;
  const AgreementTable& table = state.agreement().table;
  ImGui::TextDisabled(
      "Across the %zu trial(s) the table shows (its filters apply), %zu without Vicon. Differences are LMC - Vicon; "
      "one trial is one observation.",
      table.trials, table.trials_without_vicon);
  draw_motion_choice();
  if (table.groups.empty()) {
    ImGui::TextDisabled("No trial with Vicon among those shown.");
    return;
  }
  const AgreementGroup& group = draw_group_choice(table);
  ImGui::SameLine();
  draw_export_all();
  measure_ = std::clamp(measure_, 0, std::max(0, static_cast<int>(group.measures.size()) - 1));
  draw_measure_table(group, measure_, anchors_);
  if (!group.measures.empty()) draw_what_is_missing(group.measures[static_cast<size_t>(measure_)]);
  ImGui::Spacing();
  draw_figures(group, renderer);
}

// A joint's range of motion means something else in a static trial than in a flexion trial.
void ReviewAgreementPanel::draw_motion_choice() {
  ReviewState& state = *state_;
  std::set<std::string> motions;
  for (const auto& t : state.trials()) motions.insert(t.row.motion);
  ImGui::SetNextItemWidth(120);
  const std::string current = state.agreement_motion().empty() ? "all motions" : state.agreement_motion();
  if (ImGui::BeginCombo("motion", current.c_str())) {
    if (ImGui::Selectable("all motions", state.agreement_motion().empty())) state.set_agreement_motion("");
    for (const auto& m : motions) {
      if (ImGui::Selectable(m.c_str(), m == state.agreement_motion())) state.set_agreement_motion(m);
    }
    ImGui::EndCombo();
  }
  anchors_.remember("motion");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("A joint's range of motion means something else in a static trial than in a flexion trial");
}

// The group shown (layout and pose, or every trial pooled: the last, and the default).
const AgreementGroup& ReviewAgreementPanel::draw_group_choice(const AgreementTable& table) {
  const int last = static_cast<int>(table.groups.size()) - 1;
  const int g = group_ < 0 || group_ > last ? last : group_;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(320);
  if (ImGui::BeginCombo("group", group_label(table.groups[static_cast<size_t>(g)]).c_str())) {
    for (int k = 0; k <= last; ++k) {
      if (ImGui::Selectable(group_label(table.groups[static_cast<size_t>(k)]).c_str(), k == g))
        group_ = k == last ? -1 : k;
    }
    ImGui::EndCombo();
  }
  anchors_.remember("group");
  return table.groups[static_cast<size_t>(g)];
}

void ReviewAgreementPanel::draw_export_all() {
  ReviewState& state = *state_;
  ImGui::BeginDisabled(state.exporting());
  if (ImGui::Button("Export all...")) export_browser_.open(FileBrowser::Mode::kSave, sessions_dir(), "review-export");
  anchors_.remember("export_all");
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "The agreement table (CSV, JSON), a Bland-Altman plot per group and measure, the visibility map and the "
        "study's tables: SVG with the CSV behind each figure and a JSON sidecar (lmc figures writes the same)");
  }
  if (const auto chosen = export_browser_.draw()) state.export_agreement(*chosen);
  if (!state.export_message().empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", state.export_message().c_str());
  }
}

// What the table could not compute, in words (the statistics say why; the same for every measure
// of a one-subject group, so the selected one speaks for the rest).
void ReviewAgreementPanel::draw_what_is_missing(const MeasureAgreement& chosen) {
  const auto& selected = chosen.bland_altman;
  std::string missing;
  if (!selected.reason.empty() && std::isfinite(selected.bias)) missing += "Bland-Altman: " + selected.reason + ". ";
  if (!chosen.pearson.reason.empty()) missing += "r: " + chosen.pearson.reason + ". ";
  if (!chosen.icc_reason.empty()) missing += "ICC: " + chosen.icc_reason + ".";
  if (missing.empty()) return;
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", missing.c_str());
  ImGui::PopStyleColor();
  anchors_.remember("agreement.missing");
}

// The selected measure's Bland-Altman plot beside the visibility map.
void ReviewAgreementPanel::draw_figures(const AgreementGroup& group, const PictureRenderer& renderer) {
  const ReviewState::Agreement& agreement = state_->agreement();
  const float width = ImGui::GetContentRegionAvail().x;
  const float height = std::max(160.0F, ImGui::GetContentRegionAvail().y - 4);
  ImGui::BeginChild("bland_altman", ImVec2(width * 0.5F, height), false);
  if (!group.measures.empty()) {
    const Figure figure = bland_altman_figure(group, group.measures[static_cast<size_t>(measure_)]);
    png_.draw("ba_png", renderer,
              figure_stem("bland-altman-" + group.layout + "-" + group.pose + "-" +
                          group.measures[static_cast<size_t>(measure_)].measure.name),
              [&figure] { draw_figure_filling("ba", figure); });
    ImGui::SameLine();  // the figure's title beside its button: a line more for the plot
    draw_figure_view("ba", figure, std::max(90.0F, height - 6.6F * ImGui::GetTextLineHeightWithSpacing()));
  }
  ImGui::EndChild();
  ImGui::SameLine();
  // Its own scrollbar from the start: on a short window (1024 x 700) the map's last rows are below
  // the panel from the first frame at that size, before ImGui would add one.
  ImGui::BeginChild("visibility_map_panel", ImVec2(0, height), false, ImGuiWindowFlags_AlwaysVerticalScrollbar);
  ImGui::TextWrapped("Visibility rate per controller, motion and layout (the study's map; -1 = never saw the hand)");
  // The picture runs inside draw() (the renderer is synchronous), so the map is read in place and
  // its figure built only when a PNG is taken.
  map_png_.draw("map_png", renderer, "visibility-map",
                [&agreement] { draw_figure_filling("map", visibility_map_figure(agreement.visibility)); });
  draw_visibility_map(agreement.visibility);
  ImGui::EndChild();
}

}  // namespace lmc::ui
