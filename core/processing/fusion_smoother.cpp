#include "core/processing/fusion_smoother.h"

#include <array>
#include <cmath>

#include "core/processing/cv_kalman.h"
#include "core/processing/fusion_lanes.h"

namespace lmc {
namespace {

// Which finger a hand point belongs to (−1: palm, vectors, elbow, wrist).
int point_finger(int i) {
  return i >= kFirstDigitPoint ? (i - kFirstDigitPoint) / kJointsPerDigit : -1;
}

}  // namespace

namespace fusion_smoother_detail {

// A controller that cuts an axis reports the cut value itself (±axis_cut_mm, blurred by the
// resampler by up to the margin). A coordinate clearly beyond it was not cut on that axis: on the
// study's real trial three of the four controllers report the whole hand at y = 250–275 mm, and
// counting those as cut left the one controller with the smallest hand model to fuse alone.
bool at_axis_cut(double coordinate, const SmootherParams& p) {
  return std::abs(std::abs(coordinate) - p.axis_cut_mm) <= p.axis_cut_margin_mm;
}

}  // namespace fusion_smoother_detail

void frame_quality(std::span<const Vec3, kNumHandPoints> v, const FingerLabels* row, const SmootherParams& p,
                   std::span<float, kNumHandPoints> out) {
  using fusion_smoother_detail::at_axis_cut;
  bool any_visible = row == nullptr;
  if (row != nullptr) {
    for (int k = 0; k < kNumDigits; ++k) any_visible = any_visible || (*row)[static_cast<size_t>(k)] == 1;
  }
  std::array<double, kNumDigits> finger_cut{};
  finger_cut.fill(1.0);
  for (int i = 0; i < kNumHandPoints; ++i) {
    double factor = 1.0;
    const int finger = point_finger(i);
    if (row != nullptr) {
      const bool visible = finger >= 0 ? (*row)[static_cast<size_t>(finger)] == 1 : any_visible;
      if (!visible) factor *= p.hidden_factor;
    }
    if (i != kPalmNormal && i != kPalmDirection) {
      const Vec3& x = v[static_cast<size_t>(i)];
      if (at_axis_cut(x.x(), p) || at_axis_cut(x.y(), p) || at_axis_cut(x.z(), p)) {
        if (finger >= 0) {
          finger_cut[static_cast<size_t>(finger)] = p.axis_cut_factor;
        } else {
          factor *= p.axis_cut_factor;
        }
      }
    }
    if (i == kElbow) factor *= p.elbow_factor;
    out[static_cast<size_t>(i)] = static_cast<float>(factor);
  }
  // A finger's points share one weight, its worst joint's: weights that differ between the joints
  // of one finger stitch its fused points from controllers whose hands are millimetres apart.
  for (int i = kFirstDigitPoint; i < kNumHandPoints; ++i) {
    out[static_cast<size_t>(i)] *= static_cast<float>(finger_cut[static_cast<size_t>(point_finger(i))]);
  }
}

std::vector<float> sample_quality(const HandTrack& t, const std::vector<FingerLabels>& labels,
                                  const SmootherParams& p) {
  std::vector<float> q(static_cast<size_t>(t.frame_count) * kNumHandPoints, 1.0f);
  for (int f = 0; f < t.frame_count; ++f) {
    const size_t base = static_cast<size_t>(f) * kNumHandPoints;
    frame_quality(std::span<const Vec3, kNumHandPoints>(t.points.data() + base, kNumHandPoints),
                  labels.empty() ? nullptr : &labels[static_cast<size_t>(f)], p,
                  std::span<float, kNumHandPoints>(q.data() + base, kNumHandPoints));
  }
  return q;
}

namespace fusion_smoother_detail {

// One lane over the trial: `st[f].z, .r` hold the combined measurement per step (r = inf: none).
// Forward constant-velocity filter from the first measurement, backward (RTS) smoother, then the
// smoothed positions into `out(f)`, NaN inside stretches without measurement longer than
// max_gap_frames (and outside the measured span).
struct Step {
  double x0, x1, p00, p01, p11;  // filtered (symmetric P)
  double z, r;                   // combined measurement (r = inf: none)
};

template <typename Out>
void smooth_lane(std::vector<Step>& st, std::vector<int>& since, const SmootherParams& p, Out out) {
  const int n = static_cast<int>(st.size());
  const double dt = p.dt_s;
  // Discrete white-noise-acceleration process noise.
  const double q00 = p.accel_psd * dt * dt * dt / 3.0, q01 = p.accel_psd * dt * dt / 2.0, q11 = p.accel_psd * dt;
  int first = -1, last = -1;
  for (int f = 0; f < n; ++f) {
    if (!std::isfinite(st[static_cast<size_t>(f)].r)) continue;
    if (first < 0) first = f;
    last = f;
  }
  if (first < 0) return;  // never measured: stays NaN
  // Forward filter from the first measurement.
  CvKalman kf;
  kf.start(st[static_cast<size_t>(first)].z, st[static_cast<size_t>(first)].r);
  for (int f = first; f <= last; ++f) {
    auto& s = st[static_cast<size_t>(f)];
    if (f > first) {
      kf.predict(dt, p.accel_psd);
      if (std::isfinite(s.r)) kf.update(s.z, s.r);
    }
    s.x0 = kf.x0;
    s.x1 = kf.x1;
    s.p00 = kf.p00;
    s.p01 = kf.p01;
    s.p11 = kf.p11;
  }
  // Backward (RTS) pass: smoothed state overwrites the filtered one (only the means are output).
  for (int f = last - 1; f >= first; --f) {
    auto& s = st[static_cast<size_t>(f)];
    const auto& nx = st[static_cast<size_t>(f + 1)];
    // Predicted from s: xp = F x, Pp = F P Fᵀ + Q.
    const double xp0 = s.x0 + dt * s.x1, xp1 = s.x1;
    const double pp00 = s.p00 + 2.0 * dt * s.p01 + dt * dt * s.p11 + q00;
    const double pp01 = s.p01 + dt * s.p11 + q01;
    const double pp11 = s.p11 + q11;
    // C = P Fᵀ Pp⁻¹.
    const double a00 = s.p00 + dt * s.p01, a01 = s.p01;  // P Fᵀ row 0: (p00 + dt p01, p01)
    const double a10 = s.p01 + dt * s.p11, a11 = s.p11;  // row 1
    const double det = pp00 * pp11 - pp01 * pp01;
    const double i00 = pp11 / det, i01 = -pp01 / det, i11 = pp00 / det;
    const double c00 = a00 * i00 + a01 * i01, c01 = a00 * i01 + a01 * i11;
    const double c10 = a10 * i00 + a11 * i01, c11 = a10 * i01 + a11 * i11;
    const double d0 = nx.x0 - xp0, d1 = nx.x1 - xp1;
    s.x0 += c00 * d0 + c01 * d1;
    s.x1 += c10 * d0 + c11 * d1;
  }
  // Output, with NaN inside long stretches without any measurement.
  int gap = 0;
  for (int f = first; f <= last; ++f) {
    gap = std::isfinite(st[static_cast<size_t>(f)].r) ? 0 : gap + 1;
    since[static_cast<size_t>(f)] = gap;
  }
  // A stretch is NaN when its full length (not just the part so far) exceeds the limit.
  for (int f = last; f >= first; --f) {
    if (since[static_cast<size_t>(f)] > 0 && f + 1 <= last &&
        since[static_cast<size_t>(f + 1)] > since[static_cast<size_t>(f)]) {
      since[static_cast<size_t>(f)] = since[static_cast<size_t>(f + 1)];
    }
  }
  for (int f = first; f <= last; ++f) {
    if (since[static_cast<size_t>(f)] <= p.max_gap_frames) out(f, st[static_cast<size_t>(f)].x0);
  }
}

}  // namespace fusion_smoother_detail

HandTrack fuse_default(const std::vector<const HandTrack*>& devices,
                       const std::vector<const std::vector<float>*>& quality, const SmootherParams& p) {
  using namespace fusion_smoother_detail;
  const int n = devices.empty() ? 0 : devices.front()->frame_count;
  HandTrack out(n);
  if (n == 0) return out;
  const double base_var = p.noise_mm * p.noise_mm;
  constexpr auto kL = static_cast<size_t>(kFusionLanes);

  // Inverse-variance combination of the devices per lane and step, accumulated device by device
  // in order (as the online fuser combines them), stored lane-major so each lane's filter pass
  // reads its steps in a row.
  const auto steps = static_cast<size_t>(n);
  std::vector<double> wsum(kL * steps, 0.0), zsum(kL * steps, 0.0);
  std::array<float, kNumHandPoints> ones;
  ones.fill(1.0f);
  std::array<double, kFusionLanes> value, variance;
  for (size_t d = 0; d < devices.size(); ++d) {
    const bool has_q = d < quality.size() && quality[d] != nullptr;
    for (size_t f = 0; f < steps; ++f) {
      const size_t at = f * kNumHandPoints;
      hand_to_lanes(std::span<const Vec3, kNumHandPoints>(devices[d]->points.data() + at, kNumHandPoints),
                    has_q ? std::span<const float, kNumHandPoints>(quality[d]->data() + at, kNumHandPoints)
                          : std::span<const float, kNumHandPoints>(ones),
                    base_var, value, variance);
      for (size_t l = 0; l < kL; ++l) {
        if (!std::isfinite(value[l])) continue;
        wsum[l * steps + f] += 1.0 / variance[l];
        zsum[l * steps + f] += value[l] / variance[l];
      }
    }
  }

  std::vector<double> fused(steps * kL, kNaN);  // frame-major, as lanes_to_hand reads it
  std::vector<Step> st(steps);
  std::vector<int> since(steps);
  for (size_t l = 0; l < kL; ++l) {
    for (size_t f = 0; f < steps; ++f) {
      const double w = wsum[l * steps + f];
      st[f].z = w > 0.0 ? zsum[l * steps + f] / w : 0.0;
      st[f].r = w > 0.0 ? 1.0 / w : INFINITY;
    }
    smooth_lane(st, since, p, [&](int f, double x) { fused[static_cast<size_t>(f) * kL + l] = x; });
  }
  for (int f = 0; f < n; ++f) {
    lanes_to_hand(
        std::span<const double, kFusionLanes>(fused.data() + static_cast<size_t>(f) * kL, kL),
        std::span<Vec3, kNumHandPoints>(out.points.data() + static_cast<size_t>(f) * kNumHandPoints, kNumHandPoints));
  }
  return out;
}

}  // namespace lmc
