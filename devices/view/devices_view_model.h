#pragma once
// Non-drawing logic of the workbench's Devices tab (issue #5): it owns a device hub (simulated
// rig by default, or LeapC / replay), turns hub snapshots into table rows and world-frame hands
// for the live view, runs test recordings, and projects 3-D points for the tab's own small
// perspective view. No ImGui here, so tests drive it directly; the tab only draws.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/hand/hand_frame.h"
#include "core/layout/layout.h"
#include "devices/device_hub.h"
#include "devices/record/recorder.h"
#include "devices/source_factory.h"

namespace lmc::devices {

struct DeviceRow {
  std::string serial;
  std::string slot;  // empty: unassigned
  int slot_index = -1;
  std::string backend;
  std::string status;  // "streaming", "no hand", "stalled", "disconnected", "unassigned"
  double rate_hz = 0;
  double age_ms = -1;
  bool hand_present = false;
  std::int64_t frames = 0;
  std::int64_t dropped = 0;
  int colour = 0;  // index into device_colour()
  bool warn = false;
};

// One device's latest hand, realigned into the world frame (pose + offset).
struct LiveHand {
  int colour = 0;
  std::string slot;
  std::array<Vec3, kNumHandPoints> world{};
};

// RGB in 0..1, one distinct colour per slot (LMC1 … LMC8).
std::array<float, 3> device_colour(int index);

// Segments of the hand skeleton to draw, as pairs of HandFrame point indices.
const std::vector<std::pair<int, int>>& hand_bones();

// A small orbiting perspective camera looking at a target; project() maps world (mm) to pixels in
// a viewport, or nullopt behind the camera.
struct ViewCamera {
  Eigen::Vector3d target{0, 110, 40};
  double yaw_deg = 35;    // about world y; 0 = looking from +z (the subject's side)
  double pitch_deg = 30;  // above the table
  double distance_mm = 560;
  double fov_y_deg = 45;
  Eigen::Vector3d eye() const;
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world, double x0, double y0, double width,
                                         double height) const;
};

class DevicesViewModel {
 public:
  explicit DevicesViewModel(Layout layout);
  ~DevicesViewModel();

  const Layout& layout() const { return layout_; }
  void set_layout(Layout layout);  // stops a running backend first
  // Starts a backend ("sim", "leapc", "replay:FILE"); stops the previous one. Returns an error
  // text (empty when fine).
  std::string start(const std::string& backend, const SimConfig& sim = {});
  void stop();
  bool running() const { return hub_ != nullptr; }
  const std::string& backend() const { return backend_; }
  double running_seconds() const;

  // Pulls a fresh snapshot (call once per UI frame).
  void refresh();
  const std::vector<DeviceRow>& rows() const { return rows_; }
  const std::vector<LiveHand>& hands() const { return hands_; }
  const std::vector<std::string>& messages() const { return messages_; }
  std::vector<std::string> slot_choices() const;
  std::string assign(const std::string& serial, const std::string& slot);
  // True once every layout slot has streamed for at least a second (rates are meaningful).
  bool all_streaming() const;

  // Test recording into `dir` (trial name checked). Never overwrites: when `trial` has files in
  // `dir` the next free name (trial-2, trial-3, …; trial_name.h) is used, see recording_trial().
  // Errors come back as text.
  std::string start_recording(const std::filesystem::path& dir, const std::string& trial);
  // The name the current (or last) test recording got.
  const std::string& recording_trial() const { return recording_trial_; }
  // Stops; returns a one-line summary (or the error).
  std::string stop_recording();
  bool recording() const { return recorder_ != nullptr; }
  std::optional<RecorderStatus> recording_status() const;

 private:
  Layout layout_;
  std::unique_ptr<DeviceHub> hub_;
  std::unique_ptr<Recorder> recorder_;
  std::string backend_;
  std::string recording_trial_;
  std::int64_t started_ns_ = 0;
  std::vector<DeviceRow> rows_;
  std::vector<LiveHand> hands_;
  std::vector<std::string> messages_;
  bool all_streaming_ = false;
};

}  // namespace lmc::devices
