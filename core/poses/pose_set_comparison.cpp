#include "core/poses/pose_set_comparison.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "core/common/number_format.h"
#include "core/hand/hand_track.h"
#include "core/hand/palm_axes.h"
#include "core/processing/measures.h"

namespace lmc {
namespace {

constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
constexpr int kNumCompared = 6 + kNumAngles;

struct FrameQuantities {
  std::array<double, kNumCompared> v{};
  std::tuple<long, long, long, long> cell{};  // palm position (30 mm) × tilt (30°)
};

const char* const kNames[6] = {"palm across the table (x)",    "palm height (y)",
                               "palm towards the subject (z)", "palm tilt from facing down",
                               "hand heading on the table",    "hand pitch"};

std::vector<FrameQuantities> quantities_of(const PoseSet& set) {
  HandTrack track(set.size());
  for (int f = 0; f < set.size(); ++f) {
    for (int i = 0; i < kNumHandPoints; ++i) track.at(f, i) = set.frames[static_cast<size_t>(f)].point(i);
  }
  const std::vector<FrameMeasures> measures = measure_track(track);
  std::vector<FrameQuantities> out(static_cast<size_t>(set.size()));
  for (int f = 0; f < set.size(); ++f) {
    const HandFrame& h = set.frames[static_cast<size_t>(f)];
    FrameQuantities& q = out[static_cast<size_t>(f)];
    const Vec3& palm = h.point(kPalm);
    const PalmAxes axes = estimate_palm_axes(h);
    q.v[0] = palm.x();
    q.v[1] = palm.y();
    q.v[2] = palm.z();
    q.v[3] = std::acos(std::clamp(-axes.normal.y(), -1.0, 1.0)) * kRadToDeg;
    q.v[4] = std::atan2(axes.direction.x(), -axes.direction.z()) * kRadToDeg;
    q.v[5] = std::asin(std::clamp(axes.direction.y(), -1.0, 1.0)) * kRadToDeg;
    for (int k = 0; k < kNumAngles; ++k)
      q.v[static_cast<size_t>(6 + k)] = measures[static_cast<size_t>(f)].angle_deg[static_cast<size_t>(k)];
    auto step = [](double v, double size) { return std::isfinite(v) ? static_cast<long>(std::floor(v / size)) : 0L; };
    q.cell = {step(palm.x(), 30), step(palm.y(), 30), step(palm.z(), 30), step(q.v[3], 30)};
  }
  return out;
}

double median_of(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  const size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(mid), v.end());
  return v[mid];
}

std::vector<std::pair<double, double>> only_in(const std::vector<double>& mine, const std::vector<double>& other,
                                               double lo, double width) {
  std::vector<std::pair<double, double>> out;
  for (size_t i = 0; i < mine.size(); ++i) {
    if (mine[i] >= 0.01 && other[i] == 0.0) {
      const double a = lo + width * static_cast<double>(i), b = a + width;
      if (!out.empty() && std::abs(out.back().second - a) < 1e-9 * (1 + std::abs(a)))
        out.back().second = b;
      else
        out.emplace_back(a, b);
    }
  }
  return out;
}

QuantityComparison compare_quantity(int q, const std::vector<FrameQuantities>& a, const std::vector<FrameQuantities>& b,
                                    int bins) {
  QuantityComparison c;
  c.name = q < 6 ? kNames[q] : std::string(angle_name(q - 6)) + " angle";
  c.unit = q < 3 ? "mm" : "°";
  std::vector<double> av, bv;
  for (const auto& f : a)
    if (std::isfinite(f.v[static_cast<size_t>(q)])) av.push_back(f.v[static_cast<size_t>(q)]);
  for (const auto& f : b)
    if (std::isfinite(f.v[static_cast<size_t>(q)])) bv.push_back(f.v[static_cast<size_t>(q)]);
  double lo = INFINITY, hi = -INFINITY;
  for (const double v : av) lo = std::min(lo, v), hi = std::max(hi, v);
  for (const double v : bv) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!(lo <= hi)) lo = 0, hi = 1;
  if (hi - lo < 1e-6) lo -= 0.5, hi += 0.5;
  c.lo = lo;
  c.hi = hi;
  const double width = (hi - lo) / bins;
  auto histogram = [&](const std::vector<double>& v) {
    std::vector<double> h(static_cast<size_t>(bins), 0.0);
    for (const double x : v) h[static_cast<size_t>(std::clamp(static_cast<int>((x - lo) / width), 0, bins - 1))] += 1.0;
    for (double& s : h) s = v.empty() ? 0.0 : s / static_cast<double>(v.size());
    return h;
  };
  c.a_share = histogram(av);
  c.b_share = histogram(bv);
  for (int i = 0; i < bins; ++i)
    c.overlap += std::min(c.a_share[static_cast<size_t>(i)], c.b_share[static_cast<size_t>(i)]);
  c.a_median = median_of(av);
  c.b_median = median_of(bv);
  c.a_only = only_in(c.a_share, c.b_share, lo, width);
  c.b_only = only_in(c.b_share, c.a_share, lo, width);
  return c;
}

