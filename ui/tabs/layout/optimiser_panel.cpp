#include "ui/tabs/layout/optimiser_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>

#include "core/metric/robust_metric.h"
#include "ui/widgets/palette.h"
#include "ui/widgets/progress_row.h"
#include "ui/widgets/series_plot.h"

namespace lmc::ui {

OptimiserPanel::OptimiserPanel(std::shared_ptr<LayoutState> state)
    : Panel("##optimiser_body"), state_(std::move(state)) {}

void OptimiserPanel::draw() {
  anchors_.clear();
  // Start / progress / Apply / Discard stay at the bottom of the panel whatever is expanded above
  // them (with Search settings open they fell below the panel); the rest scrolls.
  // The footer is as high as it was last drawn (its result text wraps on a narrow panel), and
  // never lower than its rows need now: the progress row is two lines (with one line reserved,
  // "elapsed ... remaining ..." fell off the bottom of the panel at 1280 x 800).
  const float line = ImGui::GetFrameHeightWithSpacing();
  const float rows = state_->optimiser().running() ? 2.0f : state_->optimiser().outcome() ? 3.0f : 1.0f;
  const float footer_h = std::max(rows * line, footer_h_) + 4.0f;
  if (const auto window = this->window(ImVec2(0, -footer_h))) {
    if (ImGui::CollapsingHeader("Pose set", ImGuiTreeNodeFlags_DefaultOpen)) draw_pose_set();
    if (open_settings_once_) ImGui::SetNextItemOpen(true);
    if (ImGui::CollapsingHeader("Search settings")) draw_settings();
    open_settings_once_ = false;
    draw_convergence();
    draw_comparison();
  }
  const float footer_top = ImGui::GetCursorPosY();
  draw_run();
  footer_h_ = ImGui::GetCursorPosY() - footer_top;
}

void OptimiserPanel::draw_pose_set() {
  LayoutState& s = *state_;
  if (!choice_synced_ || (!ImGui::IsAnyItemActive() && !(edit_choice_ == s.doc().pose_set) && !browser_.is_open())) {
    edit_choice_ = s.doc().pose_set;
    std::snprintf(file_buf_, sizeof file_buf_, "%s", edit_choice_.file.c_str());
    std::snprintf(recordings_buf_, sizeof recordings_buf_, "%s",
                  edit_choice_.recordings.empty() ? "" : edit_choice_.recordings.front().c_str());
    std::snprintf(trials_buf_, sizeof trials_buf_, "%s", edit_choice_.trials_glob.c_str());
    choice_synced_ = true;
  }
  int src = static_cast<int>(edit_choice_.source);
  ImGui::RadioButton("Monte Carlo", &src, 0);
  ImGui::SameLine();
  ImGui::RadioButton("File", &src, 1);
  ImGui::SameLine();
  ImGui::RadioButton("From recordings...", &src, 2);
  anchors_.remember("pose_set.from_recordings");
  edit_choice_.source = static_cast<PoseSetChoice::Source>(src);
  if (edit_choice_.source == PoseSetChoice::Source::kMonteCarlo) {
    ImGui::SetNextItemWidth(110);
    ImGui::InputInt("frames", &edit_choice_.frames, 100, 1000);
    edit_choice_.frames = std::clamp(edit_choice_.frames, 1, 1000000);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    ImGui::InputScalar("seed", ImGuiDataType_U64, &edit_choice_.seed);
  } else if (edit_choice_.source == PoseSetChoice::Source::kFile) {
    ImGui::SetNextItemWidth(-90);
    if (ImGui::InputTextWithHint("##file", "poses.tsv (lmc poses -o) or recipe.json", file_buf_, sizeof file_buf_)) {
      edit_choice_.file = file_buf_;
    }
    ImGui::SameLine();
    if (ImGui::Button("Browse...")) browser_.open(FileBrowser::Mode::kOpen, std::filesystem::current_path());
  } else {
    draw_recordings_choice();
  }
  if (auto chosen = browser_.draw()) {
    edit_choice_.file = chosen->string();
    std::snprintf(file_buf_, sizeof file_buf_, "%s", edit_choice_.file.c_str());
  }
  if (auto chosen = recordings_browser_.draw()) {
    edit_choice_.recordings = {chosen->parent_path().string()};
    std::snprintf(recordings_buf_, sizeof recordings_buf_, "%s", edit_choice_.recordings.front().c_str());
  }
  const bool differs = !(edit_choice_ == s.doc().pose_set);
  ImGui::BeginDisabled(!differs);
  if (ImGui::Button("Use this pose set")) s.report(set_pose_set_choice(s.upd_history(), edit_choice_), "Pose set");
  ImGui::EndDisabled();
  ImGui::SameLine();
  draw_pose_set_status();
}

// The pose set in use: its loading progress (with Cancel), or its frames, where they came from and
// the trials left out; and why it failed to load.
void OptimiserPanel::draw_pose_set_status() {
  LayoutState& s = *state_;
  if (s.poses.loading()) {
    ImGui::TextDisabled("%s... %.0f %%", s.poses.stage().c_str(), 100.0 * s.poses.progress());
    ImGui::SameLine();
    if (ImGui::SmallButton("Cancel##pose_set")) s.cancel_pose_set_load();
    anchors_.remember("pose_set.cancel");
  } else if (const PoseSetPtr p = s.poses.current()) {
    ImGui::TextDisabled("%d frames: %zu horizontal, %zu vertical", p->size(), p->horizontal.size(), p->vertical.size());
    if (!p->set.provenance.empty() || !p->left_out.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      for (const auto& line : p->set.provenance) ImGui::TextDisabled("%s", line.c_str());
      if (!p->left_out.empty()) {
        ImGui::TextColored(palette::kWarning, "%zu trials left out (hover)", p->left_out.size());
        if (ImGui::IsItemHovered()) {
          std::string all;
          for (const auto& l : p->left_out) all += l + "\n";
          ImGui::SetTooltip("%s", all.c_str());
        }
      }
      ImGui::PopTextWrapPos();
    }
  }
  if (!s.poses.error().empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(palette::kError, "%s", s.poses.error().c_str());
    ImGui::PopTextWrapPos();
  }
}

void OptimiserPanel::draw_recordings_choice() {
  ImGui::SetNextItemWidth(-90);
  if (ImGui::InputTextWithHint("##recordings", "processed trials folder (lmc process -o) or session folder",
                               recordings_buf_, sizeof recordings_buf_)) {
    edit_choice_.recordings.clear();
    if (recordings_buf_[0] != '\0') edit_choice_.recordings.emplace_back(recordings_buf_);
  }
  ImGui::SameLine();
  if (ImGui::Button("Browse...##recordings"))
    recordings_browser_.open(FileBrowser::Mode::kOpen, std::filesystem::current_path());
  static const char* const kSources[] = {"fused", "vicon", "LMC1", "LMC2", "LMC3", "LMC4"};
  int source = 0;
  for (int i = 0; i < 6; ++i) {
    if (edit_choice_.recorded_source == kSources[i]) source = i;
  }
  ImGui::SetNextItemWidth(90);
  if (ImGui::Combo("hand from", &source, kSources, 6)) edit_choice_.recorded_source = kSources[source];
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "fused: the fused hand of processed trials (lmc process output)\n"
        "vicon: the trials' Vicon markers mapped to the hand's points\n"
        "LMCn: one controller's hand, realigned with each trial's layout");
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(110);
  if (ImGui::InputTextWithHint("trials", "*Index*", trials_buf_, sizeof trials_buf_))
    edit_choice_.trials_glob = trials_buf_;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(50);
  ImGui::InputInt("every", &edit_choice_.every, 0, 0);
  edit_choice_.every = std::clamp(edit_choice_.every, 1, 1000);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Keep every N-th frame of each trial");
  // Review hands over one file per trial; the field shows the first.
  if (edit_choice_.recordings.size() > 1)
    ImGui::TextDisabled("%zu trials from Review (the field shows the first)", edit_choice_.recordings.size());
}

