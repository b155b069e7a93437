#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <thread>

#include "core/layout/layout.h"
#include "tests/support/scratch_dir.h"
#include "ui/model/jobs/background_job.h"
#include "ui/model/layout/coverage_cache.h"
#include "ui/model/layout/frame_visibility.h"
#include "ui/model/layout/heatmap_cache.h"
#include "ui/model/layout/layout_actions.h"
#include "ui/model/layout/layout_state.h"
#include "ui/model/layout/pose_set_store.h"

namespace lmc::ui {
namespace {

using namespace std::chrono_literals;

void wait_for(const std::function<bool()>& done) {
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (!done() && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(1ms);
}

// ---- the generic job, with a deliberately slow fake task ---------------------------------------

int slow_count(std::stop_token stop, JobChannel<int>& ch, int steps) {
  ch.set_stage("counting");
  for (int i = 0; i < steps; ++i) {
    if (stop.stop_requested()) return i;
    ch.report(i);
    ch.set_progress(i + 1, steps);
    std::this_thread::sleep_for(1ms);
  }
  return steps;
}

TEST(BackgroundJob, RunsToCompletionWithProgressReports) {
  BackgroundJob<int, int> job;
  job.start([](std::stop_token st, JobChannel<int>& ch) { return slow_count(st, ch, 5); });
  wait_for([&] { return job_finished(job.state()); });
  EXPECT_EQ(job.state(), JobState::kCompleted);
  ASSERT_TRUE(job.result());
  EXPECT_EQ(*job.result(), 5);
  EXPECT_EQ(job.drain_reports().size(), 5u);
  EXPECT_DOUBLE_EQ(job.fraction(), 1.0);
}

TEST(BackgroundJob, CancelStopsTheWorkerAndSaysCancelled) {
  BackgroundJob<int, int> job;
  job.start([](std::stop_token st, JobChannel<int>& ch) { return slow_count(st, ch, 100000); });
  wait_for([&] { return job.done() > 0; });
  job.cancel();
  wait_for([&] { return job_finished(job.state()); });
  EXPECT_EQ(job.state(), JobState::kCancelled);
  EXPECT_LT(*job.result(), 100000) << "the result is the best-so-far";
}

TEST(BackgroundJob, DestroyingARunningJobJoinsPromptly) {
  const auto t0 = std::chrono::steady_clock::now();
  {
    BackgroundJob<int, int> job;
    job.start([](std::stop_token st, JobChannel<int>& ch) { return slow_count(st, ch, 100000); });
    std::this_thread::sleep_for(5ms);
  }
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 5s);
}

TEST(BackgroundJob, AnExceptionBecomesFailedWithItsMessage) {
  BackgroundJob<int, int> job;
  job.start([](std::stop_token, JobChannel<int>&) -> int { throw std::runtime_error("pose set has no frames"); });
  wait_for([&] { return job_finished(job.state()); });
  EXPECT_EQ(job.state(), JobState::kFailed);
  EXPECT_EQ(job.error(), "pose set has no frames");
}

// ---- pose set, coverage, heatmap, frame visibility -----------------------------------------------

PoseSetPtr small_pose_set() {
  static const PoseSetPtr p = [] {
    PoseSetChoice c;
    c.frames = 60;
    c.seed = 3;
    return load_pose_set_for(c, 1);
  }();
  return p;
}

Layout square_layout() {
  return default_new_layout();
}

TEST(CoverageCache, MatchesADirectComputationAndRecomputesOnlyTheMovedColumn) {
  const PoseSetPtr poses = small_pose_set();
  ASSERT_EQ(poses->size(), 60);
  CoverageCache cache;
  Layout l = square_layout();
  cache.request(l, poses);
  cache.wait();
  ASSERT_TRUE(cache.latest());
  EXPECT_TRUE(cache.up_to_date());
  EXPECT_EQ(cache.latest()->columns_computed, 4);
  const Coverage direct = compute_coverage(compute_visibility(l, poses->prepared));
  EXPECT_EQ(cache.latest()->all.c, direct.c);
  EXPECT_EQ(cache.latest()->all.device_finger_seen, direct.device_finger_seen);
  EXPECT_DOUBLE_EQ(cache.latest()->all.metric, direct.metric);

  l.devices[2].pose.x_mm += 40;  // "dragging" LMC3
  cache.request(l, poses);
  cache.wait();
  EXPECT_EQ(cache.latest()->columns_computed, 1) << "only the moved controller's column";
  const Coverage moved = compute_coverage(compute_visibility(l, poses->prepared));
  EXPECT_EQ(cache.latest()->all.c, moved.c);
  EXPECT_EQ(cache.latest()->horizontal.frames + cache.latest()->vertical.frames, 60);
}

TEST(HeatmapSweep, ACellAtTheControllersOwnSpotEqualsItsCoverage) {
  const PoseSetPtr poses = small_pose_set();
  HeatmapRequest req;
  req.layout = square_layout();
  req.device = 0;
  req.finger = 1;  // index
  req.poses = poses;
  req.half_extent_mm = 60;  // 2 × 2 cells centred on (±30, ±30) ...
  req.layout.devices[0].pose.x_mm = 30;
  req.layout.devices[0].pose.z_mm = -30;
  const HeatmapGridPtr g = sweep_heatmap(req, 2);
  ASSERT_TRUE(g);
  // ... so cell (1, 0) is exactly where LMC1 stands.
  const Coverage c = compute_coverage(compute_visibility(req.layout, poses->prepared));
  EXPECT_NEAR(g->at(1, 0), c.device_finger_fraction(0, 1), 1e-6);
  for (float v : g->value) {
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
  }
}

TEST(HeatmapSweep, ForOneFingerFramesAddedNeverExceedFramesVisible) {
  HeatmapRequest req;
  req.layout = square_layout();
  req.device = 1;
  req.finger = 2;
  req.poses = small_pose_set();
  const HeatmapGridPtr visible = sweep_heatmap(req, 6);
  req.mode = HeatmapMode::kFramesAdded;
  const HeatmapGridPtr added = sweep_heatmap(req, 6);
  for (size_t i = 0; i < visible->value.size(); ++i) EXPECT_LE(added->value[i], visible->value[i] + 1e-6f);
}

TEST(HeatmapCache, MovingTheSweptControllerDoesNotRestartButAnotherDoes) {
  HeatmapRequest a;
  a.layout = square_layout();
  a.device = 0;
  a.poses = small_pose_set();
  HeatmapRequest b = a;
  b.layout.devices[0].pose.x_mm += 100;
  EXPECT_TRUE(a.same_sweep(b));
  b.layout.devices[0].pose.rx_deg += 5;
  EXPECT_FALSE(a.same_sweep(b));
  HeatmapRequest c = a;
  c.layout.devices[1].pose.x_mm += 1;
  EXPECT_FALSE(a.same_sweep(c));
}

TEST(HeatmapCache, PublishesCoarseThenFineGrids) {
  HeatmapCache cache;
  HeatmapRequest req;
  req.layout = square_layout();
  req.device = 0;
  req.cells = 8;
  req.poses = small_pose_set();
  cache.request(req);
  wait_for([&] {
    cache.poll();
    return cache.complete();
  });
  ASSERT_TRUE(cache.complete());
  EXPECT_EQ(cache.latest()->nx, 8);
  EXPECT_TRUE(cache.latest()->fine);
}

// A hidden Layout tab sweeps no heatmap (a recording on the Record tab needs the core), keeps the
// grid it has, and sweeps again when shown.
TEST(LayoutState, OffScreenTheHeatmapSweepStopsAndResumesWhenShown) {
  LayoutDocument doc = make_document(square_layout());
  doc.pose_set.frames = 10;
  LayoutState s(std::move(doc));
  s.select(0);
  s.display.heatmap_cells = 8;
  wait_for([&] {
    s.update(0.0, false);
    return s.poses.current() != nullptr;
  });
  ASSERT_NE(s.poses.current(), nullptr);
  for (int i = 0; i < 5; ++i) s.update(0.0, false);
  EXPECT_FALSE(s.heatmap().computing());
  EXPECT_EQ(s.heatmap().latest(), nullptr) << "no sweep while off screen";
  wait_for([&] {
    s.update(0.0, true);
    return s.heatmap().complete();
  });
  ASSERT_TRUE(s.heatmap().complete());
  const HeatmapGridPtr shown = s.heatmap().latest();
  // Another finger while hidden: nothing starts, the last grid stays for when the tab comes back.
  s.display.heatmap_finger = 2;
  s.update(0.0, false);
  EXPECT_FALSE(s.heatmap().computing());
  EXPECT_EQ(s.heatmap().latest(), shown);
  wait_for([&] {
    s.update(0.0, true);
    return s.heatmap().complete();
  });
  ASSERT_TRUE(s.heatmap().complete());
  EXPECT_NE(s.heatmap().latest(), shown);
  // A sweep under way when the tab is hidden stops (12,000 cells take far longer than the step
  // between the two calls) and starts again when shown.
  s.display.heatmap_cells = 96;
  s.update(0.0, true);
  EXPECT_TRUE(s.heatmap().computing());
  s.update(0.0, false);
  EXPECT_FALSE(s.heatmap().computing());
  EXPECT_FALSE(s.heatmap().complete());
  wait_for([&] {
    s.update(0.0, true);
    return s.heatmap().complete();
  });
  ASSERT_TRUE(s.heatmap().complete());
  EXPECT_EQ(s.heatmap().latest()->nx, 96);
}

TEST(FrameVisibility, CountsAgreeWithTheBitsAndRaysCarryReasons) {
  const PoseSetPtr poses = small_pose_set();
  const Layout l = square_layout();
  const FrameVisibility fv = explain_frame(l, poses->prepared[0], 1);
  ASSERT_EQ(fv.per_device.size(), 4u);
  for (int k = 0; k < 5; ++k) {
    int n = 0;
    for (const auto& e : fv.per_device) n += (e.bits >> k) & 1;
    EXPECT_EQ(fv.seen_count[static_cast<size_t>(k)], n);
  }
  ASSERT_EQ(fv.rays.size(), 20u);
  for (const FingerRay& r : fv.rays) {
    EXPECT_FALSE(r.reason.empty());
    const bool finger_visible = (fv.per_device[1].bits >> r.digit) & 1;
    if (finger_visible) {
      EXPECT_TRUE(r.clear);
    }
  }
  // No rays without a chosen controller.
  EXPECT_TRUE(explain_frame(l, poses->prepared[0], -1).rays.empty());
}

TEST(LayoutState, UnsavedMarkFollowsTheSavedCommitAndSelectionIsPruned) {
  LayoutState s(make_document(square_layout()));
  EXPECT_FALSE(s.unsaved());
  s.select(3);
  ASSERT_TRUE(remove_device(s.upd_history(), 3));
  s.prune_selection();
  EXPECT_EQ(s.selected(), 2);
  EXPECT_TRUE(s.unsaved());
  EXPECT_NE(s.title().find('*'), std::string::npos);
  s.undo();
  EXPECT_FALSE(s.unsaved()) << "back at the saved commit";
}

TEST(LayoutState, OpeningABadFileNamesTheJsonPathAndChangesNothing) {
  const auto dir = lmc::test::scratch_dir("ui_model_bad_layout");
  const auto path = dir / "bad.json";
  {
    std::ofstream out(path);
    out << R"({"format": 1, "name": "x", "sensor": {"range_mm": 600, "fov_long_deg": 150, "fov_short_deg": 120},
               "devices": [{"slot": "LMC1", "serial": null, "pose": {"x": "left", "y": 0, "z": 0, "rx": 0, "ry": 0, "rz": 0},
                            "offset": [0, 0, 0]}]})";
  }
  LayoutState s(make_document(square_layout()));
  const LayoutDocument before = s.history().head();
  const std::string err = s.open_file(path);
  EXPECT_NE(err.find("/devices/0/pose/x"), std::string::npos) << err;
  // Path and JSON pointer exactly once ("bad.json: at …: bad.json: at …: …").
  const std::string where = path.string() + ": at /devices/0/pose/x: ";
  EXPECT_EQ(err.find(where), err.rfind(where)) << err;
  EXPECT_EQ(err.find("at /devices"), err.rfind("at /devices")) << err;
  EXPECT_EQ(s.history().head(), before);
  EXPECT_FALSE(s.history().can_undo());
  std::filesystem::remove_all(dir);
}

TEST(LayoutState, SaveThenOpenRoundTripsTheLayout) {
  const auto dir = lmc::test::scratch_dir("ui_model_roundtrip");
  LayoutState s(make_document(square_layout()));
  ASSERT_TRUE(set_pose_param(s.upd_history(), 1, 3, 22.5));
  ASSERT_TRUE(s.save_to(dir / "rig.json").empty());
  EXPECT_FALSE(s.unsaved());
  EXPECT_EQ(s.title(), "rig.json");
  LayoutState t(make_document(default_new_layout()));
  ASSERT_TRUE(t.open_file(dir / "rig.json").empty());
  EXPECT_EQ(t.layout().devices[1].pose.rx_deg, 22.5);
  EXPECT_FALSE(t.unsaved());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace lmc::ui
