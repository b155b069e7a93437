#include "ui/model/devices/devices_state.h"

#include <algorithm>
#include <exception>
#include <utility>

#include "core/io/layout_json.h"
#include "devices/leapc/leapc_library.h"
#include "devices/source_factory.h"

namespace lmc::ui {

DevicesState::DevicesState(LiveRig& rig, CurrentLayout& layout, StatusFn status)
    : layout_(layout), status_(std::move(status)), view_(rig), calibration_(rig) {}

bool DevicesState::leapc_available() {
  // Looked for now, not at build time: a library installed since the last look is found.
  return devices::find_leapc().library != nullptr;
}

void DevicesState::update() {
  view_.refresh();
  // Layout restarts and trial outcomes reach the status bar whichever tab started them.
  const auto& log = view_.messages();
  const std::uint64_t fresh = std::min<std::uint64_t>(view_.rig().messages_total() - seen_messages_, log.size());
  for (size_t i = log.size() - static_cast<size_t>(fresh); i < log.size(); ++i) {
    if (log[i].rfind("layout changed", 0) == 0) report("Devices: " + log[i], false);
  }
  seen_messages_ = view_.rig().messages_total();
  calibration_.update();
  calibration_.notice_layout(layout_.editor() != nullptr ? layout_.editor()->committed() : layout_.get());
  if (calibration_.message() != last_calibration_message_) {
    last_calibration_message_ = calibration_.message();
    if (!last_calibration_message_.empty())
      report_calibration(last_calibration_message_, calibration_.message_is_error());
  }
  ghosts_ = calibration_.ghosts();
  if (const std::string summary = view_.take_recording_summary(); !summary.empty()) {
    // "trial NAME completed|interrupted|aborted|failed…": only the last two are errors.
    const bool ok =
        summary.find(" completed") != std::string::npos || summary.find(" interrupted") != std::string::npos;
    report(summary, !ok);
  }
  if (!view_.running()) return;
  // With Ultraleap's library installed, LeapC is tried first; without controllers the simulated rig
  // takes over.
  if (fallback_pending_ && view_.running_seconds() > 3.0) {
    fallback_pending_ = false;
    if (view_.rows().empty()) {
      report("no controller found: running the simulated rig", false);
      start("sim");
    }
  }
}

void DevicesState::auto_start() {
  if (auto_started_) return;
  auto_started_ = true;
  if (leapc_available()) {
    fallback_pending_ = true;
    start("leapc");
  } else {
    report("no LeapC library installed: running the simulated rig (Start with leapc says where it looked)", false);
    start("sim");
  }
}

std::string DevicesState::start(const std::string& backend, const devices::SimConfig& sim) {
  auto_started_ = true;  // a start by hand (or for a picture) replaces the automatic one
  const std::string err = view_.start(backend, sim);
  if (!err.empty())
    report("Devices: " + err, true);
  else if (showing_error_)
    report("Devices: started " + backend + " with layout '" + view_.layout().name + "'", false);
  return err;
}

void DevicesState::assign(const std::string& serial, const std::string& slot) {
  const std::string err = view_.assign(serial, slot);
  report(err.empty() ? serial + " → " + slot : err, !err.empty());
}

void DevicesState::save_layout_with_serials(const std::filesystem::path& file) {
  try {
    save_layout(view_.layout(), file);
    report("Saved " + file.string() + " with the serial of every assigned controller", false);
  } catch (const std::exception& e) {
    report(e.what(), true);
  }
}

void DevicesState::start_recording(const std::filesystem::path& dir, const std::string& trial, double seconds) {
  const std::string err = view_.start_recording(dir, trial, seconds);
  if (err.empty())
    report("recording " + view_.recording_trial(), false);
  else
    report(err, true);
}

void DevicesState::undo_calibration() {
  if (calibration_.undo_apply(layout_.editor())) return;
  if (calibration_.stage() == CalibrationStage::kApplied) {
    report_calibration("the layout's last change is not the calibration: undo it in the Layout tab", true);
  }
}

}  // namespace lmc::ui