void OptimiserPanel::draw_settings() {
  LayoutState& s = *state_;
  PsoSettings p = s.pso();
  draw_metric(p);
  draw_swarm(p);
  s.set_pso(p);
  ImGui::Spacing();
  draw_movable();
  draw_bounds();
}

void OptimiserPanel::draw_metric(PsoSettings& p) {
  int metric = static_cast<int>(p.metric);
  ImGui::SetNextItemWidth(300);  // the whole of its longest choice
  if (ImGui::Combo("metric", &metric, "study: M only (the reference)\0robust: M, then every controller counts\0")) {
    p.metric = static_cast<PlacementMetricKind>(metric);
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "robust = M + tie-breakers: redundancy (fingers seen by 2+ controllers), participation\n"
        "(each controller sees a finger in 20 %% of frames), axis cut (seen markers within 250 mm),\n"
        "centring, footprints that do not overlap, and M inside the cut (what the controllers\n"
        "can measure: a finger with a marker beyond a controller's cut unseen by it).\n"
        "lmc evaluate prints every term.");
  }
  if (open_settings_once_) ImGui::SetNextItemOpen(true);
  if (p.metric == PlacementMetricKind::kRobust && ImGui::TreeNode("term weights (0 switches a term off)")) {
    // One input per term, from the same list the reports print (robust_term_infos).
    for (const RobustTermInfo& term : robust_term_infos()) {
      if (term.weight == nullptr) continue;  // M always counts with weight 1
      double& w = p.weights.*(term.weight);
      ImGui::SetNextItemWidth(90);
      ImGui::InputDouble(term.name, &w, 0, 0, "%.3f");
      if (!(w >= 0.0)) w = 0.0;
      if (ImGui::IsItemHovered()) {
        std::string option = std::string("--w-") + term.key;
        std::replace(option.begin(), option.end(), '_', '-');
        ImGui::SetTooltip("%s (lmc optimize %s)", term.meaning, option.c_str());
      }
    }
    if (ImGui::SmallButton("default weights")) p.weights = RobustWeights{};
    ImGui::TreePop();
  }
}

