// The reference fusion against a direct matrix transcription of docs/algorithms/fusion.md.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "core/processing/kalman_reference.h"

namespace lmc {
namespace {

double brute_variance(const std::vector<double>& x, int i) {
  std::vector<double> w;
  for (int j = i - 15; j <= i + 14; ++j) {
    if (j >= 0 && j < static_cast<int>(x.size()) && std::isfinite(x[static_cast<size_t>(j)]))
      w.push_back(x[static_cast<size_t>(j)]);
  }
  if (w.size() < 2) return kNaN;
  double m = 0;
  for (double v : w) m += v;
  m /= static_cast<double>(w.size());
  double s = 0;
  for (double v : w) s += (v - m) * (v - m);
  return s / static_cast<double>(w.size() - 1);
}

TEST(RollingVariance, MatchesPandasCentredWindowWithNaN) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g(250.0, 3.0);
  std::vector<double> x(80);
  for (auto& v : x) v = g(rng);
  for (int k : {0, 1, 7, 40, 41, 42, 79}) x[static_cast<size_t>(k)] = kNaN;
  std::vector<double> out(x.size());
  rolling_variance(x.data(), static_cast<int>(x.size()), 30, out.data());
  for (int i = 0; i < static_cast<int>(x.size()); ++i) {
    EXPECT_NEAR(out[static_cast<size_t>(i)], brute_variance(x, i), 1e-9) << i;
  }
  // A window whose values are all the same (a clipped coordinate) has variance exactly 0, as in
  // pandas, even after noisy values have slid out of the running sums.
  std::vector<double> clipped(x.begin(), x.begin() + 40);
  clipped.insert(clipped.end(), 40, 249.99999999999997);
  clipped[60] = kNaN;
  std::vector<double> cv(clipped.size());
  rolling_variance(clipped.data(), static_cast<int>(clipped.size()), 30, cv.data());
  for (int i = 55; i < 80; ++i) EXPECT_EQ(cv[static_cast<size_t>(i)], 0.0) << i;
  EXPECT_GT(cv[40], 0.0);
  // Fewer than two values in the window → NaN.
  std::vector<double> lone{kNaN, 5.0, kNaN};
  std::vector<double> lo(3);
  rolling_variance(lone.data(), 3, 30, lo.data());
  EXPECT_TRUE(std::isnan(lo[0]) && std::isnan(lo[1]) && std::isnan(lo[2]));
}

// docs/algorithms/fusion.md written with matrices, as the study's script does.
std::vector<double> matrix_kalman(const std::vector<std::vector<double>>& s) {
  const int n = static_cast<int>(s[0].size());
  std::vector<std::vector<double>> var(s.size(), std::vector<double>(static_cast<size_t>(n)));
  for (size_t d = 0; d < s.size(); ++d) {
    for (int i = 0; i < n; ++i) var[d][static_cast<size_t>(i)] = brute_variance(s[d], i);
  }
  Eigen::Matrix2d F;
  F << 1, 0.01, 0, 1;
  const Eigen::Matrix2d Q = Eigen::Vector2d(0.04, 1.0).asDiagonal();
  const Eigen::RowVector2d H(1, 0);
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
  Eigen::Matrix2d P = Eigen::Matrix2d::Zero();
  bool started = false;
  std::vector<double> out(static_cast<size_t>(n), kNaN);
  for (int i = 0; i < n; ++i) {
    if (!started) {
      for (const auto& sd : s) {
        if (std::isfinite(sd[static_cast<size_t>(i)])) {
          x << sd[static_cast<size_t>(i)], 0;
          P = Eigen::Vector2d(100, 300).asDiagonal();
          started = true;
          break;
        }
      }
      if (started) out[static_cast<size_t>(i)] = x(0);
      continue;
    }
    x = F * x;
    P = F * P * F.transpose() + Q;
    for (size_t d = 0; d < s.size(); ++d) {
      const double y = s[d][static_cast<size_t>(i)], r = var[d][static_cast<size_t>(i)];
      if (!std::isfinite(y) || !std::isfinite(r)) continue;
      const double S = (H * P * H.transpose())(0, 0) + r;
      const Eigen::Vector2d K = P * H.transpose() / S;
      x = x + K * (y - (H * x)(0, 0));
      P = P - K * H * P;
    }
    out[static_cast<size_t>(i)] = x(0);
  }
  return out;
}

TEST(KalmanReference, MatchesMatrixFormWithNaNAndLateStart) {
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 1.5);
  const int n = 120;
  std::vector<std::vector<double>> s(4, std::vector<double>(n));
  for (int d = 0; d < 4; ++d) {
    for (int i = 0; i < n; ++i)
      s[static_cast<size_t>(d)][static_cast<size_t>(i)] = 100.0 + 20.0 * std::sin(i * 0.05) + 3.0 * d + g(rng);
  }
  // Nobody sees the hand for the first 5 steps; device 1 starts late (device 2 initialises);
  // device 3 drops out in the middle; device 4 has single NaNs.
  for (int i = 0; i < 5; ++i) {
    for (auto& sd : s) sd[static_cast<size_t>(i)] = kNaN;
  }
  for (int i = 0; i < 12; ++i) s[0][static_cast<size_t>(i)] = kNaN;
  for (int i = 50; i < 90; ++i) s[2][static_cast<size_t>(i)] = kNaN;
  for (int i : {20, 21, 70}) s[3][static_cast<size_t>(i)] = kNaN;

