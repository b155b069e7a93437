#pragma once
// The placement search in the background (docs/architecture.md): start copies the document's
// layout, locks, bounds and the prepared pose set into a worker that calls core's run_pso; the UI
// keeps only the job channel. Cancelling cannot change the layout (the worker never had a
// reference to it); applying the result goes through the apply_layout action, one undo step.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/metric/coverage.h"
#include "core/optimise/pso.h"
#include "ui/model/jobs/background_job.h"
#include "ui/model/layout/layout_document.h"
#include "ui/model/layout/pose_set_store.h"

namespace lmc::ui {

// Coverage of one layout on the pose set: all frames and split by palm orientation (core's split).
using LayoutEvaluation = OrientationCoverage;
LayoutEvaluation evaluate_layout(const Layout& layout, const LoadedPoseSet& poses);

struct OptimiserReport {
  int start = 0;  // multi-start: which swarm (0-based)
  int iteration = 0;
  int iterations = 0;
  double best_cost = 0;
  std::shared_ptr<const Layout> best_layout;  // best so far (immutable snapshot for the ghost)
};

struct OptimiserOutcome {
  PsoResult pso;  // the best start's
  // Multi-start: each finished start's best cost, the best start, and how many of the
  // others found a really different layout (core's same_arrangement).
  std::vector<double> start_costs;
  int best_start = 0;
  int distinct_runners_up = 0;
  LayoutEvaluation candidate;
  // The layout the search started from and its robust terms on the same pose set with the same
  // weights (pso.best_terms are the candidate's), so the comparison can show what the robust
  // metric gained term by term.
  Layout start_layout;
  RobustTerms start_terms;
  // M of the start layout and of the candidate on the set searched on, and — when that set is not
  // the Monte Carlo set (recorded hands, a file, a recipe) — on the default Monte Carlo set too, so
  // the panel can say whether the new layout is specialised to these hands.
  double start_m = 0, candidate_m = 0;
  bool has_monte_carlo = false;
  double start_m_monte_carlo = 0, candidate_m_monte_carlo = 0;
};

// "M on the recorded poses 0.214 → 0.120 (−0.094); on the Monte Carlo set 0.300 → 0.310 (+0.010):
// better on these hands, worse on the invented ones — specialised." (or only the first part when
// the search ran on the Monte Carlo set). Lower M is better.
std::string specialisation_summary(const OptimiserOutcome& outcome);

// The search space the document describes: per-device locks, shared bounds; parameters locked
// on every device are not searched at all.
SearchSpace search_space_for(const LayoutDocument& doc);

class OptimiserJob {
 public:
  // Starts a run on a copy of the inputs. Returns false (with error()) when the inputs are unusable.
  // `starts` > 1 runs that many swarms (seeds seed, seed+1, …) one after another (core's
  // run_multi_start) and keeps the best.
  bool start(const LayoutDocument& doc, const PoseSetPtr& poses, const PsoSettings& settings, int starts = 1);
  void cancel() { job_.cancel(); }
  // Update step: drains progress into the convergence history.
  void poll();
  void wait();  // tests

  JobState state() const { return job_.state(); }
  bool running() const { return job_.running(); }
  double fraction() const { return job_.fraction(); }
  std::optional<double> eta_seconds() const { return job_.eta_seconds(); }
  double elapsed_seconds() const { return job_.elapsed_seconds(); }
  std::string error() const { return error_.empty() ? job_.error() : error_; }
  // Best cost per iteration of the start running now (or the last one).
  const std::vector<double>& history() const {
    static const std::vector<double> kNone;
    return histories_.empty() ? kNone : histories_.back();
  }
  const std::vector<std::vector<double>>& histories() const { return histories_; }  // one per start
  int starts_planned() const { return starts_; }
  // The finished (or cancelled: best so far) outcome; null while running or before a run.
  std::shared_ptr<const OptimiserOutcome> outcome() const;
  // Forget the last outcome (after Apply or Discard).
  void discard();
  int iterations_planned() const { return iterations_; }
  // Best layout so far while running (then the outcome's); null before the first iteration.
  std::shared_ptr<const Layout> best_so_far() const;

 private:
  BackgroundJob<OptimiserOutcome, OptimiserReport> job_;
  std::vector<std::vector<double>> histories_;
  int starts_ = 1;
  std::shared_ptr<const Layout> live_best_;
  std::string error_;
  int iterations_ = 0;
  bool discarded_ = false;
};

}  // namespace lmc::ui
