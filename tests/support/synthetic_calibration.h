#pragma once
// A synthetic calibration trial without the simulator (core tests and benchmarks): a still open
// hand that sways a little, seen by four controllers in the paper's initial square whose true
// transforms differ from the layout by known errors, with Gaussian noise; Vicon = the truth.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "core/calibration/calibration_input.h"
#include "core/calibration/rigid_transform.h"
#include "core/hand/hand_model.h"
#include "core/hand/reference_poses.h"
#include "core/layout/layout.h"
#include "core/processing/visibility_labels.h"

namespace lmc::test::synthetic_calibration {

inline Layout square_layout() {
  return lmc::square_layout("square");
}

// A rotation of `deg` degrees about a fixed, not axis-aligned direction chosen by `k`.
inline Eigen::Matrix3d turn(double deg, int k) {
  const Vec3 axis = Vec3(1.0 + k, 2.0 - 0.5 * k, 0.7 * k - 1.0).normalized();
  return Eigen::AngleAxisd(deg * std::numbers::pi / 180.0, axis).toRotationMatrix();
}

struct Trial {
  CalibrationInput input;
  std::vector<RigidTransform> truth;  // true device → world per controller
};

// `truth[d]` places device d; `frames` at 100 Hz; noise σ in mm; seed for the noise.
inline Trial make_trial(const std::vector<RigidTransform>& truth, int frames, double noise_mm, unsigned seed,
                        bool with_vicon = true) {
  Trial t;
  t.truth = truth;
  const HandModel model;
  const HandFrame still = reference_pose(model, HandOrientation::kHorizontal, HandMotion::kOpen);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_mm);
  GridTrial& g = t.input.device_frame;
  g.frame_count = frames;
  HandTrack world(frames);
  for (int f = 0; f < frames; ++f) {
    // Slow sway: a few millimetres and a degree or two, as a person holding still.
    const double s = 2.0 * std::numbers::pi * f / 100.0;
    const Eigen::Matrix3d r = turn(1.5 * std::sin(0.3 * s), 3);
    const Vec3 shift(3.0 * std::sin(0.23 * s), 1.5 * std::sin(0.17 * s), 3.0 * std::cos(0.31 * s));
    const Vec3 centre = still.point(kPalm);
    for (int p = 0; p < kNumHandPoints; ++p) {
      const bool vector = p == kPalmNormal || p == kPalmDirection;
      world.at(f, p) = vector ? Vec3(r * still.point(p)) : Vec3(r * (still.point(p) - centre) + centre + shift);
    }
  }
  for (size_t d = 0; d < truth.size(); ++d) {
    DeviceTrack dt;
    dt.device_id = static_cast<int>(d) + 1;
    dt.track = HandTrack(frames);
    const RigidTransform inv = truth[d].inverse();
    for (int f = 0; f < frames; ++f) {
      for (int p = 0; p < kNumHandPoints; ++p) {
        const bool vector = p == kPalmNormal || p == kPalmDirection;
        const Vec3 n(noise(rng), noise(rng), noise(rng));
        dt.track.at(f, p) = vector ? Vec3(inv.r * world.at(f, p)) : Vec3(inv.apply(world.at(f, p)) + n);
      }
    }
    t.input.labels.push_back(visibility_labels(dt.track));
    g.devices.push_back(std::move(dt));
  }
  if (with_vicon) t.input.vicon = std::move(world);
  return t;
}

// Truth = the layout's transforms with errors: device d moved by `moved[d]` and turned by
// `turned_deg[d]` about its own origin.
inline std::vector<RigidTransform> perturbed(const Layout& layout, const std::vector<Vec3>& moved,
                                             const std::vector<double>& turned_deg) {
  std::vector<RigidTransform> out;
  for (size_t d = 0; d < layout.devices.size(); ++d) {
    const RigidTransform n = device_transform(layout.devices[d]);
    out.push_back({turn(turned_deg[d], static_cast<int>(d)) * n.r, n.t + moved[d]});
  }
  return out;
}

}  // namespace lmc::test::synthetic_calibration
