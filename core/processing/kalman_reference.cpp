#include "core/processing/kalman_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lmc {

void rolling_variance(const double* x, int n, int window, double* out) {
  // pandas centres a window of w on label i as [i − w/2, i + (w − 1) − w/2] (docs/algorithms/fusion.md: i−15 … i+14).
  const int before = window / 2;
  const int after = window - 1 - before;
  // Sums of deviations from a shift value keep the one-pass formula well conditioned.
  double shift = 0.0;
  for (int i = 0; i < n; ++i) {
    if (std::isfinite(x[i])) {
      shift = x[i];
      break;
    }
  }
  // pandas (≥ 1.4) returns exactly 0 when every value in the window is the same (it counts the
  // run of equal values): a coordinate clipped at the controller's ±250 mm cut is such a run, and
  // the difference between 0 and a rounding residue decides whether the study's filter divides
  // 0 by 0 there. run[j] = how many finite values up to j, NaN skipped, equal x[j];
  // last_finite[j] = the last finite index ≤ j (−1 if none).
  std::vector<int> run(static_cast<size_t>(n), 0), last_finite(static_cast<size_t>(n), -1);
  for (int j = 0, prev = -1; j < n; ++j) {
    if (std::isfinite(x[j])) {
      run[static_cast<size_t>(j)] = prev >= 0 && x[prev] == x[j] ? run[static_cast<size_t>(prev)] + 1 : 1;
      prev = j;
    }
    last_finite[static_cast<size_t>(j)] = prev;
  }
  double s1 = 0.0, s2 = 0.0;
  int count = 0;
  auto add = [&](int j, double sign) {
    if (j < 0 || j >= n || !std::isfinite(x[j])) return;
    const double v = x[j] - shift;
    s1 += sign * v;
    s2 += sign * v * v;
    count += sign > 0 ? 1 : -1;
  };
  for (int j = 0; j <= after && j < n; ++j) add(j, 1.0);
  for (int i = 0; i < n; ++i) {
    if (i > 0) {
      add(i + after, 1.0);
      add(i - before - 1, -1.0);
    }
    const int last = last_finite[static_cast<size_t>(std::min(i + after, n - 1))];
    if (count < 2) {
      out[i] = std::numeric_limits<double>::quiet_NaN();
    } else if (last >= 0 && run[static_cast<size_t>(last)] >= count) {
      out[i] = 0.0;
    } else {
      const double var = (s2 - s1 * s1 / count) / (count - 1);
      out[i] = var < 0.0 ? 0.0 : var;
    }
  }
}

void kalman_reference_1d(const std::vector<const double*>& series, int n, double* out,
                         const ReferenceKalmanParams& params) {
  const size_t nd = series.size();
  std::vector<double> var(nd * static_cast<size_t>(n));
  for (size_t d = 0; d < nd; ++d)
    rolling_variance(series[d], n, params.window, var.data() + d * static_cast<size_t>(n));

  const double dt = params.dt_s;
  double x0 = 0.0, x1 = 0.0;  // position, velocity
  double p00 = 0.0, p01 = 0.0, p10 = 0.0, p11 = 0.0;
  bool started = false;
  for (int i = 0; i < n; ++i) {
    if (!started) {
      for (size_t d = 0; d < nd; ++d) {
        const double y = series[d][i];
        if (std::isfinite(y)) {
          x0 = y;
          x1 = 0.0;
          p00 = params.p0_position;
          p01 = p10 = 0.0;
          p11 = params.p0_velocity;
          started = true;
          break;
        }
      }
      out[i] = started ? x0 : std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    // Predict: x = F x, P = F P Fᵀ + Q with F = [[1, dt], [0, 1]].
    x0 += dt * x1;
    const double n00 = p00 + dt * (p10 + p01) + dt * dt * p11 + params.q_position;
    const double n01 = p01 + dt * p11;
    const double n10 = p10 + dt * p11;
    const double n11 = p11 + params.q_velocity;
    p00 = n00;
    p01 = n01;
    p10 = n10;
    p11 = n11;
    for (size_t d = 0; d < nd; ++d) {
      const double y = series[d][i];
      const double r = var[d * static_cast<size_t>(n) + static_cast<size_t>(i)];
      if (!std::isfinite(y) || !std::isfinite(r)) continue;
      const double s = p00 + r;
      const double k0 = p00 / s, k1 = p10 / s;
      const double innovation = y - x0;
      x0 += k0 * innovation;
      x1 += k1 * innovation;
      // P = P − K·H·P (the study's form, not Joseph's).
      const double q00 = p00 - k0 * p00, q01 = p01 - k0 * p01;
      const double q10 = p10 - k1 * p00, q11 = p11 - k1 * p01;
      p00 = q00;
      p01 = q01;
      p10 = q10;
      p11 = q11;
    }
    out[i] = x0;
  }
}

HandTrack fuse_reference(const std::vector<const HandTrack*>& devices, const ReferenceKalmanParams& params) {
  const int n = devices.empty() ? 0 : devices.front()->frame_count;
  HandTrack fused(n);
  const size_t nd = devices.size();
  std::vector<double> columns(nd * static_cast<size_t>(n));
  std::vector<double> out(static_cast<size_t>(n));
  std::vector<const double*> series(nd);
  for (int i = 0; i < kNumHandPoints; ++i) {
    for (int c = 0; c < 3; ++c) {
      for (size_t d = 0; d < nd; ++d) {
        double* col = columns.data() + d * static_cast<size_t>(n);
        for (int f = 0; f < n; ++f) col[f] = devices[d]->at(f, i)[c];
        series[d] = col;
      }
      kalman_reference_1d(series, n, out.data(), params);
      for (int f = 0; f < n; ++f) fused.at(f, i)[c] = out[static_cast<size_t>(f)];
    }
  }
  return fused;
}

}  // namespace lmc
