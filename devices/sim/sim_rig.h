#pragma once
// The simulated rig in simulated time, without threads: a truth hand moves through a
// motion; each controller of the layout reports what a real one would (sim_config.h). next()
// yields the rig's events in time order forever; generate_sim_trial() collects a whole trial
// deterministically, far faster than real time (recorder tests, `lmc record --fast`, simulated
// sessions with known truth for processing). SimSource (sim_source.h) plays a rig live.
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "core/hand/hand_model.h"
#include "core/hand/pose_set.h"
#include "core/io/trc.h"
#include "core/layout/layout.h"
#include "core/visibility/device_view.h"
#include "core/visibility/visibility_params.h"
#include "devices/frame_source.h"
#include "devices/sim/sim_config.h"
#include "devices/sim/truth_markers.h"

namespace lmc::devices {

struct SimEvent {
  double time_s = 0;  // simulated host time since the rig started
  bool is_frame = true;
  SourceFrame frame;  // is_frame; host_receive_ns = time in ns since start
  DeviceEvent event;  // !is_frame
};

class SimRig {
 public:
  SimRig(Layout layout, SimConfig config);
  ~SimRig();
  SimRig(const SimRig&) = delete;
  SimRig& operator=(const SimRig&) = delete;

  const Layout& layout() const { return layout_; }
  const SimConfig& config() const { return config_; }
  // One per layout slot, in slot order; serials "<prefix>-<slot>-<seed-derived digits>".
  const std::vector<DeviceInfo>& devices() const { return infos_; }
  // Calibration error c of device i (see sim_config.h): the offset processing must apply.
  Eigen::Vector3d calibration_error(int device) const;
  // Where device i really stands: p_world = R·p_device + t with the rotation error included
  // (sim_config.h); with no rotation error R is the layout's and t = pose + calibration_error.
  Eigen::Isometry3d true_device_to_world(int device) const;
  // The noise σ (mm per axis) device i adds: its model's or the configured one (sim_noise_sigma_mm).
  double noise_sigma_mm(int device) const;

  // A trial's countdown: the hand holds its start pose (it still sways) for `seconds` before its
  // motion begins, and unplug times count from then, so a simulated trial starts as a real one
  // does when the subject is told to go. Call before the first next().
  void hold_start_pose(double seconds) { hold_s_ = std::max(0.0, seconds); }
  double hold_s() const { return hold_s_; }

  SimEvent next();
  // The truth hand (world frame, consistent with the marker mapping) at time t.
  HandFrame truth_at(double t_s) const;
  const TruthMarkerMap& marker_map() const { return *marker_map_; }

 private:
  struct Device;
  HandFrame device_frame(Device& d, double t_s);

  Layout layout_;
  SimConfig config_;
  std::vector<DeviceInfo> infos_;
  std::vector<std::unique_ptr<Device>> devices_;
  HandModel model_;
  HandPlacement placement_;
  std::optional<PoseSet> pose_set_;
  std::unique_ptr<TruthMarkerMap> marker_map_;
  std::array<std::array<Vec3, kJointsPerDigit>, kNumDigits> neutral_local_{};
  std::array<double, 6> sway_phase_{};
  std::vector<VisibilityLimits> visibility_;  // per device, layout order
  std::optional<HandFrame> still_truth_;      // static motion without sway: the truth never changes
  size_t announced_ = 0;
  double hold_s_ = 0;
};

struct SimTrial {
  std::vector<DeviceInfo> devices;
  std::vector<SimEvent> events;  // frames and device events, in time order
  std::vector<HandFrame> truth;  // world frame at config.truth_rate_hz, from t = 0
  double truth_rate_hz = 100.0;
  TrcData truth_trc;
  // Frames per serial.
  std::vector<std::pair<std::string, std::int64_t>> frame_counts() const;
};

SimTrial generate_sim_trial(const Layout& layout, const SimConfig& config, double seconds);

}  // namespace lmc::devices
