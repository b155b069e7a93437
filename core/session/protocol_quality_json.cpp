#include "core/session/protocol_quality_json.h"

namespace lmc {
namespace {

struct QualityField {
  const char* key;
  double QualityThresholds::*member;
  bool fraction;  // 0…1, else a positive number (Hz or s)
};

constexpr QualityField kQualityFields[] = {
    {"fail_min_rate_hz", &QualityThresholds::fail_min_rate_hz, false},
    {"warn_min_rate_hz", &QualityThresholds::warn_min_rate_hz, false},
    {"fail_max_gap_s", &QualityThresholds::fail_max_gap_s, false},
    {"warn_max_gap_s", &QualityThresholds::warn_max_gap_s, false},
    {"fail_min_hand_fraction", &QualityThresholds::fail_min_hand_fraction, true},
    {"warn_min_hand_fraction", &QualityThresholds::warn_min_hand_fraction, true},
    {"warn_max_finger_unseen", &QualityThresholds::warn_max_finger_unseen, true},
    {"warn_min_rom_fraction", &QualityThresholds::warn_min_rom_fraction, true},
    {"fail_min_duration_fraction", &QualityThresholds::fail_min_duration_fraction, true},
};

}  // namespace

QualityThresholds quality_thresholds_from_json(const JsonReader& r, const QualityThresholds& defaults) {
  r.only_keys({"fail_min_rate_hz", "warn_min_rate_hz", "fail_max_gap_s", "warn_max_gap_s", "fail_min_hand_fraction",
               "warn_min_hand_fraction", "warn_max_finger_unseen", "warn_min_rom_fraction",
               "fail_min_duration_fraction"});
  QualityThresholds q = defaults;
  for (const QualityField& f : kQualityFields) {
    if (!r.has(f.key)) continue;
    const JsonReader v = r.at(f.key);
    const double x = v.number();
    if (f.fraction ? !(x >= 0 && x <= 1) : !(x >= 0)) v.fail(f.fraction ? "must be between 0 and 1" : "must be ≥ 0");
    q.*f.member = x;
  }
  // A warn line stricter than its fail line would make a fault look milder than a doubt.
  if (q.warn_min_rate_hz < q.fail_min_rate_hz) r.fail("warn_min_rate_hz is below fail_min_rate_hz");
  if (q.warn_max_gap_s > q.fail_max_gap_s) r.fail("warn_max_gap_s is above fail_max_gap_s");
  return q;
}

nlohmann::json quality_thresholds_to_json(const QualityThresholds& q) {
  nlohmann::json j = nlohmann::json::object();
  for (const QualityField& f : kQualityFields) j[f.key] = q.*f.member;
  return j;
}

}  // namespace lmc