void OptimiserPanel::draw_swarm(PsoSettings& p) {
  LayoutState& s = *state_;
  // Rows short enough for the panel at 1280 x 800 (three inputs in a row pushed "starts" off it).
  ImGui::SetNextItemWidth(100);
  ImGui::InputInt("particles", &p.particles);
  p.particles = std::clamp(p.particles, 2, 1000);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(100);
  ImGui::InputInt("iterations", &p.iterations);
  p.iterations = std::clamp(p.iterations, 1, 10000);
  ImGui::SetNextItemWidth(100);
  int starts = s.optimiser_starts();
  if (ImGui::InputInt("starts", &starts)) s.set_optimiser_starts(starts);
  anchors_.remember("starts");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Several swarms from seeds seed, seed+1, ... one after another; the best is kept and the\n"
        "convergence plot draws each (lmc optimize --starts N does the same)");
  }
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  ImGui::InputScalar("PSO seed", ImGuiDataType_U64, &p.seed);
  ImGui::SetNextItemWidth(80);
  ImGui::InputDouble("w", &p.w, 0, 0, "%.2f");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  ImGui::InputDouble("c1", &p.c1, 0, 0, "%.2f");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(80);
  ImGui::InputDouble("c2", &p.c2, 0, 0, "%.2f");
  ImGui::Checkbox("start from the current layout", &p.start_from_layout);
  if (ImGui::Button("Study defaults")) {
    const int threads = p.threads;
    p = PsoSettings{};  // the study's metric and swarm settings
    p.threads = threads;
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("30 particles, 100 iterations, w 0.9, c1 0.5, c2 0.3 (docs/algorithms/search.md)");
}

