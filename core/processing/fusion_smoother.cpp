#include "core/processing/fusion_smoother.h"

#include <cmath>

#include "core/processing/cv_kalman.h"

namespace lmc {
namespace {

// Which finger a hand point belongs to (−1: palm, vectors, elbow, wrist).
int point_finger(int i) { return i >= kFirstDigitPoint ? (i - kFirstDigitPoint) / kJointsPerDigit : -1; }

}  // namespace

void frame_quality(std::span<const Vec3, kNumHandPoints> v, const FingerLabels* row, const SmootherParams& p,
                   std::span<float, kNumHandPoints> out) {
  const double cut = p.axis_cut_mm - p.axis_cut_margin_mm;
  bool any_visible = row == nullptr;
  if (row != nullptr) {
    for (int k = 0; k < kNumDigits; ++k) any_visible = any_visible || (*row)[static_cast<size_t>(k)] == 1;
  }
  for (int i = 0; i < kNumHandPoints; ++i) {
    double factor = 1.0;
    const int finger = point_finger(i);
    if (row != nullptr) {
      const bool visible = finger >= 0 ? (*row)[static_cast<size_t>(finger)] == 1 : any_visible;
      if (!visible) factor *= p.hidden_factor;
    }
    if (i != kPalmNormal && i != kPalmDirection) {
      const Vec3& x = v[static_cast<size_t>(i)];
      if (std::abs(x.x()) >= cut || std::abs(x.y()) >= cut || std::abs(x.z()) >= cut) factor *= p.axis_cut_factor;
    }
    if (i == kElbow) factor *= p.elbow_factor;
    out[static_cast<size_t>(i)] = static_cast<float>(factor);
  }
}

std::vector<float> sample_quality(const HandTrack& t, const std::vector<FingerLabels>& labels, const SmootherParams& p) {
  std::vector<float> q(static_cast<size_t>(t.frame_count) * kNumHandPoints, 1.0f);
  for (int f = 0; f < t.frame_count; ++f) {
    const size_t base = static_cast<size_t>(f) * kNumHandPoints;
    frame_quality(std::span<const Vec3, kNumHandPoints>(t.points.data() + base, kNumHandPoints),
                  labels.empty() ? nullptr : &labels[static_cast<size_t>(f)], p,
                  std::span<float, kNumHandPoints>(q.data() + base, kNumHandPoints));
  }
  return q;
}

HandTrack fuse_default(const std::vector<const HandTrack*>& devices, const std::vector<const std::vector<float>*>& quality,
                       const SmootherParams& p) {
  const int n = devices.empty() ? 0 : devices.front()->frame_count;
  HandTrack out(n);
  if (n == 0) return out;
  const double dt = p.dt_s;
  const double base_var = p.noise_mm * p.noise_mm;
  // Discrete white-noise-acceleration process noise.
  const double q00 = p.accel_psd * dt * dt * dt / 3.0, q01 = p.accel_psd * dt * dt / 2.0, q11 = p.accel_psd * dt;

  struct Step {
    double x0, x1, p00, p01, p11;  // filtered (symmetric P)
    double z, r;                   // combined measurement (r = inf: none)
  };
  std::vector<Step> st(static_cast<size_t>(n));
  std::vector<int> since(static_cast<size_t>(n));

  for (int i = 0; i < kNumHandPoints; ++i) {
    for (int c = 0; c < 3; ++c) {
      // Combined measurement per step.
      int first = -1, last = -1;
      for (int f = 0; f < n; ++f) {
        double wsum = 0.0, zsum = 0.0;
        for (size_t d = 0; d < devices.size(); ++d) {
          const double y = devices[d]->at(f, i)[c];
          if (!std::isfinite(y)) continue;
          double var = base_var;
          if (d < quality.size() && quality[d] != nullptr) {
            var *= static_cast<double>((*quality[d])[static_cast<size_t>(f) * kNumHandPoints + static_cast<size_t>(i)]);
          }
          wsum += 1.0 / var;
          zsum += y / var;
        }
        auto& s = st[static_cast<size_t>(f)];
        if (wsum > 0.0) {
          s.z = zsum / wsum;
          s.r = 1.0 / wsum;
          if (first < 0) first = f;
          last = f;
        } else {
          s.z = 0.0;
          s.r = INFINITY;
        }
      }
      if (first < 0) continue;  // never measured: stays NaN
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
      // Backward (RTS) pass: smoothed state overwrites the filtered one.
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
        // Covariances are not needed after smoothing; only the means are output.
        (void)s.p00;
      }
      // Output, with NaN inside long stretches without any measurement.
      int gap = 0;
      for (int f = first; f <= last; ++f) since[static_cast<size_t>(f)] = 0;
      for (int f = first; f <= last; ++f) {
        gap = std::isfinite(st[static_cast<size_t>(f)].r) ? 0 : gap + 1;
        since[static_cast<size_t>(f)] = gap;
      }
      // A stretch is NaN when its full length (not just the part so far) exceeds the limit.
      for (int f = last; f >= first; --f) {
        if (since[static_cast<size_t>(f)] > 0 && f + 1 <= last && since[static_cast<size_t>(f + 1)] > since[static_cast<size_t>(f)]) {
          since[static_cast<size_t>(f)] = since[static_cast<size_t>(f + 1)];
        }
      }
      for (int f = first; f <= last; ++f) {
        out.at(f, i)[c] = since[static_cast<size_t>(f)] > p.max_gap_frames ? kNaN : st[static_cast<size_t>(f)].x0;
      }
    }
  }
  return out;
}

}  // namespace lmc
