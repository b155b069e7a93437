#include "devices/record/clock_alignment.h"

#include <cmath>

namespace lmc::devices {

nlohmann::json clock_alignment_json(const HubSnapshot& snapshot, const std::string& event, std::int64_t host_ns,
                                    std::int64_t packet_id, const std::string& host_time_utc) {
  nlohmann::json devices = nlohmann::json::array();
  for (const auto& d : snapshot.devices) {
    if (d.slot_index < 0) continue;  // unassigned devices are not recorded
    nlohmann::json e = {{"device_id", d.slot_index + 1}, {"slot", d.slot}, {"serial", d.serial}};
    if (d.latest && d.frames_received > 0 && d.latest_host_receive_ns != 0) {
      const std::int64_t since_ns = host_ns - d.latest_host_receive_ns;
      e["latest_frame_id"] = d.latest->frame_id;
      e["latest_timestamp_us"] = d.latest->timestamp_us;
      e["latest_host_receive_ns"] = d.latest_host_receive_ns;
      e["host_ns_since_latest"] = since_ns;
      e["device_clock_at_event_us"] =
          d.latest->timestamp_us + static_cast<std::int64_t>(std::llround(static_cast<double>(since_ns) / 1000.0));
    } else {
      e["latest_frame_id"] = nullptr;
      e["latest_timestamp_us"] = nullptr;
      e["latest_host_receive_ns"] = nullptr;
      e["host_ns_since_latest"] = nullptr;
      e["device_clock_at_event_us"] = nullptr;
    }
    devices.push_back(std::move(e));
  }
  return {{"event", event},
          {"packet_id", packet_id},
          {"host_ns", host_ns},
          {"host_time_utc", host_time_utc},
          {"devices", devices}};
}

}  // namespace lmc::devices
