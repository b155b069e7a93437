#pragma once
// The layout report as files, one implementation for `lmc evaluate --report DIR` and
// the Layout tab's "Write report...": the pictures first (top-view, pose-redundancy and the
// finger × pose coverage heatmap finger-coverage: SVG, the CSV behind each and a JSON sidecar),
// then report.md, which links them. Each file is written atomically; returns report.md's path.
// Throws lmc::Error naming what could not be written.
#include <filesystem>

#include "core/hand/pose_set.h"
#include "core/layout/layout.h"
#include "core/metric/layout_report.h"

namespace lmc {

std::filesystem::path write_layout_report_files(const std::filesystem::path& dir, const Layout& layout,
                                                const PoseSet& poses, const LayoutReport& report,
                                                double phalanx_radius_mm);

}  // namespace lmc
