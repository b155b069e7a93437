#include "devices/record/clock_alignment.h"

#include <cmath>

namespace lmc::devices {
namespace {

std::int64_t ns_to_us(std::int64_t ns) {
  return static_cast<std::int64_t>(std::llround(static_cast<double>(ns) / 1000.0));
}

// The device clock at the event, best first: read from the clock itself at the snapshot (exact
// up to the host time between snapshot and event), else extrapolated from the latest frame
// (early by that frame's capture-to-delivery latency). With both, the difference between them
// at the latest frame's arrival is that latency, kept so the sidecar shows what the old estimate
// would have missed.
void device_clock_at_event(const HubSnapshot& snapshot, const DeviceStatus& d, std::int64_t host_ns,
                           nlohmann::json& e) {
  const bool have_frame = d.latest && d.frames_received > 0 && d.latest_host_receive_ns != 0;
  std::optional<std::int64_t> extrapolated;
  if (have_frame) extrapolated = d.latest->timestamp_us + ns_to_us(host_ns - d.latest_host_receive_ns);
  if (d.device_clock_us) {
    e["device_clock_at_event_us"] = *d.device_clock_us + ns_to_us(host_ns - snapshot.host_time_ns);
    e["device_clock_method"] = "read";
    // Half the host interval the clock was read in: the read's own error, apart from the latency.
    e["device_clock_uncertainty_us"] =
        d.device_clock_uncertainty_us ? nlohmann::json(*d.device_clock_uncertainty_us) : nlohmann::json(nullptr);
    e["device_clock_extrapolated_us"] = extrapolated ? nlohmann::json(*extrapolated) : nlohmann::json(nullptr);
    e["latest_frame_latency_us"] =
        have_frame ? nlohmann::json(*d.device_clock_us - ns_to_us(snapshot.host_time_ns - d.latest_host_receive_ns) -
                                    d.latest->timestamp_us)
                   : nlohmann::json(nullptr);
  } else {
    e["device_clock_at_event_us"] = extrapolated ? nlohmann::json(*extrapolated) : nlohmann::json(nullptr);
    e["device_clock_method"] = extrapolated ? nlohmann::json("extrapolated") : nlohmann::json(nullptr);
  }
}

}  // namespace

nlohmann::json clock_alignment_json(const HubSnapshot& snapshot, const std::string& event, std::int64_t host_ns,
                                    std::int64_t packet_id, const std::string& host_time_utc) {
  nlohmann::json devices = nlohmann::json::array();
  for (const auto& d : snapshot.devices) {
    if (d.slot_index < 0) continue;  // unassigned devices are not recorded
    nlohmann::json e = {{"device_id", d.slot_index + 1}, {"slot", d.slot}, {"serial", d.serial}};
    if (d.latest && d.frames_received > 0 && d.latest_host_receive_ns != 0) {
      e["latest_frame_id"] = d.latest->frame_id;
      e["latest_timestamp_us"] = d.latest->timestamp_us;
      e["latest_host_receive_ns"] = d.latest_host_receive_ns;
      e["host_ns_since_latest"] = host_ns - d.latest_host_receive_ns;
    } else {
      e["latest_frame_id"] = nullptr;
      e["latest_timestamp_us"] = nullptr;
      e["latest_host_receive_ns"] = nullptr;
      e["host_ns_since_latest"] = nullptr;
    }
    device_clock_at_event(snapshot, d, host_ns, e);
    devices.push_back(std::move(e));
  }
  return {{"event", event},
          {"packet_id", packet_id},
          {"host_ns", host_ns},
          {"host_time_utc", host_time_utc},
          {"devices", devices}};
}

}  // namespace lmc::devices
