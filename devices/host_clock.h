#pragma once
// The host's monotonic clock in nanoseconds; every "host receive time" uses it so rates and frame
// ages compare across threads. Wall-clock times (for sidecars) come from utc_now_iso8601().
#include <cstdint>
#include <functional>
#include <string>

#include "core/common/utc_time.h"  // utc_now_iso8601, shared with core

namespace lmc::devices {

std::int64_t host_now_ns();

// Injectable clock (tests and simulated time pass their own).
using HostClock = std::function<std::int64_t()>;

}  // namespace lmc::devices
