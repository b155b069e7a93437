#pragma once
// One line of the Review tab's trial table, read from a processed trial's summary
// (trial_summary.h): what it is (subject, layout, pose, motion, method), whether it worked, and the
// headline numbers a researcher sorts by — how much each controller saw, how far the fingers and
// the ranges of motion are from Vicon, and the LMC–Vicon lag. NaN means "not known" (no Vicon, the
// controller never saw the hand, no clear lag) and is shown as such, never as 0.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lmc {

enum class TrialRowStatus { kOk, kNoVicon, kFailed, kCancelled };
const char* trial_row_status_name(TrialRowStatus s);  // "ok", "no Vicon", "failed", "cancelled"

struct TrialRow {
  std::string subject;  // the folder the trial came from
  std::string trial;
  std::string layout = "unknown", pose = "unknown", motion = "unknown";
  std::string method;
  TrialRowStatus status = TrialRowStatus::kOk;
  std::string error;  // failed: why
  int warnings = 0;
  double seconds = 0;  // processed length
  // Per controller (LMC1…): fingers seen by ray tracing over fingers reported, pooled over the five
  // fingers; NaN when the controller never reported the hand.
  std::vector<double> visibility_rate;
  double finger_length_diff_mm = 0;  // mean over fingers of (LMC − Vicon) per-trial mean length
  double rom_abs_diff_deg = 0;       // mean over the six joints of |ROM LMC − ROM Vicon|
  double lag_ms = 0;                 // NaN unless the lag estimate is clear
};

// `summary` as trial_summary_json writes it (null when the trial failed: `error` then says why).
TrialRow trial_row(const std::string& subject, const std::string& trial, const nlohmann::json& summary,
                   const std::string& error, bool cancelled = false);

}  // namespace lmc
