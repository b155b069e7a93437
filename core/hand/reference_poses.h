#pragma once
// The study's ten reference hand poses (paper, "LMC Placement Optimization";
// docs/algorithms/hand-points.md): five motions — open hand, index flexion, thumb flexion, wrist flexion, wrist
// extension — each with the palm facing down ("horizontal") and facing the subject's left, thumb up
// ("vertical"). The hand is about 150 mm above the table centre, the forearm comes from the subject
// (elbow at +z) and the fingers point away (−z).
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "core/hand/hand_model.h"

namespace lmc {

enum class HandOrientation : int { kHorizontal = 0, kVertical = 1 };
inline constexpr int kNumHandOrientations = 2;

// A trial motion. kOpen is the static open hand; the others move from the open hand (progress 0)
// to full flexion / extension (progress 1).
enum class HandMotion : int { kOpen = 0, kIndexFlexion = 1, kThumbFlexion = 2, kWristFlexion = 3, kWristExtension = 4 };
inline constexpr int kNumHandMotions = 5;
inline constexpr int kNumReferencePoses = kNumHandOrientations * kNumHandMotions;

std::string_view orientation_name(HandOrientation o);  // "horizontal", "vertical"
std::string_view motion_name(HandMotion m);            // "open", "index", "thumb", "wrist-flexion", "wrist-extension"
std::optional<HandOrientation> orientation_from_name(std::string_view name);
std::optional<HandMotion> motion_from_name(std::string_view name);
// "horizontal/open", "vertical/thumb", ...
std::string pose_label_name(HandOrientation o, HandMotion m);
// Words for people (tables, the timeline): "palm down" / "palm left" (the study's horizontal and
// vertical: palm facing down, palm facing left) and "open hand", "index flexion", "thumb flexion",
// "wrist flexion", "wrist extension".
std::string_view orientation_words(HandOrientation o);
std::string_view motion_words(HandMotion m);

// Where the reference hand sits: palm centre this high above the table centre (world y up).
inline constexpr double kReferencePalmHeight_mm = 150.0;

// Joint angles for `motion` at `progress` in [0, 1] (0 = open hand, 1 = end of the motion's range,
// from published active ranges of motion, docs/algorithms/hand-points.md). For kOpen progress is ignored.
HandJointAngles motion_angles(HandMotion motion, double progress);
// End-of-range values used by motion_angles (degrees), for documentation and the UI.
struct MotionRanges {
  double index_mcp_deg = 90, index_pip_deg = 100, index_dip_deg = 80;
  double thumb_cmc_deg = 30, thumb_mcp_deg = 55, thumb_ip_deg = 80;
  double wrist_flexion_deg = 75, wrist_extension_deg = 70;
};
const MotionRanges& motion_ranges();

// The placement of the canonical hand frame for an orientation and joint angles: the palm
// centre (controller palm position) lands kReferencePalmHeight_mm above the world origin —
// also while the wrist bends, so a flexed hand stays above the table as in the trials (the forearm
// moves instead); vertical = horizontal rolled −90° about the forearm axis (palm to the subject's
// left, thumb up).
HandPlacement reference_placement(const HandModel& model, HandOrientation orientation,
                                  const HandJointAngles& angles = {});

// One of the ten reference poses (full range for the motions), as a 30-point world frame.
HandFrame reference_pose(const HandModel& model, HandOrientation orientation, HandMotion motion);

// The hand `progress` of the way through `motion` (0 = open hand, 1 = end of range), placed as
// the simulated rig places it during a trial: the open hand's placement, kept while the joints
// move (so a bending wrist swings the hand, not the forearm). For the Record tab's pictogram of
// what the subject is asked to do.
HandFrame motion_pose(const HandModel& model, HandOrientation orientation, HandMotion motion, double progress);

}  // namespace lmc