  std::vector<const double*> ptr;
  for (const auto& sd : s) ptr.push_back(sd.data());
  std::vector<double> out(n);
  kalman_reference_1d(ptr, n, out.data());
  const auto expected = matrix_kalman(s);
  for (int i = 0; i < 5; ++i) EXPECT_TRUE(std::isnan(out[static_cast<size_t>(i)]));
  EXPECT_DOUBLE_EQ(out[5], s[1][5]);  // first device in order with a value initialises
  for (int i = 5; i < n; ++i) EXPECT_NEAR(out[static_cast<size_t>(i)], expected[static_cast<size_t>(i)], 1e-9) << i;
}

// Two devices whose coordinate sits on the ±250 mm cut (exactly constant): their rolling
// variances are exactly 0, the first update leaves P = 0 and the second divides 0 by 0, so the
// study's filter loses that coordinate from there on. One clipped device alone does no harm.
TEST(KalmanReference, TwoClippedDevicesGiveNaNOneDoesNot) {
  const int n = 60;
  std::vector<double> a(n, 250.0), b(n, 250.0), c(n);
  for (int i = 0; i < n; ++i) c[static_cast<size_t>(i)] = 240.0 + 0.5 * ((i % 3) - 1);
  std::vector<double> out(n);
  kalman_reference_1d({a.data(), b.data()}, n, out.data());
  EXPECT_DOUBLE_EQ(out[0], 250.0);
  for (int i = 1; i < n; ++i) EXPECT_TRUE(std::isnan(out[static_cast<size_t>(i)])) << i;
  kalman_reference_1d({a.data(), c.data()}, n, out.data());
  for (int i = 0; i < n; ++i) EXPECT_NEAR(out[static_cast<size_t>(i)], 250.0, 1e-9) << i;
}

TEST(KalmanReference, FusesAllThirtyPointsOfTracks) {
  HandTrack a(40), b(40);
  for (int f = 0; f < 40; ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) {
      // Small wobble: a series with zero rolling variance gives 0/0 in the study's update (NaN),
      // which the reference reproduces on purpose.
      const double w = 0.2 * ((f % 2) ? 1.0 : -1.0);
      a.at(f, i) = Vec3(i + w, 2.0 * i + 0.01 * f, -i + w);
      b.at(f, i) = Vec3(i + 1.0 - w, 2.0 * i + 0.01 * f, -i - w);
    }
  }
  const HandTrack fused = fuse_reference({&a, &b});
  ASSERT_EQ(fused.frame_count, 40);
  // x: devices disagree by 1 mm with equal variance ≈ 0 → estimate between them.
  EXPECT_GT(fused.at(39, 7).x(), 7.0);
  EXPECT_LT(fused.at(39, 7).x(), 8.0);
  EXPECT_DOUBLE_EQ(fused.at(0, 7).x(), 7.0 - 0.2);  // initial state = first device
  EXPECT_NEAR(fused.at(39, 29).z(), -29.0, 0.2);
}

// The whole-track fusion runs four coordinates' filters side by side from coordinate-major copies
// of the tracks; each must give, bit for bit, what the one-coordinate filter gives on that
// coordinate alone: with gaps, devices that start late, a coordinate no device ever sees, and the
// last group of two (90 coordinates are not a multiple of four).
TEST(KalmanReference, EveryCoordinateOfTheTrackFusionIsItsOwnFilterBitForBit) {
  constexpr int n = 300;
  std::mt19937_64 rng(33);
  std::normal_distribution<double> noise(0.0, 1.5);
  std::vector<HandTrack> tracks(3, HandTrack(n));
  for (size_t d = 0; d < tracks.size(); ++d) {
    for (int f = 0; f < n; ++f) {
      for (int i = 0; i < kNumHandPoints; ++i) {
        Vec3 p(10.0 * i + 20.0 * std::sin(0.03 * f) + noise(rng), -3.0 * i + noise(rng), 0.5 * f + noise(rng));
        const bool gap = (f + 17 * i + 40 * static_cast<int>(d)) % 97 < 9;  // a gap every so often
        const bool late = f < 25 * static_cast<int>(d) + i;                 // later devices start later
        if (gap || late || i == 11) p.setConstant(std::numeric_limits<double>::quiet_NaN());
        tracks[d].at(f, i) = p;
      }
    }
  }
  const HandTrack fused = fuse_reference({&tracks[0], &tracks[1], &tracks[2]});
  long compared = 0, finite = 0;
  for (int i = 0; i < kNumHandPoints; ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<std::vector<double>> columns(tracks.size(), std::vector<double>(n));
      std::vector<const double*> series;
      for (size_t d = 0; d < tracks.size(); ++d) {
        for (int f = 0; f < n; ++f) columns[d][static_cast<size_t>(f)] = tracks[d].at(f, i)[axis];
        series.push_back(columns[d].data());
      }
      std::vector<double> alone(n);
      kalman_reference_1d(series, n, alone.data());
      for (int f = 0; f < n; ++f) {
        const double a = alone[static_cast<size_t>(f)], b = fused.at(f, i)[axis];
        ASSERT_EQ(std::bit_cast<std::uint64_t>(a), std::bit_cast<std::uint64_t>(b))
            << "point " << i << " axis " << axis << " frame " << f << ": alone " << a << ", in the track " << b;
        ++compared;
        finite += std::isfinite(a) ? 1 : 0;
      }
    }
  }
  EXPECT_EQ(compared, 90L * n);
  EXPECT_GT(finite, compared / 2);
  EXPECT_LT(finite, compared) << "the never-seen point and the late starts must give NaN";
}

}  // namespace
}  // namespace lmc