void OptimiserPanel::draw_movable() {
  LayoutState& s = *state_;
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("Which controllers may move (locks per parameter are in the Inspector)");
  ImGui::PopTextWrapPos();
  anchors_.remember("movable-note");
  const LayoutDocument& doc = s.doc();
  for (int d = 0; d < doc.device_count(); ++d) {
    bool moves = false;
    for (int k = 0; k < kNumPoseParams; ++k)
      moves = moves || !doc.locks[static_cast<size_t>(d)].locked[static_cast<size_t>(k)];
    ImGui::PushID(d);
    if (d > 0) ImGui::SameLine();
    if (ImGui::Checkbox(doc.layout.devices[static_cast<size_t>(d)].slot.c_str(), &moves)) {
      s.report(set_device_movable(s.upd_history(), d, moves), "Movable");
    }
    ImGui::PopID();
  }
}

void OptimiserPanel::draw_bounds() {
  LayoutState& s = *state_;
  const LayoutDocument& doc = s.doc();
  ImGui::TextDisabled("Search bounds (shared by all controllers)");
  if (!ImGui::BeginTable("##bounds", 3, ImGuiTableFlags_SizingFixedFit)) return;
  for (int k = 0; k < kNumPoseParams; ++k) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextUnformatted(pose_param_name(k));
    ParamRange r = doc.bounds.range[static_cast<size_t>(k)];
    ImGui::PushID(k);
    ImGui::TableSetColumnIndex(1);
    ImGui::SetNextItemWidth(90);
    ImGui::InputDouble("##lo", &r.lo, 0, 0, "%.0f");
    const bool lo_done = ImGui::IsItemDeactivatedAfterEdit();
    ImGui::TableSetColumnIndex(2);
    ImGui::SetNextItemWidth(90);
    ImGui::InputDouble("##hi", &r.hi, 0, 0, "%.0f");
    const bool hi_done = ImGui::IsItemDeactivatedAfterEdit();
    if (lo_done || hi_done) s.report(set_search_range(s.upd_history(), k, r.lo, r.hi), "Bounds");
    ImGui::PopID();
  }
  ImGui::EndTable();
}

void OptimiserPanel::draw_run() {
  LayoutState& s = *state_;
  const OptimiserJob& job = s.optimiser();
  if (job.running()) {
    char stage[96];
    const auto& h = job.history();
    if (job.starts_planned() > 1) {
      std::snprintf(stage, sizeof stage, "start %d of %d, iteration %d of %d",
                    std::max(1, static_cast<int>(job.histories().size())), job.starts_planned(),
                    h.empty() ? 0 : static_cast<int>(h.size()) - 1, job.iterations_planned());
    } else {
      std::snprintf(stage, sizeof stage, "iteration %d of %d", h.empty() ? 0 : static_cast<int>(h.size()) - 1,
                    job.iterations_planned());
    }
    if (draw_progress_row("pso", job.fraction(), stage, job.elapsed_seconds(), job.eta_seconds(), true, &anchors_)) {
      s.cancel_optimiser();
    }
  } else {
    ImGui::BeginDisabled(!s.poses.current());
    if (ImGui::Button("Start optimiser", ImVec2(140, 0))) s.start_optimiser();
    anchors_.remember("start");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextDisabled("%d particles × %d iterations", s.pso().particles, s.pso().iterations);
  }
  if (job.state() == JobState::kFailed) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(palette::kError, "Failed: %s", job.error().c_str());
    ImGui::PopTextWrapPos();
  }
  const auto outcome = job.outcome();
  if (!outcome) return;
  const PsoResult& r = outcome->pso;
  // Wrapped, so a narrow panel shows the whole line rather than cutting the time off.
  ImGui::PushTextWrapPos(0.0f);
  ImGui::Text("%s %s = %.4g after %d iterations (%.1f s)",
              r.status == lmc::JobStatus::kCancelled ? "Cancelled: best so far" : "Done: best",
              r.metric == PlacementMetricKind::kStudy ? "M" : "R", r.best_cost, r.iterations_done, r.seconds);
  anchors_.remember("result");
  if (outcome->start_costs.size() > 1) {
    std::string costs;
    for (size_t k = 0; k < outcome->start_costs.size(); ++k) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%s%.4g", k > 0 ? ", " : "", outcome->start_costs[k]);
      costs += buf;
    }
    ImGui::TextDisabled("best of %zu starts (start %d); costs %s; %d other start(s) found a different layout",
                        outcome->start_costs.size(), outcome->best_start + 1, costs.c_str(),
                        outcome->distinct_runners_up);
  }
  ImGui::PopTextWrapPos();
  if (ImGui::Button("Apply", ImVec2(100, 0))) s.apply_optimised();
  anchors_.remember("apply");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Replace the poses with the candidate's (one undo step)");
  ImGui::SameLine();
  if (ImGui::Button("Discard", ImVec2(100, 0))) s.discard_optimised();
  anchors_.remember("discard");
  ImGui::SameLine();
  ImGui::Checkbox("ghost", &s.display.show_ghost);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show the candidate as ghost controllers in the 3D view");
}