double share_outside(const std::vector<FrameQuantities>& mine, const std::vector<FrameQuantities>& other) {
  std::map<std::tuple<long, long, long, long>, int> seen;
  for (const auto& f : other) seen[f.cell] = 1;
  std::int64_t outside = 0;
  for (const auto& f : mine) outside += seen.count(f.cell) == 0;
  return mine.empty() ? 0.0 : static_cast<double>(outside) / static_cast<double>(mine.size());
}

std::string range_text(const std::vector<std::pair<double, double>>& ranges, const std::string& unit) {
  std::string s;
  for (const auto& [a, b] : ranges)
    s += (s.empty() ? "" : ", ") + format_fixed(a, 0) + "…" + format_fixed(b, 0) + " " + unit;
  return s;
}

}  // namespace

PoseSetComparison compare_pose_sets(const PoseSet& a, const PoseSet& b, int bins) {
  PoseSetComparison c;
  c.a_name = a.description;
  c.b_name = b.description;
  c.a_frames = a.size();
  c.b_frames = b.size();
  const auto qa = quantities_of(a), qb = quantities_of(b);
  for (int q = 0; q < kNumCompared; ++q) c.quantities.push_back(compare_quantity(q, qa, qb, bins));
  c.a_hands_b_never_has = share_outside(qa, qb);
  c.b_hands_a_never_has = share_outside(qb, qa);
  return c;
}

std::string format_pose_set_comparison(const PoseSetComparison& c) {
  std::string s = "A: " + c.a_name + " (" + std::to_string(c.a_frames) + " frames)\nB: " + c.b_name + " (" +
                  std::to_string(c.b_frames) + " frames)\n";
  for (const auto& q : c.quantities) {
    s += "  " + q.name + ": overlap " + format_fixed(100.0 * q.overlap, 1) + " %, median A " +
         format_fixed(q.a_median, 1) + " " + q.unit + ", B " + format_fixed(q.b_median, 1) + " " + q.unit + "\n";
    if (!q.a_only.empty()) s += "      only A: " + range_text(q.a_only, q.unit) + "\n";
    if (!q.b_only.empty()) s += "      only B: " + range_text(q.b_only, q.unit) + "\n";
  }
  s += "hands (palm position in 30 mm cubes x palm tilt in 30 deg steps) the other set never has: A " +
       format_fixed(100.0 * c.a_hands_b_never_has, 1) + " % of its frames, B " +
       format_fixed(100.0 * c.b_hands_a_never_has, 1) + " %\n";
  return s;
}

nlohmann::json pose_set_comparison_json(const PoseSetComparison& c) {
  nlohmann::json j;
  j["a"] = {{"description", c.a_name}, {"frames", c.a_frames}};
  j["b"] = {{"description", c.b_name}, {"frames", c.b_frames}};
  j["a_hands_b_never_has"] = c.a_hands_b_never_has;
  j["b_hands_a_never_has"] = c.b_hands_a_never_has;
  nlohmann::json qs = nlohmann::json::array();
  for (const auto& q : c.quantities) {
    qs.push_back({{"name", q.name},
                  {"unit", q.unit},
                  {"lo", q.lo},
                  {"hi", q.hi},
                  {"overlap", q.overlap},
                  {"a_median", q.a_median},
                  {"b_median", q.b_median},
                  {"a_share", q.a_share},
                  {"b_share", q.b_share},
                  {"a_only", q.a_only},
                  {"b_only", q.b_only}});
  }
  j["quantities"] = qs;
  return j;
}

}  // namespace lmc
