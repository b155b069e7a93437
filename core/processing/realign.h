#pragma once
// Stage 2 (docs/algorithms/frames.md, docs/algorithms/processing.md): each device's points from its own frame into the
// world frame with the trial's layout: p = R·p_d + t, then + offset. Recording device id k uses the
// layout's k-th device (LMC1 = first). The palm normal and direction are directions, so they are
// only rotated (the study's script pushed them through the full transform as if they were
// points; no published measure uses them, so the published numbers are unaffected).
#include <span>
#include <string>

#include "core/hand/hand_track.h"
#include "core/layout/layout.h"

namespace lmc {

// Throws lmc::Error when a device id has no device in the layout, naming both counts.
void realign_to_world(GridTrial& grid, const Layout& layout, const std::string& layout_source = "layout");

// Frame by frame, one device (exposed for the workbench and tests).
void realign_track(HandTrack& track, const LayoutDevice& device);

// The per-frame math behind both (shared with the online fuser, online_fusion.h): one frame's 30
// entries in place, points p ← R·p + shift, the palm normal and direction p ← R·p. `rotation` =
// device.pose.rotation(), `shift` = device.pose.translation() + device.offset_mm.
void realign_frame(std::span<Vec3, kNumHandPoints> points, const Eigen::Matrix3d& rotation,
                   const Eigen::Vector3d& shift);

}  // namespace lmc
