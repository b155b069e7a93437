#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/hand/hand_model.h"
#include "core/hand/pose_set_generator.h"
#include "core/hand/reference_poses.h"
#include "core/io/lmc_recording.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_explain.h"
#include "core/visibility/visibility_kernel.h"
#include "core/visibility/visibility_tests.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace {

VisibilityLimits limits(double range_mm = 600, double radius_mm = 10) {
  return make_limits({range_mm, 150.0, 120.0, radius_mm});
}

HandFrame open_hand(HandOrientation o = HandOrientation::kHorizontal) {
  return reference_pose(HandModel(), o, HandMotion::kOpen);
}

DeviceView device_at(double x, double y, double z, double rx = 0, double ry = 0, double rz = 0) {
  DevicePose p;
  p.x_mm = x;
  p.y_mm = y;
  p.z_mm = z;
  p.rx_deg = rx;
  p.ry_deg = ry;
  p.rz_deg = rz;
  return DeviceView::from_pose(p);
}

// Both faces must agree; returns the explanation.
VisibilityExplanation check(const HandFrame& f, const DeviceView& d, const VisibilityLimits& lim) {
  const PreparedFrame fr = prepare_frame(f);
  const VisibilityExplanation ex = explain_visibility(fr, d, lim);
  EXPECT_EQ(ex.bits, visible_fingers(fr, d, lim));
  return ex;
}

TEST(Visibility, OpenHandFromBelowIsFullyVisible) {
  const auto ex = check(open_hand(), device_at(0, 0, 0), limits());
  EXPECT_EQ(ex.bits, kAllFingersVisible);
  EXPECT_GT(ex.approach_dot, 0);
}

// The index finger's distal markers lifted above the back of the hand: from below the palm hides
// them; from the side it does not.
HandFrame index_over_palm() {
  HandFrame f = open_hand();
  const Eigen::Vector3d palm = f.point(kPalm);
  f.point(digit_point(Digit::kIndex, Joint::kDist)) = palm + Eigen::Vector3d(-5, 25, -10);
  f.point(digit_point(Digit::kIndex, Joint::kEnd)) = palm + Eigen::Vector3d(-5, 30, 5);
  return f;
}

TEST(Visibility, FingerBehindThePalmSeenFromBelowIsHidden) {
  const HandFrame f = index_over_palm();
  const Eigen::Vector3d palm = f.point(kPalm);
  const auto ex = check(f, device_at(palm.x(), 0, palm.z()), limits());
  const FingerVerdict& v = ex.fingers[1];
  EXPECT_EQ(v.reason, HiddenReason::kBehindPalm) << describe(v);
  EXPECT_EQ(v.marker, 7);  // s7 = index Dist, the first of its markers behind the palm
  EXPECT_EQ(ex.bits & 0x2, 0);
}

TEST(Visibility, SameHandSeenFromTheSideShowsThatFinger) {
  const HandFrame f = index_over_palm();
  const Eigen::Vector3d palm = f.point(kPalm);
  // Device on the thumb side (−x), its viewing axis turned to +x (rz = −90°), slightly above the
  // raised finger.
  const DeviceView side = device_at(palm.x() - 250, palm.y() + 40, palm.z() - 60, 0, 0, -90);
  const auto ex = check(f, side, limits());
  EXPECT_TRUE(ex.fingers[1].visible()) << describe(ex.fingers[1]);
  for (const auto& v : ex.fingers) EXPECT_NE(v.reason, HiddenReason::kOutOfView) << describe(v);
}

TEST(Visibility, MarkerOneMillimetreOutsideAPyramidFaceIsOut) {
  const VisibilityLimits lim = limits(2000);
  const double tan60 = std::tan(60.0 * std::acos(-1.0) / 180.0);
  const double tan75 = std::tan(75.0 * std::acos(-1.0) / 180.0);
  const int tip = digit_point(Digit::kPinky, Joint::kEnd);  // s21
  for (int axis : {0, 2}) {
    for (double sign : {-1.0, 1.0}) {
      HandFrame f = open_hand();
      Eigen::Vector3d m = f.point(tip);
      const double face = m.y() * (axis == 0 ? tan75 : tan60);
      m[axis] = sign * (face + 1.0);
      f.point(tip) = m;
      auto ex = check(f, device_at(0, 0, 0), lim);
      EXPECT_EQ(ex.bits, 0);
      EXPECT_EQ(ex.fingers[0].reason, HiddenReason::kOutOfView) << "axis " << axis << " sign " << sign;
      EXPECT_EQ(ex.fingers[0].marker, 21);
      m[axis] = sign * (face - 1.0);
      f.point(tip) = m;
      ex = check(f, device_at(0, 0, 0), lim);
      for (const auto& v : ex.fingers) EXPECT_NE(v.reason, HiddenReason::kOutOfView) << describe(v);
    }
  }
}

