#pragma once
// What the simulator's tests share: the paper's initial layout, a simulator with every error
// source off, so that a controller's realigned frame is exactly the hand it models, and a hash of a
// whole trial for tests that pin the simulator's output bit for bit.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "core/io/layout_json.h"
#include "devices/sim/sim_config.h"
#include "devices/sim/sim_rig.h"
#include "tests/support/reference_data.h"

namespace lmc::devices::sim_fixtures {

inline Layout paper_initial() {
  return load_layout(test::asset_file("layouts/paper-initial.json"));
}

inline SimConfig exact() {
  SimConfig c;
  c.noise = false;
  c.elbow_error = false;
  c.axis_cut = false;
  c.occlusion = false;
  return c;
}

// FNV-1a over every frame's timing and coordinates, bit for bit.
inline std::uint64_t trial_hash(const SimTrial& t) {
  std::uint64_t h = 1469598103934665603ULL;
  auto add = [&h](const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ULL;
  };
  for (const auto& e : t.events) {
    add(&e.time_s, sizeof e.time_s);
    if (!e.is_frame) continue;
    add(&e.frame.host_receive_ns, sizeof e.frame.host_receive_ns);
    add(&e.frame.frame.timestamp_us, sizeof e.frame.frame.timestamp_us);
    for (const Vec3& p : e.frame.frame.points) add(p.data(), 3 * sizeof(double));
  }
  return h;
}

// The same over every value rounded (times to the nanosecond, coordinates to 0.1 µm): equal on
// every system. The simulator's noise and motion go through sin and cos, whose last bit differs
// between C libraries (glibc's and MinGW-w64's), so its trials agree between Linux and Windows to
// about 1e-12 mm, not to the bit.
inline std::uint64_t trial_hash_rounded(const SimTrial& t) {
  std::uint64_t h = 1469598103934665603ULL;
  auto add = [&h](std::int64_t v) {
    for (int i = 0; i < 8; ++i)
      h = (h ^ static_cast<unsigned char>(static_cast<std::uint64_t>(v) >> (8 * i))) * 1099511628211ULL;
  };
  for (const auto& e : t.events) {
    add(std::llround(e.time_s * 1e9));
    if (!e.is_frame) continue;
    add(e.frame.host_receive_ns);
    add(e.frame.frame.timestamp_us);
    for (const Vec3& p : e.frame.frame.points)
      for (int k = 0; k < 3; ++k) add(std::llround(p[k] * 1e4));
  }
  return h;
}

}  // namespace lmc::devices::sim_fixtures
