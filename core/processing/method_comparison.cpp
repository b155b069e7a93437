#include "core/processing/method_comparison.h"

#include <cmath>
#include <sstream>

#include "core/common/number_format.h"
#include "core/hand/hand_frame.h"

namespace lmc {

double ErrorAccumulator::rmse() const {
  return count > 0 ? std::sqrt(sum_sq / static_cast<double>(count)) : kNaN;
}

void MethodErrors::merge(const MethodErrors& o) {
  for (size_t k = 0; k < kNumFingers; ++k) {
    finger_all[k].merge(o.finger_all[k]);
    finger_unseen[k].merge(o.finger_unseen[k]);
  }
  for (size_t k = 0; k < kNumAngles; ++k) {
    angle_all[k].merge(o.angle_all[k]);
    angle_unseen[k].merge(o.angle_unseen[k]);
  }
  truth_values += o.truth_values;
  method_values += o.method_values;
}

ErrorAccumulator MethodErrors::finger_pooled(bool unseen) const {
  ErrorAccumulator a;
  for (const auto& e : unseen ? finger_unseen : finger_all) a.merge(e);
  return a;
}

ErrorAccumulator MethodErrors::angle_pooled(bool unseen) const {
  ErrorAccumulator a;
  for (const auto& e : unseen ? angle_unseen : angle_all) a.merge(e);
  return a;
}

MethodErrors trial_errors(const TrialAnalysis& r, const TrialAnalysis* other) {
  MethodErrors m;
  if (!r.has_vicon) return m;
  const size_t frames = std::min(r.lmc_frames.size(), r.vicon_frames.size());
  static constexpr std::array<int, kNumAngles> angle_finger{1, 1, 1, 0, 0, -1};
  for (size_t f = 0; f < frames; ++f) {
    std::array<bool, kNumDigits> unseen{};
    bool any_unseen = false;
    for (const auto& dev : r.labels) {
      if (f >= dev.size()) continue;
      for (size_t k = 0; k < kNumDigits; ++k) {
        if (dev[f][k] != 1) {
          unseen[k] = true;
          any_unseen = true;
        }
      }
    }
    const FrameMeasures& a = r.lmc_frames[f];
    const FrameMeasures& b = r.vicon_frames[f];
    const FrameMeasures* o = other != nullptr && f < other->lmc_frames.size() ? &other->lmc_frames[f] : nullptr;
    for (size_t k = 0; k < kNumFingers; ++k) {
      if (std::isfinite(b.finger_mm[k])) {
        ++m.truth_values;
        if (std::isfinite(a.finger_mm[k])) ++m.method_values;
      }
      const double e = a.finger_mm[k] - b.finger_mm[k];
      if (!std::isfinite(e) || (o != nullptr && !std::isfinite(o->finger_mm[k]))) continue;
      m.finger_all[k].add(e);
      if (unseen[k]) m.finger_unseen[k].add(e);
    }
    for (size_t k = 0; k < kNumAngles; ++k) {
      const double e = a.angle_deg[k] - b.angle_deg[k];
      if (!std::isfinite(e) || (o != nullptr && !std::isfinite(o->angle_deg[k]))) continue;
      m.angle_all[k].add(e);
      const int finger = angle_finger[k];
      if (finger < 0 ? any_unseen : unseen[static_cast<size_t>(finger)]) m.angle_unseen[k].add(e);
    }
  }
  return m;
}

std::string method_comparison_markdown(const MethodErrors& ref, const MethodErrors& def, int trials) {
  std::ostringstream o;
  o << "RMSE against truth over " << trials
    << " trial(s), per frame (100 Hz). \"not seen\": frames where at least one\n"
    << "device could not see the finger (ray-traced label 0 or no hand).\n\n";
  auto pct = [](const MethodErrors& m) {
    return m.truth_values > 0
               ? format_fixed(100.0 * static_cast<double>(m.method_values) / static_cast<double>(m.truth_values), 1)
               : std::string("nan");
  };
  o << "Both methods are scored on the same frames (where both give a value). Finger-length values given:\n"
    << "reference " << pct(ref) << " %, default " << pct(def) << " % of the frames with truth.\n\n";
  o << "| measure | reference, all | default, all | reference, not seen | default, not seen | frames all / not seen "
       "|\n";
  o << "|---|---:|---:|---:|---:|---:|\n";
  auto line = [&](const std::string& name, const ErrorAccumulator& ra, const ErrorAccumulator& da,
                  const ErrorAccumulator& ru, const ErrorAccumulator& du, const char* unit) {
    o << "| " << name << " (" << unit << ") | " << format_fixed(ra.rmse(), 2) << " | " << format_fixed(da.rmse(), 2)
      << " | " << format_fixed(ru.rmse(), 2) << " | " << format_fixed(du.rmse(), 2) << " | " << ra.count << " / "
      << ru.count << " |\n";
  };
  line("finger length, all fingers", ref.finger_pooled(false), def.finger_pooled(false), ref.finger_pooled(true),
       def.finger_pooled(true), "mm");
  for (size_t k = 0; k < kNumFingers; ++k) {
    line(std::string("finger length, ") + std::string(digit_name(k)), ref.finger_all[k], def.finger_all[k],
         ref.finger_unseen[k], def.finger_unseen[k], "mm");
  }
  line("joint angle, all joints", ref.angle_pooled(false), def.angle_pooled(false), ref.angle_pooled(true),
       def.angle_pooled(true), "deg");
  for (size_t k = 0; k < kNumAngles; ++k) {
    line(std::string("angle, ") + std::string(angle_name(static_cast<int>(k))), ref.angle_all[k], def.angle_all[k],
         ref.angle_unseen[k], def.angle_unseen[k], "deg");
  }
  return o.str();
}

}  // namespace lmc
