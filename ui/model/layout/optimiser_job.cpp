#include "ui/model/layout/optimiser_job.h"

#include "core/common/number_format.h"

#include <chrono>
#include <cmath>
#include <thread>

#include "core/common/error.h"
#include "core/optimise/multi_start.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc::ui {

LayoutEvaluation evaluate_layout(const Layout& layout, const LoadedPoseSet& poses) {
  return coverage_by_orientation(compute_visibility(layout, poses.prepared), poses.horizontal, poses.vertical);
}

SearchSpace search_space_for(const LayoutDocument& doc) {
  SearchSpace space;
  for (int k = 0; k < kNumPoseParams; ++k) {
    space.bounds[static_cast<size_t>(k)] = {doc.bounds.range[static_cast<size_t>(k)].lo,
                                            doc.bounds.range[static_cast<size_t>(k)].hi};
    bool any_free = false;
    for (const auto& l : doc.locks) any_free = any_free || !l.locked[static_cast<size_t>(k)];
    space.free[static_cast<size_t>(k)] = any_free;
  }
  space.locked.resize(doc.locks.size());
  for (size_t d = 0; d < doc.locks.size(); ++d) space.locked[d] = doc.locks[d].locked;
  return space;
}

namespace {

// The swarm (or several, one after another); false when the best it returns was not evaluated (a
// cancelled single start: multi-start keeps finished starts only, which run_pso has evaluated).
bool run_swarms(const Layout& layout, const SearchSpace& space, const LoadedPoseSet& poses, const PsoSettings& settings,
                int starts, std::stop_token stop, JobChannel<OptimiserReport>& ch, OptimiserOutcome& out) {
  const long long per_start = settings.iterations + 1;
  const auto report = [&ch, per_start](int start, const PsoProgress& p) {
    ch.report({start, p.iteration, p.iterations, p.best_cost,
               p.best_layout.devices.empty() ? nullptr : std::make_shared<const Layout>(p.best_layout)});
    ch.set_progress(start * per_start + p.iteration + 1, ch.total());
  };
  if (starts == 1) {
    out.pso = run_pso(
        layout, space, poses.prepared, settings, [&](const PsoProgress& p) { report(0, p); }, stop);
    out.start_costs = {out.pso.best_cost};
    return out.pso.status == JobStatus::kCompleted;
  }
  MultiStartResult m = run_multi_start(
      layout, space, poses.prepared, settings, starts, [&](const MultiStartProgress& p) { report(p.start, p.pso); },
      stop);
  if (m.best < 0) throw Error("no start finished");
  for (const auto& r : m.runs) out.start_costs.push_back(r.best_cost);
  out.best_start = m.best;
  out.distinct_runners_up = static_cast<int>(m.runners_up.size());
  out.pso = std::move(m.runs[static_cast<size_t>(m.best)]);
  out.pso.status = m.status;
  return true;
}

// run_pso stops as soon as it is asked and leaves a cancelled search's best unevaluated, but that
// best so far is a real layout the panel offers to Apply: evaluate it like a finished one, so the
// comparison and the status bar show its terms, not zeros.
void evaluate_best_so_far(const LoadedPoseSet& poses, const PsoSettings& settings, OptimiserOutcome& out) {
  out.pso.best_terms =
      layout_robust_terms(out.pso.best_layout, poses.prepared, settings.weights, settings.phalanx_radius_mm);
  // Cancelled before the initial swarm was evaluated: the best so far is the start layout, whose
  // cost is now known.
  if (!std::isfinite(out.pso.best_cost)) {
    out.pso.best_cost =
        settings.metric == PlacementMetricKind::kStudy ? out.pso.best_terms.metric_m : out.pso.best_terms.total;
    out.start_costs = {out.pso.best_cost};
  }
}

// The candidate says what made it, so a saved result is not mistaken for the layout it started
// from ("paper-optimized" stayed in the file after Apply and Save).
void name_candidate(const Layout& start, const LoadedPoseSet& poses, const PsoSettings& settings, int starts,
                    OptimiserOutcome& out) {
  const char* metric = placement_metric_name(settings.metric);
  out.pso.best_layout.name = std::string("optimized-") + metric;
  out.pso.best_layout.description =
      std::string("Optimiser panel, ") + metric + " metric: " + std::to_string(settings.particles) + " particles x " +
      std::to_string(settings.iterations) + " iterations, swarm seed " +
      std::to_string(settings.seed + static_cast<std::uint64_t>(out.best_start)) +
      (starts > 1 ? " (best of " + std::to_string(starts) + " starts)" : std::string()) + ", on " +
      poses.set.description + ", from " + start.name + "; cost " + std::to_string(out.pso.best_cost);
}

// Both layouts' M on the Monte Carlo set too, when the search ran on another.
void score_on_monte_carlo(const Layout& start, const LoadedPoseSet& poses, std::stop_token stop,
                          JobChannel<OptimiserReport>& ch, OptimiserOutcome& out) {
  if (poses.choice.source == PoseSetChoice::Source::kMonteCarlo || stop.stop_requested()) return;
  ch.set_stage("Scoring both layouts on the Monte Carlo set");
  PoseSetChoice mc;
  const PoseSetPtr mc_set = load_pose_set_for(mc, 0, stop);
  if (!mc_set) return;
  out.has_monte_carlo = true;
  out.start_m_monte_carlo = evaluate_layout(start, *mc_set).all.metric;
  out.candidate_m_monte_carlo = evaluate_layout(out.pso.best_layout, *mc_set).all.metric;
}

// The worker: search, evaluate and name the candidate, and score the start layout beside it.
OptimiserOutcome search(const Layout& layout, const SearchSpace& space, const PoseSetPtr& poses,
                        const PsoSettings& settings, int starts, std::stop_token stop,
                        JobChannel<OptimiserReport>& ch) {
  ch.set_stage("Searching");
  ch.set_progress(0, (settings.iterations + 1LL) * starts);
  OptimiserOutcome out;
  const bool best_evaluated = run_swarms(layout, space, *poses, settings, starts, stop, ch, out);
  if (!best_evaluated) {
    ch.set_stage("Evaluating the best so far");
    evaluate_best_so_far(*poses, settings, out);
  }
  name_candidate(layout, *poses, settings, starts, out);
  ch.set_stage("Evaluating the candidate");
  out.candidate = evaluate_layout(out.pso.best_layout, *poses);
  if (!best_evaluated) out.pso.best_coverage = out.candidate.all;
  out.start_layout = layout;
  out.start_terms = layout_robust_terms(layout, poses->prepared, settings.weights, settings.phalanx_radius_mm);
  out.start_m = out.start_terms.metric_m;
  out.candidate_m = out.candidate.all.metric;
  score_on_monte_carlo(layout, *poses, stop, ch, out);
  return out;
}

}  // namespace