void OptimiserPanel::draw_convergence() {
  LayoutState& s = *state_;
  const OptimiserJob& job = s.optimiser();
  if (job.history().empty() && !job.running()) return;
  // One curve per start, on one iteration axis.
  size_t longest = 0;
  for (const auto& h : job.histories()) longest = std::max(longest, h.size());
  convergence_x_.resize(longest);
  for (size_t i = 0; i < longest; ++i) convergence_x_[i] = static_cast<double>(i);
  SeriesPlotOptions o;
  o.log_y = true;
  o.height_px = 110;
  o.x_label = "iteration";
  o.y_label = s.pso().metric == PlacementMetricKind::kStudy ? "best cost M (log scale)" : "best cost R (log scale)";
  std::vector<PlotSeries> series;
  const auto& histories = job.histories();
  for (size_t k = 0; k < histories.size(); ++k) {
    const std::string name = histories.size() == 1 ? std::string("best so far") : "start " + std::to_string(k + 1);
    series.push_back({name, std::span<const double>(convergence_x_.data(), histories[k].size()), histories[k],
                      static_cast<int>(k + 1)});
  }
  convergence_.draw("convergence", series, o);
}

namespace {

// A row of Current vs candidate: green where the candidate is better, red where worse, whichever
// way the number moved.
void comparison_row(const char* name, double a, double b, bool lower_better, bool percent,
                    const char* meaning = nullptr) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextUnformatted(name);
  if (meaning != nullptr && ImGui::IsItemHovered()) ImGui::SetTooltip("%s (lower is better)", meaning);
  ImGui::TableSetColumnIndex(1);
  percent ? ImGui::Text("%.1f %%", a * 100) : ImGui::Text("%.4g", a);
  ImGui::TableSetColumnIndex(2);
  percent ? ImGui::Text("%.1f %%", b * 100) : ImGui::Text("%.4g", b);
  ImGui::TableSetColumnIndex(3);
  const double diff = b - a;
  const bool better = lower_better ? diff < 0 : diff > 0;
  const ImVec4 col = diff == 0 ? palette::kMuted : better ? palette::kOk : palette::kError;
  percent ? ImGui::TextColored(col, "%+.1f pt", diff * 100) : ImGui::TextColored(col, "%+.4g", diff);
}

// The share of frames in which every finger is seen by at least `i` controllers.
double share_seen_by_at_least(const Coverage& c, size_t i) {
  std::int64_t n = 0;
  for (size_t k = i; k < c.c.size(); ++k) n += c.c[k];
  return c.frames > 0 ? static_cast<double>(n) / static_cast<double>(c.frames) : 0.0;
}