TEST(Visibility, RangeIsAStrictLimit) {
  HandFrame f = open_hand();
  const int tip = digit_point(Digit::kMiddle, Joint::kEnd);  // s12
  const double r = f.point(tip).norm();
  auto ex = check(f, device_at(0, 0, 0), limits(r - 0.5));
  EXPECT_EQ(ex.fingers[2].reason, HiddenReason::kOutOfRange);
  EXPECT_EQ(ex.fingers[2].marker, 12);
  EXPECT_EQ(describe(ex.fingers[2]), "marker s12 (Finger3_End) out of range");
  ex = check(f, device_at(0, 0, 0), limits(r + 0.5));
  for (const auto& v : ex.fingers) EXPECT_NE(v.reason, HiddenReason::kOutOfRange);
}

TEST(Visibility, HandFromTheWrongSideIsUnseen) {
  // Turned 180° about y the device's forward points at the subject: a·f < 0.
  const auto ex = check(open_hand(), device_at(0, 0, 0, 0, 180, 0), limits());
  EXPECT_EQ(ex.bits, 0);
  EXPECT_LT(ex.approach_dot, 0);
  for (const auto& v : ex.fingers) EXPECT_EQ(v.reason, HiddenReason::kWrongApproach);
}

TEST(Visibility, NoHandHidesEverything) {
  HandFrame f;
  const PreparedFrame fr = prepare_frame(f);
  EXPECT_FALSE(fr.valid);
  EXPECT_EQ(visible_fingers(fr, DeviceView::identity(), limits()), 0);
  EXPECT_EQ(explain_visibility(fr, DeviceView::identity(), limits()).fingers[3].reason, HiddenReason::kNoHand);
}

// A hand-made frame whose phalanges are placed by hand, for the cylinder conditions.
PreparedFrame one_bone(Eigen::Vector3d b, Eigen::Vector3d w, double len) {
  PreparedFrame fr;
  fr.bx[3] = b.x();
  fr.by[3] = b.y();
  fr.bz[3] = b.z();
  w.normalize();
  fr.wx[3] = w.x();
  fr.wy[3] = w.y();
  fr.wz[3] = w.z();
  fr.len[3] = len;
  return fr;
}

bool bone_hides(const PreparedFrame& fr, const Eigen::Vector3d& marker, double radius = 10.0) {
  vis::PhalanxBlock pb;
  vis::prepare_phalanges(fr, DeviceView::identity(), pb);
  const double vv = marker.squaredNorm();
  return vis::phalanx_occludes(pb, 3, marker.x(), marker.y(), marker.z(), vv, radius * radius);
}

TEST(Visibility, CylinderConditions) {
  // Ray from the origin straight up to (0, 200, 0); a bone along x crossing above the origin.
  const Eigen::Vector3d m(0, 200, 0);
  EXPECT_TRUE(bone_hides(one_bone({-20, 100, 9.9}, {1, 0, 0}, 40), m));    // 9.9 mm from the ray
  EXPECT_FALSE(bone_hides(one_bone({-20, 100, 10.1}, {1, 0, 0}, 40), m));  // 10.1 mm: misses
  EXPECT_FALSE(bone_hides(one_bone({-20, 250, 0}, {1, 0, 0}, 40), m));     // beyond the marker
  EXPECT_FALSE(bone_hides(one_bone({-20, -50, 0}, {1, 0, 0}, 40), m));     // behind the device
  EXPECT_FALSE(
      bone_hides(one_bone({5, 100, 0}, {1, 0, 0}, 40), m));  // closest point before the bone's start: no end caps
  EXPECT_FALSE(bone_hides(one_bone({-45, 100, 0}, {1, 0, 0}, 40), m));  // … and past its end
  EXPECT_TRUE(bone_hides(one_bone({-39, 100, 0}, {1, 0, 0}, 40), m));
  EXPECT_FALSE(bone_hides(one_bone({-20, 100, 0}, {1, 0, 0}, 0), m));  // zero length
}

