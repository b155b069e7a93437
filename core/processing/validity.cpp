#include "core/processing/validity.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lmc {
namespace {

std::string validity_cell(double v) {
  if (!std::isfinite(v)) return "      -";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%7.1f", v);
  return buf;
}

std::string validity_row(const std::string& label, const double* values, int n) {
  char head[64];
  std::snprintf(head, sizeof head, "  %-40s", label.c_str());
  std::string line = head;
  for (int i = 0; i < n; ++i) line += " " + validity_cell(values[i]);
  return line + "\n";
}

// Mean and RMS of LMC − Vicon over the frames both have (NaN skipped); untouched without any.
template <typename Measure>
void validity_bias_rmse(const TrialAnalysis& r, Measure measure, double& bias, double& rmse) {
  const size_t n = std::min(r.lmc_frames.size(), r.vicon_frames.size());
  double sum = 0, sq = 0;
  int count = 0;
  for (size_t j = 0; j < n; ++j) {
    const double d = measure(r.lmc_frames[j]) - measure(r.vicon_frames[j]);
    if (!std::isfinite(d)) continue;
    sum += d;
    sq += d * d;
    ++count;
  }
  if (count == 0) return;
  bias = sum / count;
  rmse = std::sqrt(sq / count);
}

// The rows' name for a method: its own ("default") unless the caller named it ("corrected"); short,
// so the rows keep their columns.
std::string label_of(const MethodValidity& m) {
  return m.label.empty() ? std::string(fusion_method_name(m.method)) : m.label;
}

}  // namespace

MethodValidity method_validity(const TrialAnalysis& r) {
  MethodValidity v;
  v.method = r.method;
  for (int f = 0; f < kNumFingers; ++f) {
    v.finger_mean[static_cast<size_t>(f)] = r.lmc_stats.finger_mean[static_cast<size_t>(f)];
    v.vicon_finger_mean[static_cast<size_t>(f)] =
        r.has_vicon ? r.vicon_stats.finger_mean[static_cast<size_t>(f)] : kNaN;
  }
  v.finger_bias.fill(kNaN);
  v.finger_rmse.fill(kNaN);
  v.angle_bias.fill(kNaN);
  v.angle_rmse.fill(kNaN);
  if (r.has_vicon) {
    for (int f = 0; f < kNumFingers; ++f) {
      validity_bias_rmse(
          r, [f](const FrameMeasures& m) { return m.finger_mm[static_cast<size_t>(f)]; },
          v.finger_bias[static_cast<size_t>(f)], v.finger_rmse[static_cast<size_t>(f)]);
    }
    for (int a = 0; a < kNumAngles; ++a) {
      validity_bias_rmse(
          r, [a](const FrameMeasures& m) { return m.angle_deg[static_cast<size_t>(a)]; },
          v.angle_bias[static_cast<size_t>(a)], v.angle_rmse[static_cast<size_t>(a)]);
    }
  }
  v.consensus = consensus_report(r.world.devices, r.labels, r.fused);
  return v;
}

std::string format_validity(const std::string& title, const std::vector<MethodValidity>& methods) {
  std::string out = title + "\n";
  char head[160];
  std::snprintf(head, sizeof head, "  %-40s %7s %7s %7s %7s %7s\n", "finger length, trial mean (mm)", "thumb", "index",
                "middle", "ring", "little");
  out += head;
  if (!methods.empty() && std::isfinite(methods.front().vicon_finger_mean[0]))
    out += validity_row("Vicon", methods.front().vicon_finger_mean.data(), kNumFingers);
  for (const auto& m : methods) out += validity_row(label_of(m) + " fusion", m.finger_mean.data(), kNumFingers);
  if (!methods.empty()) {
    const ConsensusReport& c = methods.front().consensus;
    double median[kNumFingers], lo[kNumFingers], hi[kNumFingers];
    for (int f = 0; f < kNumFingers; ++f) {
      median[f] = c.fingers[static_cast<size_t>(f)].finger.median;
      lo[f] = c.fingers[static_cast<size_t>(f)].finger.shortest;
      hi[f] = c.fingers[static_cast<size_t>(f)].finger.longest;
    }
    out += validity_row("median of the seeing controllers", median, kNumFingers);
    out += validity_row("shortest seeing controller", lo, kNumFingers);
    out += validity_row("longest seeing controller", hi, kNumFingers);
  }
  out += "  consensus (no Vicon needed): fused - median of the seeing controllers, on the frames they see it\n";
  for (const auto& m : methods) {
    double d[kNumFingers], pd[kNumFingers], seg[kNumFingers];
    for (int f = 0; f < kNumFingers; ++f) {
      const auto& fc = m.consensus.fingers[static_cast<size_t>(f)];
      d[f] = fc.finger.fused_minus_median();
      pd[f] = fc.point_distance_mm;
      // The segment of this finger that comes closest to (or furthest below) the shortest seeing
      // controller's: negative means the fusion made that segment shorter than every controller.
      seg[f] = kNaN;
      for (const LengthConsensus& sc : fc.segment) {
        const double v = sc.fused - sc.shortest;
        if (std::isfinite(v) && !(v >= seg[f])) seg[f] = v;
      }
    }
    out += validity_row(label_of(m) + ": fused - median (mm)", d, kNumFingers);
    out += validity_row(label_of(m) + ": min. segment - shortest ctrl.", seg, kNumFingers);
    out += validity_row(label_of(m) + ": fused point to seeing ctrl. (mm)", pd, kNumFingers);
  }
  if (!methods.empty() && std::isfinite(methods.front().vicon_finger_mean[0])) {
    out += "  against Vicon, per frame (LMC - Vicon)\n";
    for (const auto& m : methods) {
      out += validity_row(label_of(m) + ": finger bias (mm)", m.finger_bias.data(), kNumFingers);
      out += validity_row(label_of(m) + ": finger RMSE (mm)", m.finger_rmse.data(), kNumFingers);
    }
    std::snprintf(head, sizeof head, "  %-40s %7s %7s %7s %7s %7s %7s\n", "joint angle (deg)", "idxMCP", "idxPIP",
                  "idxDIP", "thbMCP", "thbDIP", "wrist");
    out += head;
    for (const auto& m : methods) {
      out += validity_row(label_of(m) + ": bias", m.angle_bias.data(), kNumAngles);
      out += validity_row(label_of(m) + ": RMSE", m.angle_rmse.data(), kNumAngles);
    }
  }
  return out;
}

}  // namespace lmc
