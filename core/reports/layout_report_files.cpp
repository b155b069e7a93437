#include "core/reports/layout_report_files.h"

#include <nlohmann/json.hpp>

#include "core/figures/export_sidecar.h"
#include "core/io/atomic_write.h"
#include "core/reports/layout_figures.h"
#include "core/reports/layout_report_markdown.h"

namespace lmc {

std::filesystem::path write_layout_report_files(const std::filesystem::path& dir, const Layout& layout,
                                                const PoseSet& poses, const LayoutReport& report,
                                                double phalanx_radius_mm) {
  std::filesystem::create_directories(dir);
  const nlohmann::json parameters = {{"poses", poses.description}, {"phalanx_radius_mm", phalanx_radius_mm}};
  const std::vector<std::string> inputs = {layout.name, poses.description};
  write_figure_files(dir, "top-view", layout_top_view(layout, poses), inputs, "layout top view", parameters, 800, 700);
  write_figure_files(dir, "pose-redundancy", pose_redundancy_figure(report), inputs,
                     "fingers seen by 2+ controllers per pose", parameters);
  write_figure_files(dir, "finger-coverage", finger_coverage_heatmap(report), inputs,
                     "share of each reference pose's frames in which each finger is seen by 1+ and 2+ controllers",
                     parameters, 900, 560);
  const auto md = dir / "report.md";
  write_file_atomically(
      md, format_layout_report_markdown(
              report, {{"Top view: footprints, viewing axes, palm positions", "top-view.svg"},
                       {"Fingers seen by two or more controllers per reference pose", "pose-redundancy.svg"},
                       {"Coverage heatmap: a cell is the share of a reference pose's frames in which the finger is "
                        "seen by at least one controller (top) or by two or more (bottom)",
                        "finger-coverage.svg"}}));
  return md;
}

}  // namespace lmc
