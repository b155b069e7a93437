#include "core/metric/layout_report.h"

#include "core/hand/reference_poses.h"
#include "core/metric/inside_cut_visibility.h"
#include "core/metric/layout_tally.h"
#include "core/visibility/visibility_kernel.h"

namespace lmc {

LayoutReport build_layout_report(const Layout& layout, const PoseSet& poses, std::span<const PreparedFrame> prepared,
                                 const RobustWeights& weights, double phalanx_radius_mm) {
  LayoutReport r;
  r.layout_name = layout.name;
  r.layout_description = layout.description;
  r.poses_description = poses.description;
  r.weights = weights;
  for (const auto& d : layout.devices) r.slots.push_back(d.slot);
  // One kernel pass gives what each controller sees and what it sees inside its axis cut; the
  // coverage, the robust terms and each controller's contribution are all counted from it.
  const VisibilityWithCut tables = visibility_with_inside_cut(layout, prepared, phalanx_radius_mm);
  const VisibilityTable& table = tables.seen;
  const std::vector<int> horizontal = poses.indices_with(HandOrientation::kHorizontal);
  const std::vector<int> vertical = poses.indices_with(HandOrientation::kVertical);
  r.coverage = coverage_by_orientation(table, horizontal, vertical);
  r.poses_provenance = poses.provenance;
  r.sets.push_back(pose_set_score(table, "this set", poses.description));

  std::vector<DeviceView> views;
  for (const auto& d : layout.devices) views.push_back(DeviceView::from_device(d));
  const std::vector<VisibilityLimits> limits = device_limits(layout, phalanx_radius_mm);
  const double footprint = footprint_overlap_share(layout);
  // The tallies from the same tables: the kernel runs once for the whole report.
  const LayoutTally all = tally_from_visibility(tables, views, prepared, limits);
  r.terms_all = robust_terms(all, footprint, weights);
  if (!horizontal.empty())
    r.terms_horizontal =
        robust_terms(tally_from_visibility(tables, views, prepared, limits, horizontal), footprint, weights);
  if (!vertical.empty())
    r.terms_vertical =
        robust_terms(tally_from_visibility(tables, views, prepared, limits, vertical), footprint, weights);
  r.controllers = controller_contributions(table, all, r.slots, {}, &tables.inside_cut);
  for (size_t i = 0; i < layout.devices.size(); ++i) {
    for (size_t j = i + 1; j < layout.devices.size(); ++j) {
      if (footprints_overlap(layout.devices[i], layout.devices[j]))
        r.overlapping_pairs.push_back(r.slots[i] + " and " + r.slots[j]);
    }
  }

  for (int o = 0; o < kNumHandOrientations; ++o) {
    for (int m = 0; m < kNumHandMotions; ++m) {
      PoseCoverageRow row;
      row.orientation = static_cast<HandOrientation>(o);
      row.motion = static_cast<HandMotion>(m);
      std::array<std::int64_t, kNumDigits> one{}, two{};
      for (int j = 0; j < poses.size(); ++j) {
        const PoseLabel& l = poses.labels[static_cast<size_t>(j)];
        if (l.orientation != row.orientation || l.motion != row.motion) continue;
        ++row.frames;
        for (int k = 0; k < kNumDigits; ++k) {
          int seeing = 0;
          for (int d = 0; d < table.devices; ++d) seeing += (table.at(d, j) >> k) & 1;
          one[static_cast<size_t>(k)] += seeing >= 1;
          two[static_cast<size_t>(k)] += seeing >= 2;
        }
      }
      if (row.frames == 0) continue;
      for (size_t k = 0; k < static_cast<size_t>(kNumDigits); ++k) {
        row.seen_by_one[k] = static_cast<double>(one[k]) / row.frames;
        row.seen_by_two[k] = static_cast<double>(two[k]) / row.frames;
      }
      r.poses.push_back(row);
    }
  }
  return r;
}

}  // namespace lmc
