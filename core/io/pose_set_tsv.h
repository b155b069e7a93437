#pragma once
// Pose-set files (`lmc poses -o poses.tsv`; read by every command that takes --poses).
// Tab-separated text, UTF-8, '\n' line ends:
//   line 1: "# lmc-poses 1" (format tag and version)
//   lines starting with '#' after it, before the header: comments; "# description: <text>"
//           carries PoseSet::description, each "# provenance: <text>" one line of
//           PoseSet::provenance (in order); other comments are ignored
//   header: "frame\torientation\tmotion\tprogress\t" then the 30 points × x/y/z as
//           "<hand point name>.x" … (names as in the study's headers, hand_frame.h)
//   one row per frame: index (0-based), "horizontal"|"vertical", "open"|"index"|"thumb"|
//           "wrist-flexion"|"wrist-extension", progress, then 90 numbers (mm, world frame;
//           palm normal/direction are unit vectors) in the shortest form that reads back
//           as the same double (std::to_chars), so reading back gives the same numbers.
#include <filesystem>
#include <iosfwd>
#include <string>

#include "core/hand/pose_set.h"

namespace lmc {

void write_pose_set(std::ostream& out, const PoseSet& set);
// Atomic (temporary file + rename).
void save_pose_set(const std::filesystem::path& path, const PoseSet& set);

// Throws lmc::Error naming the file, line and column of the first problem.
PoseSet parse_pose_set(std::istream& in, const std::string& source_name);
PoseSet load_pose_set(const std::filesystem::path& path);

}  // namespace lmc
