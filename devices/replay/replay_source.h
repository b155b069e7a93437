#pragma once
// Replays a recorded file (the study's raw format or ours) as live devices, keeping each
// device's timing: rows are delivered in device-timestamp order, at `speed` × real time (0: as
// fast as possible). Serials come from our session sidecar when one sits beside the file
// (LMC_<trial>.session.json), else "REPLAY-LMC<n>" for device id n.
#include <atomic>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "core/io/lmc_recording.h"
#include "devices/frame_source.h"

namespace lmc::devices {

struct ReplayOptions {
  double speed = 1.0;
  bool loop = false;
};

class ReplaySource final : public FrameSource {
 public:
  // Reads the file now; throws lmc::Error (file, line, column) when it is malformed.
  explicit ReplaySource(const std::filesystem::path& path, ReplayOptions options = {});
  ~ReplaySource() override;

  std::string backend_name() const override { return "replay"; }
  void start(FrameSink& sink) override;
  void stop() override;
  bool realtime() const override { return options_.speed > 0; }
  bool finished() const override { return finished_.load(); }

  const std::vector<DeviceInfo>& devices() const { return devices_; }
  size_t row_count() const { return rows_.size(); }
  double duration_s() const;

 private:
  void run(FrameSink& sink);
  std::filesystem::path path_;
  ReplayOptions options_;
  std::vector<HandFrame> rows_;  // sorted by timestamp (stable: per-device order kept)
  std::vector<DeviceInfo> devices_;
  std::vector<std::string> serial_of_id_;  // index = device id
  std::atomic<bool> stop_{false};
  std::atomic<bool> finished_{false};
  std::thread thread_;
};

}  // namespace lmc::devices
