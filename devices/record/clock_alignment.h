#pragma once
// Lines an LMC recording up with a Vicon capture: at the instant the Vicon
// CaptureStart leaves (or arrives), every device's latest frame says which device timestamp
// (µs, the device's own clock) belongs to that host instant. Processing later maps TRC time 0
// (CaptureStart + Delay) to each device's clock with it. Key list: devices/README.md.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "devices/device_hub.h"

namespace lmc::devices {

// `event`: "CaptureStart sent" / "CaptureStart received"; `host_ns`: host_now_ns() of that event.
// Per assigned device: its latest frame's timestamp, frame id and host receive time, and the
// device clock at `host_ns`: the clock as its source read it at the snapshot (DeviceStatus::
// device_clock_us, carried to `host_ns` on the host clock; "device_clock_method": "read"), or,
// when the source has no clock to read, the latest timestamp + host time elapsed since that frame
// arrived ("extrapolated": early by the frame's capture-to-delivery latency).
nlohmann::json clock_alignment_json(const HubSnapshot& snapshot, const std::string& event, std::int64_t host_ns,
                                    std::int64_t packet_id, const std::string& host_time_utc);

}  // namespace lmc::devices
