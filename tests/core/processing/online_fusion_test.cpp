#include "core/processing/online_fusion.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <vector>

#include "core/common/error.h"
#include "core/hand/hand_model.h"
#include "core/hand/reference_poses.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/processing/realign.h"
#include "core/processing/trial_pipeline.h"
#include "tests/support/reference_data.h"

namespace online_fusion_test {

using namespace lmc;

const Layout& paper_initial_layout() {
  static const Layout l = load_layout(lmc::test::asset_file("layouts/paper-initial.json"));
  return l;
}

// World frame → device frame: the inverse of realign_frame for one layout device.
HandFrame to_device(const HandFrame& world, const LayoutDevice& dev) {
  const Eigen::Matrix3d rt = dev.pose.rotation().transpose();
  const Eigen::Vector3d shift = dev.pose.translation() + dev.offset_mm;
  HandFrame f = world;
  for (int i = 0; i < kNumHandPoints; ++i) {
    f.point(i) =
        (i == kPalmNormal || i == kPalmDirection) ? Vec3(rt * world.point(i)) : Vec3(rt * (world.point(i) - shift));
  }
  f.hand_present = true;
  return f;
}

bool is_position(int i) {
  return i != kPalmNormal && i != kPalmDirection;
}

// A hand flexing its index and drifting sideways: world frame at time t.
HandFrame moving_hand(const HandModel& model, double t) {
  const double progress = 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * t / 2.0));
  const HandJointAngles angles = motion_angles(HandMotion::kIndexFlexion, progress);
  HandPlacement place = reference_placement(model, HandOrientation::kHorizontal, angles);
  HandFrame f = model.pose(angles, place);
  const Vec3 drift(30.0 * std::sin(2.0 * std::numbers::pi * t / 3.0), 10.0 * std::sin(2.0 * std::numbers::pi * t / 1.7),
                   0.0);
  for (int i = 0; i < kNumHandPoints; ++i) {
    if (is_position(i)) f.point(i) += drift;
  }
  f.hand_present = true;
  return f;
}

// RMS of a − b over finite position entries of frames [from, n) with b shifted back by `lag`.
struct Diff {
  double rms = NAN;
  long samples = 0;
};
Diff rms_diff(const std::vector<std::array<Vec3, kNumHandPoints>>& a, const HandTrack& b, int from, int lag) {
  double sum = 0.0;
  long n = 0;
  for (int f = std::max(from, lag); f < static_cast<int>(a.size()) && f - lag < b.frame_count; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      if (!is_position(i)) continue;
      const Vec3& x = a[static_cast<size_t>(f)][static_cast<size_t>(i)];
      const Vec3& y = b.at(f - lag, i);
      if (!is_finite(x) || !is_finite(y)) continue;
      sum += (x - y).squaredNorm();
      ++n;
    }
  }
  return {n > 0 ? std::sqrt(sum / static_cast<double>(n)) : NAN, n};
}

// The lag (in grid frames, 0…max_lag) at which the online output best matches the offline one.
int best_lag(const std::vector<std::array<Vec3, kNumHandPoints>>& online, const HandTrack& offline, int from,
             int max_lag) {
  int best = 0;
  double best_rms = INFINITY;
  for (int k = 0; k <= max_lag; ++k) {
    const Diff d = rms_diff(online, offline, from, k);
    if (d.samples > 0 && d.rms < best_rms) {
      best_rms = d.rms;
      best = k;
    }
  }
  return best;
}

// Four devices' device-frame tracks of `world` frames on a 100 Hz grid, with noise.
GridTrial simulated_grid(const Layout& layout, const std::vector<HandFrame>& world, double noise_mm, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, noise_mm);
  GridTrial grid;
  grid.frame_count = static_cast<int>(world.size());
  for (int d = 0; d < layout.device_count(); ++d) {
    DeviceTrack dt;
    dt.device_id = d + 1;
    dt.track = HandTrack(grid.frame_count);
    for (int f = 0; f < grid.frame_count; ++f) {
      const HandFrame df = to_device(world[static_cast<size_t>(f)], layout.devices[static_cast<size_t>(d)]);
      for (int i = 0; i < kNumHandPoints; ++i) {
        dt.track.at(f, i) = df.point(i) + (is_position(i) ? Vec3(g(rng), g(rng), g(rng)) : Vec3::Zero());
      }
    }
    grid.devices.push_back(std::move(dt));
  }
  return grid;
}

HandFrame frame_of(const HandTrack& t, int f) {
  HandFrame h;
  h.hand_present = t.has_hand(f);
  for (int i = 0; i < kNumHandPoints; ++i) h.point(i) = t.at(f, i);
  return h;
}

