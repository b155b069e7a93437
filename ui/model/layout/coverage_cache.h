#pragma once
// Coverage of the current layout on the current pose set, kept per device (docs/architecture.md): one
// visibility bit column per device, keyed on that device's pose and offset, the sensor model and
// the pose-set version. When one controller is dragged only its column is recomputed; M, c_i and
// the device × finger table are then rebuilt from bits, which is cheap.
//
// The columns are computed on one worker thread (a 2,000-frame column takes milliseconds, too
// much to risk inside a frame); while it runs, a newer request waits and replaces any older one,
// so during a drag the table trails the cursor by at most one computation.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/layout/layout.h"
#include "core/metric/coverage.h"
#include "core/visibility/visibility_kernel.h"
#include "ui/model/jobs/background_job.h"
#include "ui/model/layout/pose_set_store.h"

namespace lmc::ui {

// What one column depends on.
struct ColumnKey {
  DevicePose pose;
  std::array<double, 3> offset_mm{};
  SensorModel sensor;
  std::uint64_t pose_set_version = 0;
  bool operator==(const ColumnKey&) const = default;
};
ColumnKey column_key(const LayoutDevice& device, const SensorModel& sensor, std::uint64_t pose_set_version);

using BitColumn = std::shared_ptr<const std::vector<FingerBits>>;

struct CoverageSnapshot {
  std::uint64_t pose_set_version = 0;
  std::vector<ColumnKey> keys;  // one per device, in layout order
  std::vector<BitColumn> columns;
  Coverage all, horizontal, vertical;
  int columns_computed = 0;  // how many columns this snapshot had to compute (the rest were reused)
};
using CoverageSnapshotPtr = std::shared_ptr<const CoverageSnapshot>;

// Computes a snapshot synchronously, reusing columns of `previous` whose keys match.
CoverageSnapshotPtr compute_coverage_snapshot(const Layout& layout, const PoseSetPtr& poses,
                                              const CoverageSnapshotPtr& previous, std::stop_token stop = {});

class CoverageCache {
 public:
  // Asks for the coverage of `layout` on `poses`; cheap when nothing changed. Call in update().
  void request(const Layout& layout, const PoseSetPtr& poses);
  // Picks up a finished computation and starts the pending one.
  void poll();
  void wait();  // tests and capture

  CoverageSnapshotPtr latest() const { return latest_; }
  // True when latest() matches the last request exactly.
  bool up_to_date() const;
  bool busy() const { return job_.running() || pending_; }
  const std::string& error() const { return error_; }

 private:
  void start_pending();

  CoverageSnapshotPtr latest_;
  Layout requested_layout_;
  PoseSetPtr requested_poses_;
  std::vector<ColumnKey> requested_keys_;
  bool pending_ = false;
  std::string error_;
  BackgroundJob<CoverageSnapshotPtr, int> job_;
};

}  // namespace lmc::ui