// M, how many controllers see every finger, each finger, and each controller's best finger.
void coverage_rows(const CoverageSnapshot& cur, const LayoutEvaluation& cand, const Layout& layout) {
  comparison_row("M, all frames", cur.all.metric, cand.all.metric, true, false);
  comparison_row("M, palm down", cur.horizontal.metric, cand.horizontal.metric, true, false);
  comparison_row("M, palm left", cur.vertical.metric, cand.vertical.metric, true, false);
  // Cumulative shares read one way: more frames with every finger seen by >= i controllers is
  // better for every i (the c_i histogram itself is not: moving frames from c_1 to c_2 is good).
  const size_t nc = std::min(cur.all.c.size(), cand.all.c.size());
  for (size_t i = 1; i < nc; ++i) {
    char name[48];
    std::snprintf(name, sizeof name, "all fingers, %zu+ ctrl.", i);
    comparison_row(name, share_seen_by_at_least(cur.all, i), share_seen_by_at_least(cand.all, i), false, true);
  }
  for (int k = 0; k < kNumDigits; ++k) {
    char name[48];
    std::snprintf(name, sizeof name, "%s seen", std::string(digit_name(k)).c_str());
    comparison_row(name, 1.0 - cur.all.finger_unseen_fraction(k), 1.0 - cand.all.finger_unseen_fraction(k), false,
                   true);
  }
  for (int d = 0; d < cand.all.devices && d < cur.all.devices; ++d) {
    // The share of frames in which this controller sees its best finger: 0 means it is idle.
    double a = 0, b = 0;
    for (int k = 0; k < kNumDigits; ++k) {
      a = std::max(a, cur.all.device_finger_fraction(d, k));
      b = std::max(b, cand.all.device_finger_fraction(d, k));
    }
    char name[48];
    std::snprintf(name, sizeof name, "%s, best finger", layout.devices[static_cast<size_t>(d)].slot.c_str());
    comparison_row(name, a, b, false, true);
  }
}

// The robust metric's terms (lower is better), from the start layout to the candidate.
void robust_term_rows(const OptimiserOutcome& outcome) {
  comparison_row("R (robust metric)", outcome.start_terms.total, outcome.pso.best_terms.total, true, false,
                 "M plus each weight times its term");
  for (const RobustTermInfo& term : robust_term_infos()) {
    if (term.weight == nullptr) continue;  // M is in the first rows
    comparison_row(term.name, outcome.start_terms.*(term.value), outcome.pso.best_terms.*(term.value), true, false,
                   term.meaning);
  }
}

}  // namespace

void OptimiserPanel::draw_comparison() {
  LayoutState& s = *state_;
  const auto outcome = s.optimiser().outcome();
  const CoverageSnapshotPtr cur = s.coverage().latest();
  if (!outcome || !cur) return;
  ImGui::Spacing();
  ImGui::TextUnformatted("Current vs candidate");
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(specialisation_summary(*outcome).c_str());
  ImGui::PopTextWrapPos();
  anchors_.remember("specialisation");
  // The label column fits its longest label; the numbers share the rest.
  if (!ImGui::BeginTable("##compare", 4,
                         ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit))
    return;
  ImGui::TableSetupColumn("");
  ImGui::TableSetupColumn("current", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableSetupColumn("candidate", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableSetupColumn("change", ImGuiTableColumnFlags_WidthStretch);
  ImGui::TableHeadersRow();
  coverage_rows(*cur, outcome->candidate, s.layout());
  // The terms only while "current" is still the layout the search started from: the job computed
  // both on the same pose set with the same weights. (Poses, offsets and the sensor model all
  // change the terms; the name does not.)
  const bool same_start = outcome->start_layout.devices == s.layout().devices;
  if (same_start) robust_term_rows(*outcome);
  ImGui::EndTable();
  if (!same_start)
    ImGui::TextDisabled("(the robust terms are not compared: the layout changed since the search started)");
  if (show_comparison_once_) {
    ImGui::SetScrollHereY(1.0f);  // the table's end: the robust terms' rows
    show_comparison_once_ = false;
  }
}

}  // namespace lmc::ui