// The offline default fusion of a device-frame grid, as trial_pipeline runs it.
HandTrack offline_default(const GridTrial& grid, const Layout& layout,
                          std::vector<std::vector<FingerLabels>>* labels_out) {
  std::vector<std::vector<FingerLabels>> labels;
  std::vector<std::vector<float>> quality;
  std::vector<HandTrack> world;
  for (const auto& d : grid.devices) {
    labels.push_back(visibility_labels(d.track));
    quality.push_back(sample_quality(d.track, labels.back()));
    world.push_back(d.track);
    realign_track(world.back(), layout.devices[static_cast<size_t>(d.device_id - 1)]);
  }
  std::vector<const HandTrack*> tracks;
  std::vector<const std::vector<float>*> qptr;
  for (size_t d = 0; d < world.size(); ++d) {
    tracks.push_back(&world[d]);
    qptr.push_back(&quality[d]);
  }
  if (labels_out != nullptr) *labels_out = labels;
  return fuse_default(tracks, qptr);
}

// Feeds a grid to the online fuser, all devices at each grid time; the fused hand after each.
std::vector<FusedHand> run_online(OnlineFusion& fusion, const GridTrial& grid) {
  std::vector<FusedHand> out;
  for (int f = 0; f < grid.frame_count; ++f) {
    for (const auto& d : grid.devices) fusion.add(frame_of(d.track, f), d.device_id - 1, grid.time_s(f));
    out.push_back(fusion.current());
  }
  return out;
}

std::vector<std::array<Vec3, kNumHandPoints>> points_of(const std::vector<FusedHand>& hands) {
  std::vector<std::array<Vec3, kNumHandPoints>> p;
  for (const auto& h : hands) p.push_back(h.points);
  return p;
}

TEST(OnlineFusion, FourDevicesGiveBackAKnownWorldHand) {
  const Layout& layout = paper_initial_layout();
  ASSERT_EQ(layout.device_count(), 4);
  const HandModel model;
  const HandFrame world = reference_pose(model, HandOrientation::kHorizontal, HandMotion::kOpen);
  OnlineFusion fusion(layout);
  for (int k = 0; k < 6; ++k) {
    for (int d = 0; d < 4; ++d) {
      fusion.add(to_device(world, layout.devices[static_cast<size_t>(d)]), d, k / 120.0 + d * 0.002);
    }
  }
  const FusedHand h = fusion.current();
  ASSERT_TRUE(h.has_hand);
  for (int i = 0; i < kNumHandPoints; ++i) {
    const double tol = is_position(i) ? 0.5 : 1e-3;
    EXPECT_LT((h.points[static_cast<size_t>(i)] - world.point(i)).norm(), tol) << hand_point_name(i);
  }
  for (int k = 0; k < kNumDigits; ++k) EXPECT_GE(h.seen_by[static_cast<size_t>(k)], 1) << digit_name(k);
}

TEST(OnlineFusion, TracksTheOfflineFusionOfASimulatedTrialWithBoundedLag) {
  const Layout& layout = paper_initial_layout();
  const HandModel model;
  std::vector<HandFrame> world;
  for (int f = 0; f < 600; ++f) world.push_back(moving_hand(model, f * 0.01));
  const GridTrial grid = simulated_grid(layout, world, 1.0, 3);
  const HandTrack offline = offline_default(grid, layout, nullptr);
  OnlineFusion fusion(layout);
  const auto online = points_of(run_online(fusion, grid));

  const int warmup = 20;  // the filters' first 0.2 s
  const Diff d0 = rms_diff(online, offline, warmup, 0);
  const int lag = best_lag(online, offline, warmup, 10);
  const Diff dl = rms_diff(online, offline, warmup, lag);
  HandTrack truth(grid.frame_count);
  for (int f = 0; f < grid.frame_count; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) truth.at(f, i) = world[static_cast<size_t>(f)].point(i);
  }
  const Diff online_truth = rms_diff(online, truth, warmup, 0);
  double off_sum = 0.0;
  long off_n = 0;
  for (int f = warmup; f < grid.frame_count; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      if (!is_position(i) || !is_finite(offline.at(f, i))) continue;
      off_sum += (offline.at(f, i) - truth.at(f, i)).squaredNorm();
      ++off_n;
    }
  }
  std::cout << "[ simulated ] online vs offline RMS " << d0.rms << " mm (" << d0.samples << " points), best lag " << lag
            << " frames (RMS there " << dl.rms << " mm); vs truth: online " << online_truth.rms << " mm, offline "
            << std::sqrt(off_sum / static_cast<double>(off_n)) << " mm\n";
  // At the last frame the smoothed result is the filtered one, and with every device on one grid
  // time the online filter is the offline forward filter: the same numbers.
  const int last = grid.frame_count - 1;
  for (int i = 0; i < kNumHandPoints; ++i) {
    EXPECT_LT((online[static_cast<size_t>(last)][static_cast<size_t>(i)] - offline.at(last, i)).norm(), 1e-9)
        << hand_point_name(i);
  }
  EXPECT_LT(d0.rms, 3.0);
  EXPECT_LE(lag, 3);
  EXPECT_LT(online_truth.rms, 3.0);
  EXPECT_GT(static_cast<double>(d0.samples), 0.95 * (grid.frame_count - warmup) * 28);
}

