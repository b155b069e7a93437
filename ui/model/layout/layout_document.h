#pragma once
// A *layout document* is what the user edits and saves in the Layout tab (docs/architecture.md): the
// layout itself plus the document-level choices that travel with it — which pose parameters the
// optimiser may change per device (locks), the search bounds, and the pose set to evaluate on.
// No selection, camera or caches: "if undo should not restore it, it is not document state".
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/layout/layout.h"
#include "ui/scene/device_locks.h"

namespace lmc::ui {

struct ParamRange {
  double lo = 0, hi = 0;
  bool operator==(const ParamRange&) const = default;
};

// Search box per pose parameter, shared by all devices. Default: the table drawn in the scene, as
// core's table_search_space: x, z ∈ [−360, 360] mm keep every controller whole on the ±400 mm
// table top (not the authors' ±1000 mm box, which let the search park a controller off it),
// y ∈ [0, 300] mm, rx ∈ [−90, 90]°, ry and rz ∈ [−180, 180]°. y and rz are locked by default
// (DeviceLocks: the paper searched {x, z, rx, ry}), so their ranges apply only once unlocked.
struct SearchBounds {
  std::array<ParamRange, kNumPoseParams> range{ParamRange{-360, 360}, ParamRange{0, 300},    ParamRange{-360, 360},
                                               ParamRange{-90, 90},   ParamRange{-180, 180}, ParamRange{-180, 180}};
  bool operator==(const SearchBounds&) const = default;
};

// Which hand poses the tab shows and scores (docs/algorithms/search.md: the Monte Carlo set of
// ten reference poses varied along the trial trajectories, a file — a pose set or a recipe — or
// the hands of recorded trials, core/poses/recorded_poses.h).
struct PoseSetChoice {
  enum class Source : int { kMonteCarlo = 0, kFile = 1, kRecordings = 2 };
  Source source = Source::kMonteCarlo;
  int frames = 2000;
  std::uint64_t seed = 1;
  std::string file;
  // kRecordings: processed-trial folders or files (fused), session folders or LMC files (LMCn, vicon).
  std::vector<std::string> recordings;
  std::string recorded_source = "fused";  // fused, vicon, LMC1 … LMC8
  std::string trials_glob;                // empty: every trial
  int every = 1;
  bool operator==(const PoseSetChoice&) const = default;
};

struct LayoutDocument {
  Layout layout;
  std::vector<DeviceLocks> locks;  // one per layout device, same order
  SearchBounds bounds;
  PoseSetChoice pose_set;

  bool operator==(const LayoutDocument&) const = default;

  int device_count() const { return layout.device_count(); }
  // Keeps locks parallel to devices (after a load or an apply that changed the count).
  void sync_locks() { locks.resize(layout.devices.size()); }
};

// A document holding `layout` with default locks, bounds and pose set.
LayoutDocument make_document(Layout layout);

}  // namespace lmc::ui
