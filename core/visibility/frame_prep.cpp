#include "core/visibility/frame_prep.h"

#include <tbb/parallel_for.h>

#include <Eigen/Core>
#include <array>
#include <cmath>

#include "core/geometry/least_variance_direction.h"

namespace lmc {

namespace {

constexpr int marker_hand_point(int k) {
  if (k == 0) return kElbow;
  if (k == 17) return digit_point(4, 0);                         // pinky Meta
  if (k < 17) return digit_point((k - 1) / 4, 1 + (k - 1) % 4);  // Proxi…End of thumb…ring
  return digit_point(4, 1 + (k - 18));                           // pinky Proxi…End
}

constexpr std::array<int, kNumRayMarkers> kMarkerHandPoints = [] {
  std::array<int, kNumRayMarkers> t{};
  for (int k = 0; k < kNumRayMarkers; ++k) t[static_cast<size_t>(k)] = marker_hand_point(k);
  return t;
}();

}  // namespace

int ray_marker_hand_point(int k) {
  return kMarkerHandPoints[static_cast<size_t>(k)];
}

Eigen::Vector3d palm_plane_normal(const Eigen::Matrix<double, kNumPalmPoints, 3>& centred) {
  // The right singular vector of the smallest singular value of `centred` is the eigenvector of
  // the smallest eigenvalue of its scatter matrix.
  return least_variance_direction(centred.transpose() * centred);
}

PreparedFrame prepare_frame(const HandFrame& frame) {
  PreparedFrame fr;
  prepare_frame_into(frame.points, frame.hand_present, fr);
  return fr;
}

void prepare_frame_into(std::span<const Vec3, kNumHandPoints> points, bool hand_present, PreparedFrame& fr) {
  fr.valid = false;
  if (!hand_present) return;
  std::array<Eigen::Vector3d, kNumRayMarkers> s;
  // x − x is 0 for a finite x and NaN for NaN or ±inf, and NaN stays in a sum: one test for all
  // 66 coordinates instead of a branch each.
  double finite = 0.0;
  for (size_t k = 0; k < kNumRayMarkers; ++k) {
    const Eigen::Vector3d& p = points[static_cast<size_t>(kMarkerHandPoints[k])];
    s[k] = p;
    fr.mx[k] = p.x();
    fr.my[k] = p.y();
    fr.mz[k] = p.z();
    finite += (p.x() - p.x()) + (p.y() - p.y()) + (p.z() - p.z());
  }
  if (finite != 0.0) return;
  // Visibility step 1 approach vector a = (s1 + s17)/2 − s0.
  const Eigen::Vector3d a = (s[1] + s[17]) / 2.0 - s[0];
  fr.ax = a.x();
  fr.ay = a.y();
  fr.az = a.z();

  // Visibility step 3 palm points: u = unit(s1 − s9); P = {s5 + 3u, s9 + 3u, s13 + 3u, s18 + 3u, s1 − 5u, s17}.
  Eigen::Vector3d u = s[1] - s[9];
  const double ulen = u.norm();
  u = ulen > 0.0 ? Eigen::Vector3d(u / ulen) : Eigen::Vector3d::Zero();
  fr.palm_points = {s[5] + 3.0 * u, s[9] + 3.0 * u, s[13] + 3.0 * u, s[18] + 3.0 * u, s[1] - 5.0 * u, s[17]};
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& p : fr.palm_points) centroid += p;
  centroid /= static_cast<double>(kNumPalmPoints);
  Eigen::Matrix<double, kNumPalmPoints, 3> centred;
  for (int i = 0; i < kNumPalmPoints; ++i)
    centred.row(i) = (fr.palm_points[static_cast<size_t>(i)] - centroid).transpose();
  const Eigen::Vector3d normal = palm_plane_normal(centred);
  fr.cx = centroid.x();
  fr.cy = centroid.y();
  fr.cz = centroid.z();
  fr.nx = normal.x();
  fr.ny = normal.y();
  fr.nz = normal.z();
  build_convex_hull_into(fr.palm_points, fr.hull);

  // Visibility step 4 phalanges: finger f's markers m0…m3 give three segments.
  for (int f = 0; f < kNumDigits; ++f) {
    for (int seg = 0; seg < 3; ++seg) {
      const Eigen::Vector3d& b = s[static_cast<size_t>(finger_marker(f, seg))];
      const Eigen::Vector3d& e = s[static_cast<size_t>(finger_marker(f, seg + 1))];
      const Eigen::Vector3d dvec = e - b;
      const double len = dvec.norm();
      const Eigen::Vector3d w = len > 0.0 ? Eigen::Vector3d(dvec / len) : Eigen::Vector3d::Zero();
      const size_t p = static_cast<size_t>(3 * f + seg);
      fr.bx[p] = b.x();
      fr.by[p] = b.y();
      fr.bz[p] = b.z();
      fr.wx[p] = w.x();
      fr.wy[p] = w.y();
      fr.wz[p] = w.z();
      fr.len[p] = len;
    }
  }
  fr.valid = true;
}

std::vector<PreparedFrame> prepare_frames(std::span<const HandFrame> frames) {
  std::vector<PreparedFrame> out(frames.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, frames.size(), 64), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t j = r.begin(); j != r.end(); ++j) out[j] = prepare_frame(frames[j]);
  });
  return out;
}

}  // namespace lmc
