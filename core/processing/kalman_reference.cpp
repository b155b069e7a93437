#include "core/processing/kalman_reference.h"

#include <algorithm>
#include <array>
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

namespace {

// One coordinate's filter: state, covariance, and whether it has started.
struct ReferenceFilter {
  double x0 = 0.0, x1 = 0.0;  // position, velocity
  double p00 = 0.0, p01 = 0.0, p10 = 0.0, p11 = 0.0;
  bool started = false;
};

// One coordinate's inputs: each device's series and its rolling variance, n values each.
struct ReferenceSeries {
  std::vector<const double*> values;
  const double* variance = nullptr;  // device d's at variance + d·n
};

// Step i of one coordinate's filter; returns its output at i.
inline double reference_step(ReferenceFilter& k, const ReferenceSeries& in, int n, int i,
                             const ReferenceKalmanParams& params) {
  const size_t nd = in.values.size();
  if (!k.started) {
    for (size_t d = 0; d < nd; ++d) {
      const double y = in.values[d][i];
      if (std::isfinite(y)) {
        k.x0 = y;
        k.x1 = 0.0;
        k.p00 = params.p0_position;
        k.p01 = k.p10 = 0.0;
        k.p11 = params.p0_velocity;
        k.started = true;
        break;
      }
    }
    return k.started ? k.x0 : std::numeric_limits<double>::quiet_NaN();
  }
  const double dt = params.dt_s;
  // Predict: x = F x, P = F P Fᵀ + Q with F = [[1, dt], [0, 1]].
  k.x0 += dt * k.x1;
  const double n00 = k.p00 + dt * (k.p10 + k.p01) + dt * dt * k.p11 + params.q_position;
  const double n01 = k.p01 + dt * k.p11;
  const double n10 = k.p10 + dt * k.p11;
  const double n11 = k.p11 + params.q_velocity;
  k.p00 = n00;
  k.p01 = n01;
  k.p10 = n10;
  k.p11 = n11;
  for (size_t d = 0; d < nd; ++d) {
    const double y = in.values[d][i];
    const double r = in.variance[d * static_cast<size_t>(n) + static_cast<size_t>(i)];
    if (!std::isfinite(y) || !std::isfinite(r)) continue;
    const double s = k.p00 + r;
    const double k0 = k.p00 / s, k1 = k.p10 / s;
    const double innovation = y - k.x0;
    k.x0 += k0 * innovation;
    k.x1 += k1 * innovation;
    // P = P − K·H·P (the study's form, not Joseph's).
    const double q00 = k.p00 - k0 * k.p00, q01 = k.p01 - k0 * k.p01;
    const double q10 = k.p10 - k1 * k.p00, q11 = k.p11 - k1 * k.p01;
    k.p00 = q00;
    k.p01 = q01;
    k.p10 = q10;
    k.p11 = q11;
  }
  return k.x0;
}

// The rolling variances of every device's series of one coordinate, into `variance` (nd · n).
void device_variances(const std::vector<const double*>& values, int n, const ReferenceKalmanParams& params,
                      std::vector<double>& variance) {
  variance.resize(values.size() * static_cast<size_t>(n));
  for (size_t d = 0; d < values.size(); ++d)
    rolling_variance(values[d], n, params.window, variance.data() + d * static_cast<size_t>(n));
}

}  // namespace

void kalman_reference_1d(const std::vector<const double*>& series, int n, double* out,
                         const ReferenceKalmanParams& params) {
  std::vector<double> variance;
  device_variances(series, n, params, variance);
  const ReferenceSeries in{series, variance.data()};
  ReferenceFilter k;
  for (int i = 0; i < n; ++i) out[i] = reference_step(k, in, n, i, params);
}

HandTrack fuse_reference(const std::vector<const HandTrack*>& devices, const ReferenceKalmanParams& params) {
  const int n = devices.empty() ? 0 : devices.front()->frame_count;
  HandTrack fused(n);
  const size_t nd = devices.size();
  const auto steps = static_cast<size_t>(n);
  constexpr int kCoordinates = 3 * kNumHandPoints;
  // Every device's track turned coordinate-major in one pass (columns[(d · 90 + c) · n + f]): read
  // coordinate by coordinate, a track's frames 720 bytes apart were fetched from memory anew for
  // each of the 90.
  std::vector<double> columns(nd * kCoordinates * steps);
  for (size_t d = 0; d < nd; ++d) {
    double* const device_columns = columns.data() + d * kCoordinates * steps;
    for (size_t f = 0; f < steps; ++f) {
      for (int i = 0; i < kNumHandPoints; ++i) {
        const Vec3& p = devices[d]->at(static_cast<int>(f), i);
        for (int axis = 0; axis < 3; ++axis) device_columns[static_cast<size_t>(3 * i + axis) * steps + f] = p[axis];
      }
    }
  }
  // Four coordinates' filters step side by side: each filter's step is a chain of dependent
  // divisions, and four independent chains keep the CPU busy where one leaves it waiting. Every
  // filter does exactly what it does alone.
  constexpr int kSideBySide = 4;
  std::array<std::vector<double>, kSideBySide> variance;
  std::array<ReferenceSeries, kSideBySide> in;
  std::vector<double> out(kCoordinates * steps);  // coordinate-major, turned back at the end
  for (int first = 0; first < kCoordinates; first += kSideBySide) {
    const int count = std::min(kSideBySide, kCoordinates - first);
    for (int g = 0; g < count; ++g) {
      auto& series = in[static_cast<size_t>(g)];
      series.values.resize(nd);
      for (size_t d = 0; d < nd; ++d) {
        series.values[d] = columns.data() + (d * kCoordinates + static_cast<size_t>(first + g)) * steps;
      }
      device_variances(series.values, n, params, variance[static_cast<size_t>(g)]);
      series.variance = variance[static_cast<size_t>(g)].data();
    }
    std::array<ReferenceFilter, kSideBySide> filters{};
    for (int i = 0; i < n; ++i) {
      for (int g = 0; g < count; ++g) {
        out[static_cast<size_t>(first + g) * steps + static_cast<size_t>(i)] =
            reference_step(filters[static_cast<size_t>(g)], in[static_cast<size_t>(g)], n, i, params);
      }
    }
  }
  for (size_t f = 0; f < steps; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      Vec3& p = fused.at(static_cast<int>(f), i);
      for (int axis = 0; axis < 3; ++axis) p[axis] = out[static_cast<size_t>(3 * i + axis) * steps + f];
    }
  }
  return fused;
}

}  // namespace lmc