TEST(OnlineFusion, StaggeredDevicesAt120HzFollowAMovingHandWithSmallLag) {
  // The live case: four controllers at 120 Hz, each its own phase, noisy, a moving hand.
  const Layout& layout = paper_initial_layout();
  const HandModel model;
  std::mt19937 rng(21);
  std::normal_distribution<double> g(0.0, 1.0);
  OnlineFusion fusion(layout);
  struct Sample {
    double t;
    std::array<Vec3, kNumHandPoints> points;
  };
  std::vector<Sample> out;
  const double period = 1.0 / 120.0;
  for (int k = 0; k < 600; ++k) {
    for (int d = 0; d < 4; ++d) {
      const double t = k * period + d * period / 4.0;
      HandFrame f = to_device(moving_hand(model, t), layout.devices[static_cast<size_t>(d)]);
      for (int i = 0; i < kNumHandPoints; ++i) {
        if (is_position(i)) f.point(i) += Vec3(g(rng), g(rng), g(rng));
      }
      fusion.add(f, d, t);
      if (k >= 60 && d == 3) out.push_back({t, fusion.current().points});  // once per cycle: keeps the test fast
    }
  }
  // RMS against the truth delayed by tau; the best tau is the online fuser's lag.
  auto rms_vs_truth = [&](double tau) {
    double sum = 0.0;
    long n = 0;
    for (const Sample& smp : out) {
      const HandFrame truth = moving_hand(model, smp.t - tau);
      for (int i = 0; i < kNumHandPoints; ++i) {
        if (!is_position(i)) continue;
        EXPECT_TRUE(is_finite(smp.points[static_cast<size_t>(i)]));
        sum += (smp.points[static_cast<size_t>(i)] - truth.point(i)).squaredNorm();
        ++n;
      }
    }
    return std::sqrt(sum / static_cast<double>(n));
  };
  const double rms0 = rms_vs_truth(0.0);
  double best_tau = 0.0, best = rms0;
  for (int ms = 2; ms <= 30; ms += 2) {
    const double r = rms_vs_truth(ms * 1e-3);
    if (r < best) {
      best = r;
      best_tau = ms * 1e-3;
    }
  }
  std::cout << "[ 4 x 120 Hz staggered ] online vs truth RMS " << rms0 << " mm; best lag " << best_tau * 1e3
            << " ms (RMS there " << best << " mm)\n";
  EXPECT_LT(rms0, 2.0);
  EXPECT_LE(best_tau, 0.015);
}

TEST(OnlineFusion, TracksTheOfflineFusionOfTheRecordedTrial) {
  const auto path = lmc::test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const LmcRecording rec = read_lmc_recording(path);
  const Layout& layout = paper_initial_layout();
  ProcessOptions options;
  options.method = FusionMethod::kDefault;
  const TrialAnalysis offline = process_trial("Naiv_Static101", rec, layout, nullptr, options);
  const GridTrial& grid = offline.device_frame;

  // Rows in time order on the shared device clock, as a live hub would deliver them.
  std::vector<HandFrame> rows = rec.rows;
  std::stable_sort(rows.begin(), rows.end(),
                   [](const HandFrame& a, const HandFrame& b) { return a.timestamp_us < b.timestamp_us; });
  OnlineFusion fusion(layout);
  std::vector<std::array<Vec3, kNumHandPoints>> online;
  size_t next = 0;
  for (int f = 0; f < grid.frame_count; ++f) {
    const double t_grid_us = static_cast<double>(grid.start_us) + f * grid.step_us;
    while (next < rows.size() && static_cast<double>(rows[next].timestamp_us) <= t_grid_us) {
      fusion.add(rows[next], rows[next].device_id - 1,
                 static_cast<double>(rows[next].timestamp_us - grid.start_us) * 1e-6);
      ++next;
    }
    online.push_back(fusion.current_at((t_grid_us - static_cast<double>(grid.start_us)) * 1e-6).points);
  }
  const int warmup = 20;
  const Diff d0 = rms_diff(online, offline.fused, warmup, 0);
  const int lag = best_lag(online, offline.fused, warmup, 10);
  long offline_finite = 0;
  for (int f = warmup; f < grid.frame_count; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i)
      offline_finite += is_position(i) && is_finite(offline.fused.at(f, i)) ? 1 : 0;
  }
  std::cout << "[ recorded ] " << grid.frame_count << " grid frames, " << rows.size()
            << " raw rows: online vs offline RMS " << d0.rms << " mm over " << d0.samples << " of " << offline_finite
            << " offline points (" << 100.0 * static_cast<double>(d0.samples) / static_cast<double>(offline_finite)
            << " %), best lag " << lag << " frames\n";
  EXPECT_LT(d0.rms, 5.0);
  EXPECT_LE(lag, 5);
}

