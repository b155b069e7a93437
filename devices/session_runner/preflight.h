#pragma once
// The checklist before the first trial of a session and after every layout change:
// every slot of the block's layout streams from its bound controller (or a simulated one) above
// a minimum rate, the Vicon target resolves, the folder is writable and its disk holds the rest
// of the session several times over. Each line is green or red with a reason in plain words; the
// operator may override a red list, and the runner journals both.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/layout/layout.h"

namespace lmc::devices {

struct PreflightItem {
  std::string check;  // "LMC1 streams", "Vicon target", "disk space", "folder writable"
  bool ok = false;
  std::string detail;  // what was found, e.g. "SIM-1 at 23 Hz" or "no controller in this slot"
};

struct PreflightReport {
  std::string block;  // the layout key of the block it was run for
  std::string layout_name;
  std::vector<PreflightItem> items;
  bool ok() const;
  std::vector<std::string> failures() const;  // "<check>: <detail>" of the red lines
};

nlohmann::json preflight_to_json(const PreflightReport& report);

// What the controllers did while the probe listened, per layout slot (slot order).
struct SlotProbe {
  std::string slot;
  std::string serial;        // the device that streamed in this slot ("" when none)
  std::string bound_serial;  // the layout's serial for the slot ("" when not bound)
  std::int64_t frames = 0;
  double rate_hz = 0;  // from the device timestamps of the frames seen
};

struct PreflightInputs {
  std::string block;
  Layout layout;
  std::vector<SlotProbe> slots;
  double min_rate_hz = 5;
  std::optional<std::string> vicon_target;  // "HOST[:PORT]" when the session triggers Vicon
  std::filesystem::path folder;
  std::uint64_t bytes_needed = 0;  // the rest of the session's recordings, estimated
  double disk_margin = 3.0;        // "several times over"
};

// Runs the non-device checks (Vicon, disk, folder) and turns the probe into lines.
PreflightReport evaluate_preflight(const PreflightInputs& in);

// Bytes a trial of `seconds` from `devices` controllers writes, generously (≈1 KB a row at the
// study's highest rate), so a disk check errs on the safe side.
std::uint64_t estimated_trial_bytes(int devices, double seconds);

}  // namespace lmc::devices
