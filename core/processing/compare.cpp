#include "core/processing/compare.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lmc {

LagEstimate estimate_lag(const HandTrack& lmc, const HandTrack& vicon, int max_lag_frames) {
  LagEstimate best;
  const int n = lmc.frame_count, m = vicon.frame_count;
  auto mean_of = [](const HandTrack& t) {
    Vec3 s = Vec3::Zero();
    int c = 0;
    for (int f = 0; f < t.frame_count; ++f) {
      if (is_finite(t.at(f, kWrist))) {
        s += t.at(f, kWrist);
        ++c;
      }
    }
    return c > 0 ? Vec3(s / c) : Vec3(Vec3::Constant(kNaN));
  };
  const Vec3 ml = mean_of(lmc), mv = mean_of(vicon);
  if (!is_finite(ml) || !is_finite(mv)) return best;
  const int min_overlap = std::max(10, std::min(n, m) / 2);
  // Each track's centred wrist, its squared norm and whether it is there, laid out in a row once:
  // the scan below visits every pair ~100 times (once per lag), and reading the wrist out of each
  // 30-point frame every time was most of its cost. Same values, added in the same order.
  struct Centred {
    std::vector<Vec3> d;
    std::vector<double> sq;
    std::vector<char> ok;
  };
  const auto centred = [](const HandTrack& t, const Vec3& mean) {
    Centred c;
    c.d.resize(static_cast<size_t>(t.frame_count));
    c.sq.resize(c.d.size());
    c.ok.resize(c.d.size());
    for (int f = 0; f < t.frame_count; ++f) {
      const auto k = static_cast<size_t>(f);
      const Vec3& p = t.at(f, kWrist);
      c.ok[k] = is_finite(p) ? 1 : 0;
      c.d[k] = p - mean;
      c.sq[k] = c.d[k].squaredNorm();
    }
    return c;
  };
  const Centred a = centred(lmc, ml), b = centred(vicon, mv);
  double best_corr = -2.0;
  for (int lag = -max_lag_frames; lag <= max_lag_frames; ++lag) {
    double sab = 0, saa = 0, sbb = 0;
    int count = 0;
    for (int f = std::max(0, lag); f < std::min(n, m + lag); ++f) {
      const auto i = static_cast<size_t>(f), j = static_cast<size_t>(f - lag);
      if (!a.ok[i] || !b.ok[j]) continue;
      sab += a.d[i].dot(b.d[j]);
      saa += a.sq[i];
      sbb += b.sq[j];
      ++count;
    }
    if (count < min_overlap || saa <= 0.0 || sbb <= 0.0) continue;
    const double corr = sab / std::sqrt(saa * sbb);
    // Ties go to the smallest |lag| (scanning order would favour negative lags).
    if (corr > best_corr + 1e-12 ||
        (std::abs(corr - best_corr) <= 1e-12 && std::abs(lag) < std::abs(best.lag_frames))) {
      best_corr = corr;
      best.lag_frames = lag;
      best.correlation = corr;
      best.valid = true;
    }
  }
  best.clear = best.valid && best.correlation >= 0.9 && std::abs(best.lag_frames) < max_lag_frames;
  return best;
}

namespace {

template <size_t N, typename Get>
void diff_stats(const std::vector<FrameMeasures>& a, const std::vector<FrameMeasures>& b, size_t frames, Get get,
                std::array<double, N>& mean, std::array<double, N>& sd) {
  for (size_t k = 0; k < N; ++k) {
    double s = 0, s2 = 0;
    int c = 0;
    for (size_t f = 0; f < frames; ++f) {
      const double d = get(a[f])[k] - get(b[f])[k];
      if (!std::isfinite(d)) continue;
      s += d;
      s2 += d * d;
      ++c;
    }
    mean[k] = c > 0 ? s / c : kNaN;
    sd[k] = c > 1 ? std::sqrt(std::max(0.0, (s2 - s * s / c) / (c - 1))) : kNaN;
  }
}

}  // namespace

Comparison compare_measures(const std::vector<FrameMeasures>& lmc, const MeasureStats& ls,
                            const std::vector<FrameMeasures>& vicon, const MeasureStats& vs) {
  Comparison c;
  const size_t frames = std::min(lmc.size(), vicon.size());
  c.frames = static_cast<int>(frames);
  diff_stats<kNumFingers>(
      lmc, vicon, frames, [](const FrameMeasures& m) { return m.finger_mm; }, c.finger_diff_mean, c.finger_diff_sd);
  diff_stats<kNumAngles>(
      lmc, vicon, frames, [](const FrameMeasures& m) { return m.angle_deg; }, c.angle_diff_mean, c.angle_diff_sd);
  for (size_t k = 0; k < kNumFingers; ++k) c.finger_mean_diff[k] = ls.finger_mean[k] - vs.finger_mean[k];
  for (size_t k = 0; k < kNumAngles; ++k) c.rom_diff[k] = ls.angle_rom[k] - vs.angle_rom[k];
  return c;
}

}  // namespace lmc
