#include "devices/session_runner/preflight.h"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>

#include "devices/vicon/vicon_trigger.h"

namespace fs = std::filesystem;

namespace lmc::devices {
namespace {

std::string one_decimal(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

std::string human_bytes(std::uint64_t bytes) {
  const double mb = static_cast<double>(bytes) / (1024.0 * 1024.0);
  if (mb >= 1024) return one_decimal(mb / 1024) + " GB";
  return one_decimal(mb) + " MB";
}

PreflightItem slot_item(const SlotProbe& p, double min_rate_hz) {
  PreflightItem item;
  item.check = p.slot + " streams";
  if (p.frames == 0 || p.serial.empty()) {
    item.detail = "no controller streams in this slot";
    if (!p.bound_serial.empty()) item.detail += " (its bound serial is " + p.bound_serial + ")";
    return item;
  }
  if (!p.bound_serial.empty() && p.serial != p.bound_serial) {
    item.detail = p.serial + " streams here, but the layout binds " + p.bound_serial + " to " + p.slot;
    return item;
  }
  if (p.rate_hz < min_rate_hz) {
    item.detail = p.serial + " at " + one_decimal(p.rate_hz) + " Hz, below the " + one_decimal(min_rate_hz) +
                  " Hz minimum (USB bandwidth? tracking mode?)";
    return item;
  }
  item.ok = true;
  item.detail = p.serial + " at " + one_decimal(p.rate_hz) + " Hz";
  return item;
}

PreflightItem vicon_item(const std::string& target) {
  PreflightItem item;
  item.check = "Vicon target";
  try {
    ViconTriggerConfig config = parse_vicon_target(target);
    // Resolving the host and opening the socket is all a UDP trigger can check before sending;
    // nothing is sent, so no capture starts.
    ViconTrigger trigger(config);
    item.ok = true;
    item.detail = trigger.target() + " resolves";
  } catch (const std::exception& e) {
    item.detail = std::string("cannot reach ") + target + ": " + e.what();
  }
  return item;
}

PreflightItem folder_item(const fs::path& folder) {
  PreflightItem item;
  item.check = "folder writable";
  const fs::path probe = folder / ".preflight-write-test";
  {
    std::ofstream out(probe, std::ios::binary | std::ios::trunc);
    out << "lmc preflight\n";
    out.flush();
    if (!out) {
      item.detail = "cannot write in " + folder.string();
      return item;
    }
  }
  std::error_code ec;
  fs::remove(probe, ec);
  item.ok = true;
  item.detail = folder.string();
  return item;
}

PreflightItem disk_item(const fs::path& folder, std::uint64_t needed, double margin) {
  PreflightItem item;
  item.check = "disk space";
  std::error_code ec;
  const fs::space_info space = fs::space(folder, ec);
  if (ec) {
    item.detail = "cannot tell the free space of " + folder.string() + ": " + ec.message();
    return item;
  }
  const auto wanted = static_cast<std::uint64_t>(static_cast<double>(needed) * margin);
  item.ok = space.available >= wanted;
  item.detail = human_bytes(space.available) + " free; the rest of the session needs about " + human_bytes(needed);
  if (!item.ok) item.detail += " and " + one_decimal(margin) + "× that is wanted";
  return item;
}

}  // namespace

bool PreflightReport::ok() const {
  for (const auto& i : items)
    if (!i.ok) return false;
  return true;
}

std::vector<std::string> PreflightReport::failures() const {
  std::vector<std::string> out;
  for (const auto& i : items)
    if (!i.ok) out.push_back(i.check + ": " + i.detail);
  return out;
}

nlohmann::json preflight_to_json(const PreflightReport& report) {
  nlohmann::json items = nlohmann::json::array();
  for (const auto& i : report.items) items.push_back({{"check", i.check}, {"ok", i.ok}, {"detail", i.detail}});
  return {{"block", report.block}, {"layout", report.layout_name}, {"ok", report.ok()}, {"items", items}};
}

PreflightReport evaluate_preflight(const PreflightInputs& in) {
  PreflightReport r;
  r.block = in.block;
  r.layout_name = in.layout.name;
  for (const auto& p : in.slots) r.items.push_back(slot_item(p, in.min_rate_hz));
  if (in.vicon_target) r.items.push_back(vicon_item(*in.vicon_target));
  r.items.push_back(folder_item(in.folder));
  r.items.push_back(disk_item(in.folder, in.bytes_needed, in.disk_margin));
  return r;
}

std::uint64_t estimated_trial_bytes(int devices, double seconds) {
  // 30 points × ~3 × 10 characters ≈ 0.95 KB a row with a hand; 120 Hz is the fastest a controller runs.
  constexpr double kBytesPerRow = 1024.0;
  constexpr double kMaxRateHz = 120.0;
  return static_cast<std::uint64_t>(kBytesPerRow * kMaxRateHz * devices * seconds) + 64 * 1024;
}

}  // namespace lmc::devices