bool OptimiserJob::start(const LayoutDocument& doc, const PoseSetPtr& poses, const PsoSettings& settings, int starts) {
  error_.clear();
  if (!poses || poses->size() == 0) {
    error_ = "the pose set is not loaded yet";
    return false;
  }
  const SearchSpace space = search_space_for(doc);
  if (std::string why = space.validate(); !why.empty()) {
    error_ = why;
    return false;
  }
  if (space.dimensions(doc.device_count()).empty()) {
    error_ = "every parameter of every controller is locked: nothing to search";
    return false;
  }
  if (starts < 1 || starts > 64) {
    error_ = "starts must be 1 to 64";
    return false;
  }
  histories_.clear();
  live_best_.reset();
  discarded_ = false;
  iterations_ = settings.iterations;
  starts_ = starts;
  job_.start(
      [layout = doc.layout, space, poses, settings, starts](std::stop_token stop, JobChannel<OptimiserReport>& ch) {
        return search(layout, space, poses, settings, starts, stop, ch);
      });
  return true;
}

void OptimiserJob::poll() {
  for (const auto& r : job_.drain_reports()) {
    if (r.start >= static_cast<int>(histories_.size())) histories_.resize(static_cast<size_t>(r.start) + 1);
    auto& history = histories_[static_cast<size_t>(r.start)];
    if (r.iteration >= static_cast<int>(history.size()))
      history.resize(static_cast<size_t>(r.iteration) + 1, r.best_cost);
    history[static_cast<size_t>(r.iteration)] = r.best_cost;
    if (r.best_layout) live_best_ = r.best_layout;
  }
}

void OptimiserJob::wait() {
  while (job_.running()) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  poll();
}

std::shared_ptr<const OptimiserOutcome> OptimiserJob::outcome() const {
  if (discarded_ || job_.running()) return nullptr;
  return job_.result();
}

void OptimiserJob::discard() {
  discarded_ = true;
}

std::shared_ptr<const Layout> OptimiserJob::best_so_far() const {
  if (discarded_) return nullptr;
  if (!job_.running()) {
    if (const auto o = outcome()) return std::shared_ptr<const Layout>(o, &o->pso.best_layout);
  }
  return live_best_;
}

namespace {

std::string m_change_text(double before, double after) {
  return format_readable(before, 3) + " -> " + format_readable(after, 3) + " (" +
         format_readable(after - before, 3, true) + ")";
}

}  // namespace

std::string specialisation_summary(const OptimiserOutcome& o) {
  const bool recorded = o.has_monte_carlo;
  std::string s = std::string("M on ") + (recorded ? "the poses searched on " : "the Monte Carlo set ") +
                  m_change_text(o.start_m, o.candidate_m);
  if (!recorded) return s + ".";
  s += "; on the Monte Carlo set " + m_change_text(o.start_m_monte_carlo, o.candidate_m_monte_carlo);
  const bool better_here = o.candidate_m < o.start_m;
  const bool better_there = o.candidate_m_monte_carlo < o.start_m_monte_carlo;
  if (better_here && !better_there) return s + ": better on these hands, not on the invented ones (specialised).";
  if (better_here && better_there) return s + ": better on both.";
  return s + ".";
}

}  // namespace lmc::ui