TEST(OnlineFusion, SeenByEqualsTheOfflineLabelCount) {
  const Layout& layout = paper_initial_layout();
  const HandModel model;
  // Every reference pose for a few frames (occlusions differ per pose), then the moving hand.
  std::vector<HandFrame> world;
  for (int o = 0; o < kNumHandOrientations; ++o) {
    for (int m = 0; m < kNumHandMotions; ++m) {
      const HandFrame p = reference_pose(model, static_cast<HandOrientation>(o), static_cast<HandMotion>(m));
      for (int k = 0; k < 5; ++k) world.push_back(p);
    }
  }
  for (int f = 0; f < 100; ++f) world.push_back(moving_hand(model, f * 0.01));
  GridTrial grid = simulated_grid(layout, world, 0.5, 11);
  // Device 3 loses the hand for a while: −1 labels, never counted.
  for (int f = 60; f < 70; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) grid.devices[2].track.at(f, i) = Vec3::Constant(kNaN);
  }
  std::vector<std::vector<FingerLabels>> labels;
  offline_default(grid, layout, &labels);
  OnlineFusion fusion(layout);
  const std::vector<FusedHand> online = run_online(fusion, grid);
  int partial = 0;
  for (int f = 0; f < grid.frame_count; ++f) {
    for (int k = 0; k < kNumDigits; ++k) {
      int expected = 0;
      for (const auto& dev : labels) expected += dev[static_cast<size_t>(f)][static_cast<size_t>(k)] == 1 ? 1 : 0;
      EXPECT_EQ(online[static_cast<size_t>(f)].seen_by[static_cast<size_t>(k)], expected)
          << "frame " << f << " finger " << k;
      partial += expected < 4 ? 1 : 0;
    }
  }
  EXPECT_GT(partial, 0) << "the poses should hide some fingers from some devices";
}

TEST(OnlineFusion, AStoppedDeviceDropsOutAfterTheStalenessWindow) {
  const Layout& layout = paper_initial_layout();
  const HandModel model;
  const HandFrame world = reference_pose(model, HandOrientation::kHorizontal, HandMotion::kOpen);
  OnlineFusion fusion(layout);
  // Device 0 reports everything 10 mm off in x until it stops at t = 1 s; the others go on.
  HandFrame biased_world = world;
  for (int i = 0; i < kNumHandPoints; ++i) {
    if (is_position(i)) biased_world.point(i).x() += 10.0;
  }
  const double dt = 1.0 / 120.0;
  double t = 0.0;
  int seen_while_sending = 0;
  for (; t < 1.0; t += dt) {
    fusion.add(to_device(biased_world, layout.devices[0]), 0, t);
    for (int d = 1; d < 4; ++d) fusion.add(to_device(world, layout.devices[static_cast<size_t>(d)]), d, t);
    seen_while_sending = fusion.current().seen_by[1];
  }
  const double stop = t - dt;
  const int idx = digit_point(Digit::kIndex, Joint::kEnd);
  EXPECT_GT(fusion.current().points[static_cast<size_t>(idx)].x() - world.point(idx).x(), 0.5);  // device 0 pulls
  const bool device0_saw_index = fusion.slot_labels(0)[1] == 1;
  for (; t < stop + 0.5; t += dt) {
    for (int d = 1; d < 4; ++d) fusion.add(to_device(world, layout.devices[static_cast<size_t>(d)]), d, t);
    const FusedHand h = fusion.current();
    if (h.t_s - stop < OnlineFusion::kStaleAfterS - 1e-6) {
      EXPECT_EQ(h.seen_by[1], seen_while_sending);
    } else if (h.t_s - stop > OnlineFusion::kStaleAfterS + 1e-6) {
      EXPECT_EQ(h.seen_by[1], seen_while_sending - (device0_saw_index ? 1 : 0)) << h.t_s - stop;
    }
  }
  EXPECT_LT((fusion.current().points[static_cast<size_t>(idx)] - world.point(idx)).norm(), 0.5);

  // When every device stops, the hand fades to NaN after the gap limit (5 × 10 ms).
  const double last = t - dt;
  EXPECT_TRUE(fusion.current_at(last + 0.04).has_hand);
  EXPECT_FALSE(fusion.current_at(last + 0.06).has_hand);
  for (const Vec3& p : fusion.current_at(last + 0.06).points) EXPECT_FALSE(is_finite(p));
  EXPECT_EQ(fusion.current_at(last + 0.2).seen_by, (std::array<int, kNumDigits>{}));
}

