#include "core/optimise/pso.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/hand/pose_set_generator.h"
#include "core/metric/coverage.h"
#include "core/visibility/visibility_kernel.h"
#include "tests/support/mc_frames.h"

namespace lmc {
namespace {

const std::vector<PreparedFrame>& frames() {
  return test::mc_frames(120, 3);
}

PsoSettings small(int threads = 0) {
  PsoSettings s;
  s.particles = 8;
  s.iterations = 6;
  s.seed = 17;
  s.threads = threads;
  return s;
}

SearchSpace box() {
  SearchSpace sp = parse_search_bounds("x=-300:300,z=-300:300,rx=-45:45,ry=-60:60");
  return sp;
}

TEST(Pso, SameSeedSameResultWithOneOrTwoThreads) {
  const Layout start = default_start_layout(3);
  const PsoResult a = run_pso(start, box(), frames(), small(1));
  const PsoResult b = run_pso(start, box(), frames(), small(2));
  const PsoResult c = run_pso(start, box(), frames(), small(2));
  EXPECT_EQ(a.status, JobStatus::kCompleted);
  EXPECT_EQ(a.best_layout, b.best_layout);
  EXPECT_EQ(b.best_layout, c.best_layout);
  EXPECT_EQ(a.best_cost_history, b.best_cost_history);
  EXPECT_EQ(a.best_cost, b.best_cost);
  PsoSettings other = small(1);
  other.seed = 18;
  EXPECT_NE(run_pso(start, box(), frames(), other).best_layout, a.best_layout);
}

TEST(Pso, BestCostIsMonotoneAndMatchesTheLayoutsCoverage) {
  const PsoResult r = run_pso(default_start_layout(2), box(), frames(), small());
  ASSERT_EQ(r.best_cost_history.size(), 7u);  // initial swarm + 6 iterations
  for (size_t i = 1; i < r.best_cost_history.size(); ++i) EXPECT_LE(r.best_cost_history[i], r.best_cost_history[i - 1]);
  EXPECT_EQ(r.iterations_done, 6);
  EXPECT_EQ(r.layout_evaluations, 8 * 7);
  EXPECT_EQ(r.device_frame_evaluations, 8 * 7 * 2 * 120);
  EXPECT_DOUBLE_EQ(r.best_cost, layout_cost(r.best_layout, frames()));
  EXPECT_DOUBLE_EQ(r.best_coverage.metric, r.best_cost);
  EXPECT_EQ(r.best_coverage.frames, 120);
}

// The pruning bound (cost_lower_bound.h) changes no comparison the swarm makes: the same search
// with a check after every chunk of frames and with none, for both metrics, on the table where
// the robust search's layouts see the hand.
TEST(Pso, PruningSkipsFramesButTakesTheSameSteps) {
  const auto& many = test::mc_frames(640, 3);
  for (const auto metric : {PlacementMetricKind::kStudy, PlacementMetricKind::kRobust}) {
    PsoSettings s = small(2);
    s.iterations = 12;
    s.metric = metric;
    s.prune_round_frames = 0;
    const PsoResult whole = run_pso(default_start_layout(4), table_search_space(), many, s);
    s.prune_round_frames = 64;
    const PsoResult pruned = run_pso(default_start_layout(4), table_search_space(), many, s);
    EXPECT_EQ(pruned.best_layout, whole.best_layout);
    EXPECT_EQ(pruned.best_cost_history, whole.best_cost_history);
    EXPECT_EQ(pruned.best_cost, whole.best_cost);
    EXPECT_EQ(pruned.layout_evaluations, whole.layout_evaluations);
    EXPECT_EQ(whole.layouts_stopped_early, 0);
    EXPECT_EQ(whole.device_frame_evaluations, 8 * 13 * 4 * 640);
    EXPECT_GT(pruned.layouts_stopped_early, 0);
    EXPECT_LT(pruned.device_frame_evaluations, whole.device_frame_evaluations);
    // A one-thread pruned search is the same as well.
    s.threads = 1;
    EXPECT_EQ(run_pso(default_start_layout(4), table_search_space(), many, s).best_cost_history,
              whole.best_cost_history);
  }
  PsoSettings bad = small();
  bad.prune_round_frames = -1;
  EXPECT_THROW(run_pso(default_start_layout(2), box(), frames(), bad), Error);
}

TEST(Pso, StaysInBoundsAndHonoursLocksAndFixedParameters) {
  Layout start = default_start_layout(3);
  start.devices[1].pose.x_mm = 77;
  start.devices[1].pose.z_mm = -33;
  start.devices[2].pose.rz_deg = 12;  // rz is not searched: stays
  start.devices[0].pose.ry_deg = 5;
  SearchSpace sp = box();
  sp.lock_device(1);
  sp.lock_param(0, 4);  // device 0 keeps its ry
  const PsoResult r = run_pso(start, sp, frames(), small());
  const auto& d = r.best_layout.devices;
  EXPECT_EQ(d[1].pose, start.devices[1].pose);
  EXPECT_EQ(d[0].pose.ry_deg, 5);
  EXPECT_EQ(d[2].pose.rz_deg, 12);
  EXPECT_EQ(d[2].pose.y_mm, 0);
  for (const auto& dev : d) {
    EXPECT_GE(dev.pose.x_mm, -300);
    EXPECT_LE(dev.pose.x_mm, 300);
    EXPECT_GE(dev.pose.rx_deg, -45);
    EXPECT_LE(dev.pose.rx_deg, 45);
    EXPECT_GE(dev.pose.ry_deg, -60);
    EXPECT_LE(dev.pose.ry_deg, 60);
  }
  EXPECT_EQ(r.best_layout.devices[2].slot, "LMC3");
  EXPECT_EQ(sp.dimensions(3).size(), 4u + 3u);  // device 0: x,z,rx; device 1 locked; device 2: 4
}

TEST(Pso, StartFromLayoutIsNeverWorseThanTheStart) {
  Layout start = default_start_layout(2);
  const double start_cost = layout_cost(start, frames());
  PsoSettings s = small();
  s.start_from_layout = true;
  s.iterations = 2;
  const PsoResult r = run_pso(start, box(), frames(), s);
  EXPECT_LE(r.best_cost, start_cost);
}

TEST(Pso, ReportsProgressAndStopsWhenCancelled) {
  std::stop_source stop;
  std::vector<PsoProgress> seen;
  PsoSettings s = small();
  s.iterations = 50;
  const PsoResult r = run_pso(
      default_start_layout(2), box(), frames(), s,
      [&](const PsoProgress& p) {
        seen.push_back(p);
        if (p.iteration == 3) stop.request_stop();
      },
      stop.get_token());
  EXPECT_EQ(r.status, JobStatus::kCancelled);
  ASSERT_EQ(seen.size(), 4u);
  EXPECT_EQ(seen[0].iteration, 0);
  EXPECT_EQ(seen[3].iteration, 3);
  EXPECT_EQ(seen[3].iterations, 50);
  EXPECT_EQ(seen[3].layout_evaluations, 8 * 4);
  EXPECT_EQ(seen[3].device_frame_evaluations, 8 * 4 * 2 * 120);
  EXPECT_EQ(r.iterations_done, 3);
  EXPECT_DOUBLE_EQ(r.best_cost, seen[3].best_cost);  // best so far
  EXPECT_EQ(r.best_layout.device_count(), 2);

  std::stop_source already;
  already.request_stop();
  const PsoResult none = run_pso(default_start_layout(2), box(), frames(), s, {}, already.get_token());
  EXPECT_EQ(none.status, JobStatus::kCancelled);
  EXPECT_EQ(none.best_layout, default_start_layout(2));
}

TEST(Pso, RejectsBadSettings) {
  PsoSettings s = small();
  s.particles = 0;
  EXPECT_THROW(run_pso(default_start_layout(1), box(), frames(), s), Error);
  EXPECT_THROW(run_pso(default_start_layout(1), box(), {}, small()), Error);
  EXPECT_THROW(parse_search_bounds("x=5:-5"), Error);
  EXPECT_THROW(parse_search_bounds("q=0:1"), Error);
  EXPECT_THROW(parse_search_bounds("x=0"), Error);
  EXPECT_THROW(parse_search_bounds("x=a:1"), Error);
  const SearchSpace sp = parse_search_bounds("y=0:50,rz=-10:10");
  EXPECT_TRUE(sp.free[1]);
  EXPECT_TRUE(sp.free[5]);
  EXPECT_FALSE(sp.free[0]);
  EXPECT_EQ(sp.bounds[1].max, 50);
}

// lmc bench prints the bounds it searched in --bounds form; read back they are the same space.
TEST(SearchSpace, FormattedBoundsReadBackAsTheSameSpace) {
  EXPECT_EQ(format_search_bounds(table_search_space()), "x=-360:360,z=-360:360,rx=-90:90,ry=-180:180");
  EXPECT_EQ(format_search_bounds(SearchSpace{}), "x=-1000:1000,z=-1000:1000,rx=-90:90,ry=-180:180");
  for (const SearchSpace& space : {table_search_space(), parse_search_bounds("y=0.1:50.25,rz=-10:1e-3")}) {
    const SearchSpace back = parse_search_bounds(format_search_bounds(space));
    EXPECT_EQ(back.free, space.free);
    EXPECT_EQ(back.bounds, space.bounds);
  }
}

TEST(Pso, EightDevicesWork) {
  PsoSettings s = small();
  s.particles = 3;
  s.iterations = 1;
  const PsoResult r = run_pso(default_start_layout(8), box(), frames(), s);
  EXPECT_EQ(r.best_layout.device_count(), 8);
  EXPECT_EQ(r.best_coverage.c.size(), 9u);
}

}  // namespace
}  // namespace lmc
