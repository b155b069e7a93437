#pragma once
// The numbers of the page that explains a layout: the study's M and the robust terms, split by
// palm orientation; what each controller contributes (what the layout loses without it, the frames
// in which it alone sees some finger, its axis-cut violations); and per reference pose how often
// each finger is seen by one and by two or more controllers. They are the same ones `lmc evaluate`
// prints, computed here once; core/reports/ turns them into the Markdown page and its figures.
#include <array>
#include <span>
#include <string>
#include <vector>

#include "core/hand/pose_set.h"
#include "core/layout/layout.h"
#include "core/metric/controller_contribution.h"
#include "core/metric/coverage.h"
#include "core/metric/pose_set_score.h"
#include "core/metric/robust_metric.h"
#include "core/visibility/frame_prep.h"

namespace lmc {

struct PoseCoverageRow {
  HandOrientation orientation = HandOrientation::kHorizontal;
  HandMotion motion = HandMotion::kOpen;
  int frames = 0;
  std::array<double, kNumDigits> seen_by_one{};  // share of the pose's frames: finger seen by ≥ 1 controller
  std::array<double, kNumDigits> seen_by_two{};  // … by ≥ 2
};

struct LayoutReport {
  std::string layout_name, layout_description, poses_description;
  std::vector<std::string> slots;
  OrientationCoverage coverage;
  RobustTerms terms_all, terms_horizontal, terms_vertical;
  RobustWeights weights;
  std::vector<ControllerContribution> controllers;  // all frames
  std::vector<PoseCoverageRow> poses;               // the reference poses present in the set, in enum order
  std::vector<std::string> overlapping_pairs;       // "LMC1 and LMC2": footprints that overlap on the table
  std::vector<std::string> poses_provenance;        // PoseSet::provenance: where recorded frames came from
  // The headline figures on the report's own set first (label "this set" until the caller names
  // it), then on any other set the caller adds (`lmc evaluate` adds the Monte Carlo set to a
  // recorded one and the other way round), shown side by side.
  std::vector<PoseSetScore> sets;
};

// `prepared` are `poses.frames` prepared (prepare_frames).
LayoutReport build_layout_report(const Layout& layout, const PoseSet& poses, std::span<const PreparedFrame> prepared,
                                 const RobustWeights& weights = {}, double phalanx_radius_mm = 10.0);

}  // namespace lmc