TEST(OnlineFusion, NonFiniteInputNeverReachesAFiniteOutput) {
  const Layout& layout = paper_initial_layout();
  const HandModel model;
  const HandFrame world = reference_pose(model, HandOrientation::kVertical, HandMotion::kOpen);
  OnlineFusion fusion(layout);
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pick(0, kNumHandPoints - 1), coord(0, 2), kind(0, 3);
  const double dt = 1.0 / 120.0;
  for (int k = 0; k < 240; ++k) {
    for (int d = 0; d < 4; ++d) {
      HandFrame f = to_device(world, layout.devices[static_cast<size_t>(d)]);
      for (int j = 0; j < 6; ++j) {
        const double bad = kind(rng) == 0 ? INFINITY : kNaN;
        f.point(pick(rng))[coord(rng)] = bad;
      }
      if (k % 17 == d) f.point(kPalm) = Vec3::Constant(kNaN);  // "hand" without a palm: treated as no hand
      if (k % 23 == d) f.hand_present = false;
      fusion.add(f, d, k * dt + d * 0.001);
    }
    const FusedHand h = fusion.current();
    for (int i = 0; i < kNumHandPoints; ++i) {
      const Vec3& p = h.points[static_cast<size_t>(i)];
      for (int c = 0; c < 3; ++c) EXPECT_FALSE(std::isinf(p[c])) << i;
      if (k > 5 && is_finite(p)) {
        EXPECT_LT((p - world.point(i)).norm(), is_position(i) ? 1.0 : 0.01) << hand_point_name(i) << " at " << k;
      }
    }
  }
  EXPECT_TRUE(fusion.current().has_hand);
  EXPECT_THROW(fusion.add(world, 4, 3.0), Error);
  EXPECT_THROW(fusion.add(world, -1, 3.0), Error);
  EXPECT_THROW(fusion.add(world, 0, kNaN), Error);
}

TEST(OnlineFusion, PerFrameHelpersMatchTheTrackFunctions) {
  // The shared per-frame pieces give what the whole-track functions give.
  const Layout& layout = paper_initial_layout();
  const HandModel model;
  std::vector<HandFrame> world;
  for (int f = 0; f < 30; ++f) world.push_back(moving_hand(model, f * 0.05));
  const GridTrial grid = simulated_grid(layout, world, 0.0, 1);
  const auto& track = grid.devices[1].track;
  const auto labels = visibility_labels(track);
  const auto quality = sample_quality(track, labels);
  HandTrack moved = track;
  realign_track(moved, layout.devices[1]);
  const VisibilityLimits limits = make_limits(recorded_trial_visibility_params());
  const Eigen::Matrix3d r = layout.devices[1].pose.rotation();
  const Eigen::Vector3d shift = layout.devices[1].pose.translation() + layout.devices[1].offset_mm;
  for (int f = 0; f < track.frame_count; ++f) {
    const HandFrame h = frame_of(track, f);
    EXPECT_EQ(frame_visibility_labels(prepare_frame(h), true, limits), labels[static_cast<size_t>(f)]);
    std::array<float, kNumHandPoints> q;
    frame_quality(h.points, &labels[static_cast<size_t>(f)], SmootherParams{}, q);
    std::array<Vec3, kNumHandPoints> p = h.points;
    realign_frame(p, r, shift);
    for (int i = 0; i < kNumHandPoints; ++i) {
      EXPECT_EQ(q[static_cast<size_t>(i)], quality[static_cast<size_t>(f) * kNumHandPoints + static_cast<size_t>(i)]);
      EXPECT_EQ(p[static_cast<size_t>(i)], moved.at(f, i));
    }
  }
}

}  // namespace online_fusion_test
