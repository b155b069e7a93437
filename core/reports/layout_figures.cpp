#include "core/reports/layout_figures.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/common/nan.h"
#include "core/hand/hand_frame.h"
#include "core/hand/reference_poses.h"
#include "core/metric/robust_metric.h"

namespace lmc {
namespace {}  // namespace

Figure layout_top_view(const Layout& layout, const PoseSet& poses, int max_hand_points) {
  Figure f;
  f.title = "Top view of " + layout.name;
  f.x = {"x (across the table)", "mm", std::nullopt};
  f.y = {"z (towards the subject)", "mm", std::nullopt};
  // The hands' mean palm height: where each viewing axis is followed to.
  double height = 0;
  int n = 0;
  for (const auto& frame : poses.frames) {
    if (std::isfinite(frame.points[kPalm].y())) {
      height += frame.points[kPalm].y();
      ++n;
    }
  }
  height = n > 0 ? height / n : 200.0;
  for (const auto& d : layout.devices) {
    Series s;
    s.name = d.slot;
    const auto corners = controller_footprint(d);
    for (int i = 0; i <= 4; ++i) {
      s.x.push_back(corners[static_cast<size_t>(i % 4)].x());
      s.y.push_back(corners[static_cast<size_t>(i % 4)].y());
    }
    // A missing sample breaks the line: the footprint and the axis are two pieces of one series.
    s.x.push_back(kNaN);
    s.y.push_back(kNaN);
    const Eigen::Vector3d centre = d.pose.translation() + d.offset_mm;
    const Eigen::Vector3d axis = d.pose.up();
    if (axis.y() > 0.05) {
      const Eigen::Vector3d reach = centre + axis * ((height - centre.y()) / axis.y());
      s.x.push_back(centre.x());
      s.y.push_back(centre.z());
      s.x.push_back(reach.x());
      s.y.push_back(reach.z());
    }
    f.series.push_back(std::move(s));
  }
  Series hands;
  hands.name = "palm positions";
  hands.style = SeriesStyle::points;
  hands.colour = Rgb{150, 150, 150};
  const int total = poses.size();
  const int cap = std::max(1, max_hand_points);
  const int step = std::max(1, (total + cap - 1) / cap);  // rounded up: never more than the cap
  for (int k = 0; k < total; k += step) {
    const auto& p = poses.frames[static_cast<size_t>(k)].points[kPalm];
    hands.x.push_back(p.x());
    hands.y.push_back(p.z());
  }
  f.series.push_back(std::move(hands));
  f.notes.push_back("Boxes: the controllers' footprints; lines: each viewing axis followed up to the hands'");
  f.notes.push_back("mean palm height (" + std::to_string(static_cast<int>(std::lround(height))) +
                    " mm); grey: the pose set's palm positions.");
  return f;
}

Figure pose_redundancy_figure(const LayoutReport& r) {
  Figure f;
  f.title = "Fingers seen by 2+ controllers: " + r.layout_name;
  f.x = {"reference pose", "", AxisRange{0.5, static_cast<double>(r.poses.size()) + 0.5}};
  f.y = {"share of the pose's frames", "", AxisRange{0.0, 1.0}};
  for (int k = 0; k < kNumDigits; ++k) {
    Series s;
    s.name = std::string(digit_name(k));
    s.style = SeriesStyle::line_and_points;
    for (size_t p = 0; p < r.poses.size(); ++p) {
      s.x.push_back(static_cast<double>(p + 1));
      s.y.push_back(r.poses[p].seen_by_two[static_cast<size_t>(k)]);
    }
    f.series.push_back(std::move(s));
  }
  // Three poses a line: the notes are written under the chart at its width.
  std::string line;
  for (size_t p = 0; p < r.poses.size(); ++p) {
    line += (line.empty() ? "" : "; ") + std::to_string(p + 1) + " " +
            std::string(orientation_words(r.poses[p].orientation)) + ", " +
            std::string(motion_words(r.poses[p].motion));
    if (p % 3 == 2 || p + 1 == r.poses.size()) {
      f.notes.push_back(line);
      line.clear();
    }
  }
  return f;
}

Heatmap finger_coverage_heatmap(const LayoutReport& r) {
  Heatmap h;
  h.title = "Finger coverage per pose: " + r.layout_name;
  for (int f = 0; f < kNumDigits; ++f) h.rows.emplace_back(digit_name(f));
  h.row_title = "finger";
  h.column_title = "reference pose (palm orientation, motion)";
  h.scale_label = "share of the pose's frames";
  h.value_text = HeatmapValueText::percent;
  int fewest = 0, most = 0;
  for (const PoseCoverageRow& p : r.poses) {
    h.columns.emplace_back(motion_words(p.motion));
    h.column_groups.emplace_back(orientation_words(p.orientation));
    fewest = fewest == 0 ? p.frames : std::min(fewest, p.frames);
    most = std::max(most, p.frames);
  }
  HeatmapPanel one{"Seen by at least one controller", {}};
  HeatmapPanel two{"Seen by two or more controllers", {}};
  for (size_t k = 0; k < static_cast<size_t>(kNumDigits); ++k) {
    for (const PoseCoverageRow& p : r.poses) {
      one.values.push_back(p.seen_by_one[k]);
      two.values.push_back(p.seen_by_two[k]);
    }
  }
  h.panels = {std::move(one), std::move(two)};
  h.notes.push_back(
      "A cell: the share of that pose's frames in which the finger is seen by ≥ 1 controller (top), ≥ 2 (bottom).");
  h.notes.push_back(std::to_string(fewest) + (fewest == most ? "" : "–" + std::to_string(most)) +
                    " frames a pose (the set's frames labelled with it); pose set: " + r.poses_description + ".");
  return h;
}

}  // namespace lmc
