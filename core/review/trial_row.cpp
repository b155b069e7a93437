#include "core/review/trial_row.h"

#include <cmath>

#include "core/common/nan.h"
#include "core/processing/trial_tag.h"

namespace lmc {
namespace {

double summary_number_or_nan(const nlohmann::json& v) {
  return v.is_number() ? v.get<double>() : kNaN;
}

// Mean of the finite entries of a JSON array (nulls are unknown values, not zeros).
double mean_of(const nlohmann::json& values, bool absolute) {
  double sum = 0;
  int n = 0;
  if (!values.is_array()) return kNaN;
  for (const auto& v : values) {
    const double x = summary_number_or_nan(v);
    if (!std::isfinite(x)) continue;
    sum += absolute ? std::abs(x) : x;
    ++n;
  }
  return n > 0 ? sum / n : kNaN;
}

int pooled_count(const nlohmann::json& counts) {
  int n = 0;
  if (counts.is_array()) {
    for (const auto& c : counts) n += c.is_number_integer() ? c.get<int>() : 0;
  }
  return n;
}

}  // namespace

const char* trial_row_status_name(TrialRowStatus s) {
  switch (s) {
    case TrialRowStatus::kOk:
      return "ok";
    case TrialRowStatus::kNoVicon:
      return "no Vicon";
    case TrialRowStatus::kFailed:
      return "failed";
    case TrialRowStatus::kCancelled:
      return "cancelled";
  }
  return "?";
}

TrialRow trial_row(const std::string& subject, const std::string& trial, const nlohmann::json& summary,
                   const std::string& error, bool cancelled) {
  TrialRow row;
  row.subject = subject;
  row.trial = trial;
  const TrialTag tag = parse_trial_tag(trial);
  row.layout = tag.layout;
  row.pose = tag.pose;
  row.motion = tag.motion;
  row.finger_length_diff_mm = row.rom_abs_diff_deg = row.lag_ms = kNaN;
  if (cancelled || !summary.is_object()) {
    row.status = cancelled ? TrialRowStatus::kCancelled : TrialRowStatus::kFailed;
    row.error = error;
    return row;
  }
  row.method = summary.value("method", "");
  row.warnings =
      summary.contains("warnings") && summary["warnings"].is_array() ? static_cast<int>(summary["warnings"].size()) : 0;
  row.seconds = summary.value("frames", 0) / 100.0;
  if (summary.contains("visibility") && summary["visibility"].is_array()) {
    for (const auto& d : summary["visibility"]) {
      const int seen = pooled_count(d.value("visible", nlohmann::json()));
      const int reported = seen + pooled_count(d.value("hidden", nlohmann::json()));
      row.visibility_rate.push_back(reported > 0 ? static_cast<double>(seen) / reported : kNaN);
    }
  }
  if (!summary.contains("comparison") || !summary["comparison"].is_object()) {
    row.status = TrialRowStatus::kNoVicon;
    return row;
  }
  const auto& c = summary["comparison"];
  row.finger_length_diff_mm = mean_of(c.value("finger_mean_diff_mm", nlohmann::json()), false);
  row.rom_abs_diff_deg = mean_of(c.value("rom_diff_deg", nlohmann::json()), true);
  if (c.contains("lag") && c["lag"].value("clear", false)) row.lag_ms = summary_number_or_nan(c["lag"]["ms"]);
  return row;
}

}  // namespace lmc