TEST(Visibility, ParallelRaysDoNotDivideByZero) {
  const Eigen::Vector3d m(0, 200, 0);
  // A bone along the ray itself, and one parallel to it 5 mm away: n = v × w = 0.
  EXPECT_FALSE(bone_hides(one_bone({0, 50, 0}, {0, 1, 0}, 40), m));
  EXPECT_FALSE(bone_hides(one_bone({5, 50, 0}, {0, 1, 0}, 40), m));
  // A ray parallel to the palm plane is not occluded by the palm.
  PreparedFrame fr;
  fr.nx = 0;
  fr.ny = 1;
  fr.nz = 0;
  fr.cx = 0;
  fr.cy = 0;
  fr.cz = 0;
  std::vector<Eigen::Vector3d> square = {{-50, 0, -50}, {50, 0, -50}, {50, 0, 50}, {-50, 0, 50}};
  fr.hull = build_convex_hull(square);
  const DeviceView d = DeviceView::identity();
  EXPECT_FALSE(vis::palm_occludes(fr, d, vis::palm_plane_numerator(fr, d), 100, 0, 0));
  // …while a ray through it is.
  const DeviceView below = device_at(0, -100, 0);
  EXPECT_TRUE(vis::palm_occludes(fr, below, vis::palm_plane_numerator(fr, below), 0, 200, 0));
  EXPECT_FALSE(
      vis::palm_occludes(fr, below, vis::palm_plane_numerator(fr, below), 0, 100, 0));  // q = m: not strictly between
}

// The study's literal formulas (unit ray, divisions) as an independent check of the rewritten,
// division-free cylinder test.
bool literal_cylinder(const Eigen::Vector3d& o, const Eigen::Vector3d& m, const Eigen::Vector3d& b,
                      const Eigen::Vector3d& w, double len, double r) {
  const Eigen::Vector3d v = (m - o).normalized();
  const double D = (m - o).norm();
  const Eigen::Vector3d n = v.cross(w);
  if (n.norm() == 0) return false;
  const double d = std::abs(n.dot(o - b)) / n.norm();
  const double t1 = w.cross(n).dot(b - o) / n.dot(n);
  const double t2 = v.cross(n).dot(b - o) / n.dot(n);
  return d < r && t1 > 0 && t1 <= D && t2 > 0 && t2 < len;
}

TEST(Visibility, CylinderTestMatchesTheLiteralFormulaOnRandomCases) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0, misses = 0;
  for (int i = 0; i < 20000; ++i) {
    const Eigen::Vector3d o(100 * u(rng), 100 * u(rng), 100 * u(rng));
    const Eigen::Vector3d m(100 * u(rng), 200 + 100 * u(rng), 100 * u(rng));
    const Eigen::Vector3d w = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const double len = 20 + 30 * (1 + u(rng));
    const Eigen::Vector3d b =
        o + (0.5 + 0.5 * u(rng)) * (m - o) + Eigen::Vector3d(20 * u(rng), 20 * u(rng), 20 * u(rng)) - 0.5 * len * w;
    PreparedFrame fr = one_bone(b, w, len);
    fr.wx[3] = w.x();
    fr.wy[3] = w.y();
    fr.wz[3] = w.z();
    vis::PhalanxBlock pb;
    const DeviceView d = device_at(o.x(), o.y(), o.z());
    vis::prepare_phalanges(fr, d, pb);
    const Eigen::Vector3d v = m - o;
    const bool fast = vis::phalanx_occludes(pb, 3, v.x(), v.y(), v.z(), v.squaredNorm(), 100.0);
    EXPECT_EQ(fast, literal_cylinder(o, m, b, w, len, 10.0)) << i;
    (fast ? hits : misses)++;
  }
  EXPECT_GT(hits, 1000);
  EXPECT_GT(misses, 1000);
}

