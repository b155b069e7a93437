#include "core/processing/fusion_smoother.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

#include "core/common/cpu_features.h"
#include "core/processing/cv_kalman.h"
#include "core/processing/fusion_lanes.h"

namespace lmc {
namespace {

// Which finger a hand point belongs to (−1: palm, vectors, elbow, wrist).
int point_finger(int i) {
  return i >= kFirstDigitPoint ? (i - kFirstDigitPoint) / kJointsPerDigit : -1;
}

// `rows` × `cols` row-major → `cols` × `rows` row-major, eight rows at a time so that both the
// reads and the writes stay within a few cache lines (a lane's steps are ~900 bytes apart). The
// result is not zeroed first: every element is written.
std::unique_ptr<double[]> transposed(const std::vector<double>& in, size_t rows, size_t cols) {
  auto out = std::make_unique_for_overwrite<double[]>(rows * cols);
  constexpr size_t kBlock = 8;
  for (size_t r0 = 0; r0 < rows; r0 += kBlock) {
    const size_t r1 = std::min(rows, r0 + kBlock);
    for (size_t c = 0; c < cols; ++c) {
      for (size_t r = r0; r < r1; ++r) out[c * rows + r] = in[r * cols + c];
    }
  }
  return out;
}

// One device's step into the inverse-variance sums: wsum += 1/variance, zsum += value/variance,
// for every lane whose value is finite. Four lanes at a time where the CPU has AVX2: the divisions
// are most of the fusion's arithmetic, and IEEE division and addition round each lane alike in
// either form. A skipped lane and one that adds +0 give the same sum (no sum is ever −0: they
// start at +0, and +0 + −0 is +0).
constexpr size_t kSumLanes = static_cast<size_t>(kFusionLanes);
void accumulate_lanes_plain(const double* value, const double* variance, double* wsum, double* zsum, size_t from = 0) {
  for (size_t l = from; l < kSumLanes; ++l) {
    if (!std::isfinite(value[l])) continue;
    wsum[l] += 1.0 / variance[l];
    zsum[l] += value[l] / variance[l];
  }
}
#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2")]] void accumulate_lanes_avx2(const double* value, const double* variance, double* wsum,
                                                   double* zsum) {
  const __m256d one = _mm256_set1_pd(1.0);
  const __m256d zero = _mm256_setzero_pd();
  size_t l = 0;
  for (; l + 4 <= kSumLanes; l += 4) {
    const __m256d v = _mm256_loadu_pd(value + l);
    const __m256d var = _mm256_loadu_pd(variance + l);
    const __m256d finite = _mm256_cmp_pd(_mm256_sub_pd(v, v), zero, _CMP_EQ_OQ);  // v − v is NaN for ±inf, NaN
    const __m256d w = _mm256_and_pd(_mm256_div_pd(one, var), finite);
    const __m256d z = _mm256_and_pd(_mm256_div_pd(v, var), finite);
    _mm256_storeu_pd(wsum + l, _mm256_add_pd(_mm256_loadu_pd(wsum + l), w));
    _mm256_storeu_pd(zsum + l, _mm256_add_pd(_mm256_loadu_pd(zsum + l), z));
  }
  accumulate_lanes_plain(value, variance, wsum, zsum, l);  // the lanes after the last four
}
#endif
void accumulate_lanes(const double* value, const double* variance, double* wsum, double* zsum) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (cpu_has_avx2()) {
    accumulate_lanes_avx2(value, variance, wsum, zsum);
    return;
  }
#endif
  accumulate_lanes_plain(value, variance, wsum, zsum);
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

// One lane's step: `z, r` hold the combined measurement (r = inf: none), the rest the filter's
// state, later overwritten by the smoother's.
struct Step {
  double x0, x1, p00, p01, p11;  // filtered (symmetric P)
  double z, r;                   // combined measurement (r = inf: none)
  CvKalman::Gain k;              // the filter's gain at this step (when measured)
  double c00, c01, c10, c11;     // the smoother's gain C from this step to the next
};

// The steps of a lane from its first to its last measurement (first < 0: never measured).
struct MeasuredSpan {
  int first = -1, last = -1;
};

MeasuredSpan measured_span(const std::vector<Step>& st) {
  MeasuredSpan span;
  for (int f = 0; f < static_cast<int>(st.size()); ++f) {
    if (!std::isfinite(st[static_cast<size_t>(f)].r)) continue;
    if (span.first < 0) span.first = f;
    span.last = f;
  }
  return span;
}

// Forward constant-velocity filter of several lanes from each one's first measurement, the lanes
// in step with each other: one lane's filter is a chain of dependent divisions, and running a few
// side by side lets the processor overlap them. Each lane's arithmetic is exactly its own.
template <size_t G>
void forward_filters(const std::array<std::vector<Step>*, G>& lanes, const std::array<MeasuredSpan, G>& spans,
                     const SmootherParams& p) {
  std::array<CvKalman, G> kf;
  int lo = std::numeric_limits<int>::max(), hi = -1;
  for (const auto& span : spans) {
    if (span.first < 0) continue;
    lo = std::min(lo, span.first);
    hi = std::max(hi, span.last);
  }
  for (int f = lo; f <= hi; ++f) {
    for (size_t k = 0; k < G; ++k) {
      if (lanes[k] == nullptr || f < spans[k].first || f > spans[k].last) continue;
      auto& s = (*lanes[k])[static_cast<size_t>(f)];
      if (f == spans[k].first) {
        kf[k].start(s.z, s.r);
      } else {
        kf[k].predict(p.dt_s, p.accel_psd);
        if (std::isfinite(s.r)) {
          s.k = kf[k].update_covariance(s.r);
          CvKalman::update_state(s.k, s.z, kf[k].x0, kf[k].x1);
        }
      }
      s.x0 = kf[k].x0;
      s.x1 = kf[k].x1;
      s.p00 = kf[k].p00;
      s.p01 = kf[k].p01;
      s.p11 = kf[k].p11;
    }
  }
}

// The forward filter of a lane measured exactly as `leader` (the same variances at the same
// steps), after the leader's forward_filters: only the state is stepped, with the leader's gains,
// which are bit for bit the ones this lane's own filter would compute.
void follow_forward(std::vector<Step>& st, const std::vector<Step>& leader, MeasuredSpan span,
                    const SmootherParams& p) {
  double x0 = 0.0, x1 = 0.0;
  for (int f = span.first; f <= span.last; ++f) {
    auto& s = st[static_cast<size_t>(f)];
    if (f == span.first) {
      CvKalman::start_state(s.z, x0, x1);
    } else {
      CvKalman::predict_state(p.dt_s, x0, x1);
      if (std::isfinite(s.r)) CvKalman::update_state(leader[static_cast<size_t>(f)].k, s.z, x0, x1);
    }
    s.x0 = x0;
    s.x1 = x1;
  }
}

// After forward_filters: the backward (Rauch–Tung–Striebel) smoother's gains C = P Fᵀ Pp⁻¹ over
// the lane's measured span, from its filtered covariances.
void smoother_gains(std::vector<Step>& st, MeasuredSpan span, const SmootherParams& p) {
  const double dt = p.dt_s;
  // Discrete white-noise-acceleration process noise.
  const double q00 = p.accel_psd * dt * dt * dt / 3.0, q01 = p.accel_psd * dt * dt / 2.0, q11 = p.accel_psd * dt;
  for (int f = span.last - 1; f >= span.first; --f) {
    auto& s = st[static_cast<size_t>(f)];
    // Predicted from s: Pp = F P Fᵀ + Q.
    const double pp00 = s.p00 + 2.0 * dt * s.p01 + dt * dt * s.p11 + q00;
    const double pp01 = s.p01 + dt * s.p11 + q01;
    const double pp11 = s.p11 + q11;
    const double a00 = s.p00 + dt * s.p01, a01 = s.p01;  // P Fᵀ row 0: (p00 + dt p01, p01)
    const double a10 = s.p01 + dt * s.p11, a11 = s.p11;  // row 1
    const double det = pp00 * pp11 - pp01 * pp01;
    const double i00 = pp11 / det, i01 = -pp01 / det, i11 = pp00 / det;
    s.c00 = a00 * i00 + a01 * i01;
    s.c01 = a00 * i01 + a01 * i11;
    s.c10 = a10 * i00 + a11 * i01;
    s.c11 = a10 * i01 + a11 * i11;
  }
}

// The backward pass of the states with the smoother gains in `gains` (the lane's own, or its
// leader's): the smoothed state overwrites the filtered one. Then the smoothed positions into
// `out(f)`, NaN inside stretches without measurement longer than max_gap_frames (and outside the
// measured span).
template <typename Out>
void smooth_and_output(std::vector<Step>& st, const std::vector<Step>& gains, MeasuredSpan span,
                       std::vector<int>& since, const SmootherParams& p, Out out) {
  if (span.first < 0) return;  // never measured: stays NaN
  const int first = span.first, last = span.last;
  const double dt = p.dt_s;
  for (int f = last - 1; f >= first; --f) {
    auto& s = st[static_cast<size_t>(f)];
    const auto& nx = st[static_cast<size_t>(f + 1)];
    const auto& c = gains[static_cast<size_t>(f)];
    const double xp0 = s.x0 + dt * s.x1, xp1 = s.x1;  // predicted from s: xp = F x
    const double d0 = nx.x0 - xp0, d1 = nx.x1 - xp1;
    s.x0 += c.c00 * d0 + c.c01 * d1;
    s.x1 += c.c10 * d0 + c.c11 * d1;
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

namespace {

// Inverse-variance combination of the devices per lane and step, accumulated device by device
// in order (as the online fuser combines them). Stored step-major, as hand_to_lanes produces a
// step's lanes together: stored lane-major, each step's writes would land ~100 cache lines apart.
void accumulate_device_sums(const std::vector<const HandTrack*>& devices,
                            const std::vector<const std::vector<float>*>& quality, double base_var, size_t steps,
                            std::vector<double>& wsum, std::vector<double>& zsum) {
  constexpr auto kL = static_cast<size_t>(kFusionLanes);
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
      accumulate_lanes(value.data(), variance.data(), wsum.data() + f * kL, zsum.data() + f * kL);
    }
  }
}

// Lanes measured alike share one filter's covariances and gains: the y and z of a point are
// nearly always measured exactly as its x (same devices, same variances, same steps), and the
// covariances and gains hold the divisions. A lane whose sums of inverse variances equal its
// point's x lane, bit for bit, follows that lane; any other (the bone lengths, a point measured
// in part) runs its own filter. The result is the same either way.
struct FilterLeaders {
  std::vector<size_t> leaders;    // the lanes that run a filter of their own, in order
  std::vector<int> followers_of;  // per lane: how many of the lanes after it (its point's y, then z) follow it
};

FilterLeaders filter_leaders(const double* wsum_lanes, size_t steps) {
  constexpr auto kL = static_cast<size_t>(kFusionLanes);
  FilterLeaders out;
  std::vector<size_t>& leaders = out.leaders;
  std::vector<int>& followers_of = out.followers_of;
  followers_of.assign(kL, 0);
  const auto same_bits = [](double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
  };
  for (size_t l = 0; l < kL; ++l) {
    leaders.push_back(l);
    if (l + 2 >= static_cast<size_t>(kFirstLengthLane) || l % 3 != 0) continue;
    const double* x = wsum_lanes + l * steps;
    while (followers_of[l] < 2 &&
           std::equal(x, x + steps, wsum_lanes + (l + 1 + static_cast<size_t>(followers_of[l])) * steps, same_bits)) {
      ++followers_of[l];
    }
    l += static_cast<size_t>(followers_of[l]);  // the followers run no filter of their own
  }
  return out;
}

}  // namespace

HandTrack fuse_default(const std::vector<const HandTrack*>& devices,
                       const std::vector<const std::vector<float>*>& quality, const SmootherParams& p) {
  using namespace fusion_smoother_detail;
  const int n = devices.empty() ? 0 : devices.front()->frame_count;
  HandTrack out(n);
  if (n == 0) return out;
  const double base_var = p.noise_mm * p.noise_mm;
  constexpr auto kL = static_cast<size_t>(kFusionLanes);

  const auto steps = static_cast<size_t>(n);
  std::vector<double> wsum(kL * steps, 0.0), zsum(kL * steps, 0.0);
  accumulate_device_sums(devices, quality, base_var, steps, wsum, zsum);

  // The sums turned lane-major for the filter passes, which walk one lane's steps in a row; the
  // smoothed lanes are turned back step-major for lanes_to_hand.
  const auto wsum_lanes = transposed(wsum, steps, kL);
  const auto zsum_lanes = transposed(zsum, steps, kL);
  std::vector<double> smoothed(kL * steps, kNaN);  // lane-major
  const FilterLeaders lanes = filter_leaders(wsum_lanes.get(), steps);
  const std::vector<size_t>& leaders = lanes.leaders;
  const std::vector<int>& followers_of = lanes.followers_of;
  // Each step's combined measurement of lane l: the inverse-variance mean and its variance.
  const auto fill_measurements = [&](size_t l, std::vector<Step>& lane) {
    for (size_t f = 0; f < steps; ++f) {
      const double w = wsum_lanes[l * steps + f];
      lane[f].z = w > 0.0 ? zsum_lanes[l * steps + f] / w : 0.0;
      lane[f].r = w > 0.0 ? 1.0 / w : INFINITY;
    }
  };
  constexpr size_t kGroup = 4;
  std::array<std::vector<Step>, kGroup> st;
  for (auto& lane : st) lane.resize(steps);
  std::vector<Step> follower(steps);
  std::vector<int> since(steps);
  for (size_t g0 = 0; g0 < leaders.size(); g0 += kGroup) {
    std::array<std::vector<Step>*, kGroup> group{};
    std::array<MeasuredSpan, kGroup> spans{};
    const size_t members = std::min(kGroup, leaders.size() - g0);
    for (size_t k = 0; k < members; ++k) {
      fill_measurements(leaders[g0 + k], st[k]);
      group[k] = &st[k];
      spans[k] = measured_span(st[k]);
    }
    forward_filters(group, spans, p);
    for (size_t k = 0; k < members; ++k) {
      const size_t l = leaders[g0 + k];
      if (spans[k].first < 0) continue;  // never measured: it and its followers stay NaN
      smoother_gains(st[k], spans[k], p);
      smooth_and_output(st[k], st[k], spans[k], since, p,
                        [&](int f, double x) { smoothed[l * steps + static_cast<size_t>(f)] = x; });
      for (size_t c = 1; c <= static_cast<size_t>(followers_of[l]); ++c) {
        fill_measurements(l + c, follower);
        follow_forward(follower, st[k], spans[k], p);
        smooth_and_output(follower, st[k], spans[k], since, p,
                          [&](int f, double x) { smoothed[(l + c) * steps + static_cast<size_t>(f)] = x; });
      }
    }
  }
  const auto fused = transposed(smoothed, kL, steps);  // step-major
  for (int f = 0; f < n; ++f) {
    lanes_to_hand(
        std::span<const double, kFusionLanes>(fused.get() + static_cast<size_t>(f) * kL, kL),
        std::span<Vec3, kNumHandPoints>(out.points.data() + static_cast<size_t>(f) * kNumHandPoints, kNumHandPoints));
  }
  return out;
}

}  // namespace lmc
