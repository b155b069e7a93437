#include "core/export/bids_trial_sidecar.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "core/export/bids_dataset_files.h"
#include "core/export/bids_names.h"

namespace lmc {
namespace bids_sidecar_detail {  // named: core compiles in unity batches

std::string software_line(const RecorderSidecar* sidecar) {
  std::string s;
  if (sidecar != nullptr && !sidecar->software_name.empty()) {
    s = "recorded with " + sidecar->software_name + " " + sidecar->software_version + " (" + sidecar->backend +
        " backend); ";
  }
  return s + "processed with lmc-workbench " LMC_VERSION;
}

std::optional<std::int64_t> json_int(const nlohmann::json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<std::int64_t>();
}

// The recorder keeps no model name; a newer sidecar's device entry may carry one.
std::string controller_model(const RecorderSidecar* sidecar, int device_id) {
  if (sidecar == nullptr) return "Leap Motion Controller";
  if (const SidecarDevice* d = sidecar->device(device_id);
      d != nullptr && d->unknown.contains("model") && d->unknown["model"].is_string()) {
    return d->unknown["model"].get<std::string>();
  }
  return sidecar->backend == "sim" ? "simulated Leap Motion Controller" : "Leap Motion Controller";
}

}  // namespace bids_sidecar_detail

BidsMotionInfo bids_motion_info(const BidsTrialPlan& t, const BidsTrackingSystem& system,
                                const RecorderSidecar* sidecar, FusionMethod method_used) {
  using namespace bids_sidecar_detail;
  BidsMotionInfo info;
  info.task_name = t.motion;
  info.task_description = t.operator_cue;
  info.instructions = t.subject_cue;
  info.software_versions = software_line(sidecar);
  const std::string method = fusion_method_name(method_used);
  if (system.name == kBidsViconTracksys) {
    info.manufacturer = "Vicon";
    info.tracking_system_name = "Vicon markers of the trial's " +
                                (t.job.vicon ? t.job.vicon->filename().string() : std::string("Vicon file")) +
                                ", frame f on the processing grid's frame f";
    if (sidecar != nullptr && sidecar->backend == "sim") info.model = "simulated (the simulated rig's ground truth)";
    return info;
  }
  info.manufacturer = "Ultraleap";
  if (system.name == kBidsFusedTracksys) {
    info.tracking_system_name = "the hand fused from every controller by lmc-workbench (" + method + " method)";
    info.model = controller_model(sidecar, 1);
    info.software_versions += " (" + method + " fusion)";
    return info;
  }
  info.tracking_system_name = "the Leap Motion Controller in slot " + system.name + ", realigned into the world frame";
  info.model = controller_model(sidecar, system.device_id);
  if (sidecar != nullptr) {
    if (const SidecarDevice* d = sidecar->device(system.device_id)) info.serial = d->serial;
  }
  return info;
}

std::vector<BidsEvent> bids_trial_events(std::int64_t grid_start_us, const RecorderSidecar* sidecar) {
  using bids_sidecar_detail::json_int;
  std::vector<BidsEvent> events;
  if (sidecar == nullptr) return events;
  const double start = static_cast<double>(grid_start_us);
  std::int64_t first = std::numeric_limits<std::int64_t>::max(), last = std::numeric_limits<std::int64_t>::min();
  for (const auto& d : sidecar->devices) {
    if (d.frames_written <= 0) continue;
    first = std::min(first, d.first_timestamp_us);
    last = std::max(last, d.last_timestamp_us);
  }
  const bool rows = first <= last;
  // The file starts at go only when the sidecar has the trial window and the trial reached go.
  const bool has_go = rows && json_int(sidecar->trial_window, "go_host_ns").has_value();
  if (has_go)
    events.push_back({(static_cast<double>(first) - start) * 1e-6, (static_cast<double>(last - first)) * 1e-6, "go"});
  if (rows) events.push_back({(static_cast<double>(last) - start) * 1e-6, 0.0, "stop"});
  std::optional<std::int64_t> vicon;
  if (sidecar->vicon_alignment.is_object() && sidecar->vicon_alignment.contains("devices") &&
      sidecar->vicon_alignment["devices"].is_array()) {
    for (const auto& d : sidecar->vicon_alignment["devices"]) {
      if ((vicon = json_int(d, "device_clock_at_event_us"))) break;
    }
  }
  if (!vicon && sidecar->ground_truth) vicon = sidecar->ground_truth->device_clock_at_time_zero_us;
  if (vicon) events.push_back({(static_cast<double>(*vicon) - start) * 1e-6, 0.0, "vicon_capture_start"});
  std::stable_sort(events.begin(), events.end(),
                   [](const BidsEvent& a, const BidsEvent& b) { return a.onset_s < b.onset_s; });
  return events;
}

std::string bids_trial_acq_time(const RecorderSidecar* sidecar, bool anonymise) {
  if (sidecar == nullptr || anonymise) return {};
  if (sidecar->trial_window.is_object() && sidecar->trial_window.contains("go_host_utc") &&
      sidecar->trial_window["go_host_utc"].is_string()) {
    return bids_acq_time(sidecar->trial_window["go_host_utc"].get<std::string>());
  }
  return bids_acq_time(sidecar->host_start_utc);
}

}  // namespace lmc