// Both faces agree on many Monte Carlo frames seen from many random device poses (a variety of
// palm and finger occlusions, range and view failures).
TEST(Visibility, KernelAndExplainAgreeOnRandomPosesAndDevices) {
  PoseSetSettings s;
  s.frames = 150;
  s.seed = 5;
  const PoseSet set = generate_pose_set(HandModel(), s);
  const auto frames = prepare_frames(set.frames);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  int counts[7] = {};
  const VisibilityLimits lim = limits();
  for (int i = 0; i < 60; ++i) {
    const DeviceView d = device_at(250 * u(rng), 60 * u(rng), 250 * u(rng), 60 * u(rng), 180 * u(rng), 60 * u(rng));
    for (const auto& fr : frames) {
      const auto ex = explain_visibility(fr, d, lim);
      for (const KernelBuild build :
           {KernelBuild::kBest, KernelBuild::kAvx512, KernelBuild::kAvx2, KernelBuild::kBaseline}) {
        ASSERT_EQ(ex.bits, visible_fingers(fr, d, lim, build)) << kernel_build_name(build);
      }
      for (int k = 0; k < kNumDigits; ++k) {
        const auto& v = ex.fingers[static_cast<size_t>(k)];
        ++counts[static_cast<int>(v.reason)];
        EXPECT_EQ(v.visible(), ((ex.bits >> k) & 1) != 0);
        if (v.reason == HiddenReason::kBehindFinger) {
          EXPECT_NE(v.occluding_finger, k);
        }
      }
    }
  }
  // Every kind of outcome occurs, so the agreement above covers each test.
  EXPECT_GT(counts[static_cast<int>(HiddenReason::kVisible)], 100);
  EXPECT_GT(counts[static_cast<int>(HiddenReason::kWrongApproach)], 100);
  EXPECT_GT(counts[static_cast<int>(HiddenReason::kOutOfView)], 100);
  EXPECT_GT(counts[static_cast<int>(HiddenReason::kBehindPalm)], 20);
  EXPECT_GT(counts[static_cast<int>(HiddenReason::kBehindFinger)], 100);
}

TEST(Visibility, ComputeVisibilityMatchesSingleCallsAndIsDeviceMajor) {
  PoseSetSettings s;
  s.frames = 300;
  const auto frames = prepare_frames(generate_pose_set(HandModel(), s).frames);
  Layout layout;
  layout.devices.resize(3);
  layout.devices[0].pose.x_mm = -60;
  layout.devices[1].pose.x_mm = 60;
  layout.devices[2].pose.z_mm = -60;
  layout.devices[2].offset_mm = {5, 0, 0};
  const VisibilityTable t = compute_visibility(layout, frames);
  ASSERT_EQ(t.bits.size(), 900u);
  const VisibilityLimits lim = make_limits(VisibilityParams::from_sensor(common_sensor(layout)));
  for (int d = 0; d < 3; ++d) {
    const DeviceView view = DeviceView::from_device(layout.devices[static_cast<size_t>(d)]);
    for (int j = 0; j < 300; ++j) ASSERT_EQ(t.at(d, j), visible_fingers(frames[static_cast<size_t>(j)], view, lim));
    std::vector<FingerBits> col(300);
    device_visibility(view, frames, lim, col);
    EXPECT_TRUE(std::equal(col.begin(), col.end(), t.device_column(d).begin()));
  }
  // The offset moves the device origin (docs/algorithms/frames.md): device 2 sits at (5, 0, −60).
  EXPECT_DOUBLE_EQ(DeviceView::from_device(layout.devices[2]).ox, 5.0);
}

// reference-data/validation: the authors' labels for all 200 rows × 5 fingers, device at its own
// origin, range 400 mm, 150°×120°, radius 10 mm.
TEST(Visibility, ReproducesTheAuthorsRaytracedLabels) {
  const auto input = test::reference_file("validation/Interp_LMC_Naiv_Static101.txt");
  const auto expected = test::reference_file("validation/Interp_LMC_Naiv_Static101.raytraced.txt");
  LMC_REQUIRE_REFERENCE_FILE(input);
  LMC_REQUIRE_REFERENCE_FILE(expected);
  const LmcRecording in = read_lmc_recording(input);
  const LmcRecording ref = read_lmc_recording(expected);
  ASSERT_EQ(ref.kind, RecordingKind::kRaytraced);
  ASSERT_EQ(in.rows.size(), ref.visibility.size());
  const VisibilityLimits lim = make_limits({400.0, 150.0, 120.0, 10.0});
  int compared = 0;
  for (size_t i = 0; i < in.rows.size(); ++i) {
    const PreparedFrame fr = prepare_frame(in.rows[i]);
    const FingerBits bits = visible_fingers(fr, DeviceView::identity(), lim);
    for (int k = 0; k < kNumDigits; ++k) {
      const int label = (!in.rows[i].hand_present || !fr.valid) ? -1 : ((bits >> k) & 1);
      EXPECT_EQ(label, ref.visibility[i][static_cast<size_t>(k)]) << "row " << i + 1 << " finger " << k;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 1000);
}

}  // namespace
}  // namespace lmc
