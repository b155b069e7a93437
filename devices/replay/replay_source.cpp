#include "devices/replay/replay_source.h"

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/io/json_checked.h"
#include "devices/host_clock.h"
#include "devices/platform/fine_timer.h"

namespace lmc::devices {
namespace {

// Serial per device id from a sidecar beside the recording, when there is one.
std::vector<std::pair<int, std::string>> sidecar_serials(const std::filesystem::path& recording) {
  std::vector<std::pair<int, std::string>> out;
  std::string name = recording.filename().string();
  const std::string suffix = ".raw.txt";
  if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0) return out;
  const auto sidecar = recording.parent_path() / (name.substr(0, name.size() - suffix.size()) + ".session.json");
  if (!std::filesystem::exists(sidecar)) return out;
  try {
    const nlohmann::json j = read_json_file(sidecar);
    if (j.contains("devices") && j["devices"].is_array())
      for (const auto& d : j["devices"])
        if (d.contains("device_id") && d.contains("serial") && d["serial"].is_string() &&
            !d["serial"].get<std::string>().empty())
          out.emplace_back(d["device_id"].get<int>(), d["serial"].get<std::string>());
  } catch (const std::exception&) {
    // A damaged sidecar must not stop a replay of a readable recording: fall back to ids.
  }
  return out;
}

}  // namespace

ReplaySource::ReplaySource(const std::filesystem::path& path, ReplayOptions options) : path_(path), options_(options) {
  LmcRecording rec = read_lmc_recording(path);
  rows_ = std::move(rec.rows);
  if (rows_.empty()) throw Error(ErrorLocation(path.string()), "recording has no rows to replay");
  std::stable_sort(rows_.begin(), rows_.end(),
                   [](const HandFrame& a, const HandFrame& b) { return a.timestamp_us < b.timestamp_us; });
  int max_id = 0;
  for (const auto& r : rows_) max_id = std::max(max_id, r.device_id);
  serial_of_id_.assign(static_cast<size_t>(max_id) + 1, {});
  for (const auto& [id, serial] : sidecar_serials(path))
    if (id >= 0 && id <= max_id) serial_of_id_[static_cast<size_t>(id)] = serial;
  std::vector<bool> present(static_cast<size_t>(max_id) + 1, false);
  for (const auto& r : rows_) present[static_cast<size_t>(std::max(0, r.device_id))] = true;
  for (int id = 0; id <= max_id; ++id) {
    if (!present[static_cast<size_t>(id)]) continue;
    auto& serial = serial_of_id_[static_cast<size_t>(id)];
    if (serial.empty()) serial = "REPLAY-LMC" + std::to_string(id);
    devices_.push_back({serial, "replay", "replay of " + path.filename().string(), ""});
  }
}

ReplaySource::~ReplaySource() {
  stop();
}

double ReplaySource::duration_s() const {
  return static_cast<double>(rows_.back().timestamp_us - rows_.front().timestamp_us) / 1e6;
}

void ReplaySource::start(FrameSink& sink) {
  if (thread_.joinable()) return;
  stop_ = false;
  thread_ = std::thread([this, &sink] { run(sink); });
}

void ReplaySource::stop() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void ReplaySource::run(FrameSink& sink) {
  const FineTimerResolution fine_sleeps;  // 120 Hz pacing on Windows too
  for (const auto& info : devices_) {
    DeviceEvent e;
    e.kind = DeviceEventKind::kAppeared;
    e.info = info;
    e.host_time_ns = host_now_ns();
    sink.on_device_event(e);
  }
  bool completed = false;
  do {
    const std::int64_t start_ns = host_now_ns();
    const std::int64_t t0 = rows_.front().timestamp_us;
    for (const HandFrame& row : rows_) {
      if (stop_) break;
      if (options_.speed > 0) {
        const auto due =
            start_ns + static_cast<std::int64_t>(static_cast<double>(row.timestamp_us - t0) * 1000.0 / options_.speed);
        for (;;) {
          const std::int64_t now = host_now_ns();
          if (now >= due || stop_) break;
          std::this_thread::sleep_for(std::chrono::nanoseconds(std::min<std::int64_t>(due - now, 20'000'000)));
        }
        if (stop_) break;
      }
      SourceFrame f;
      f.serial = serial_of_id_[static_cast<size_t>(std::max(0, row.device_id))];
      f.frame = row;
      f.host_receive_ns = host_now_ns();
      sink.on_frame(f);
    }
    completed = !stop_;
  } while (options_.loop && !stop_);
  finished_ = completed;
}

}  // namespace lmc::devices
