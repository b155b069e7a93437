#include "core/metric/layout_report.h"

#include <gtest/gtest.h>

#include "core/hand/pose_set_generator.h"
#include "core/io/layout_json.h"
#include "core/reports/layout_report_markdown.h"

namespace lmc {
namespace layout_report_test {

struct ReportPoses {
  PoseSet set;
  std::vector<PreparedFrame> prepared;
};

const ReportPoses& report_poses() {
  static const ReportPoses p = [] {
    PoseSetSettings s;
    s.frames = 300;
    s.seed = 4;
    ReportPoses out;
    out.set = generate_pose_set(HandModel(), s);
    out.prepared = prepare_frames(out.set.frames);
    return out;
  }();
  return p;
}

TEST(LayoutReport, ThePapersOptimizedLayoutIsExplainedInOnePage) {
  const Layout l = load_layout_or_preset("paper-optimized");
  const LayoutReport r = build_layout_report(l, report_poses().set, report_poses().prepared);
  ASSERT_EQ(r.controllers.size(), 4u);
  EXPECT_FALSE(r.controllers[0].counts);  // LMC1 looks away from the hand as published
  EXPECT_EQ(r.coverage.all.frames, 300);
  EXPECT_EQ(r.coverage.horizontal.frames + r.coverage.vertical.frames, 300);
  EXPECT_EQ(r.terms_all.metric_m, r.coverage.all.metric);
  // The ten reference poses, each with its frames.
  ASSERT_EQ(r.poses.size(), 10u);
  int frames = 0;
  for (const auto& p : r.poses) {
    frames += p.frames;
    for (size_t k = 0; k < 5; ++k) EXPECT_LE(p.seen_by_two[k], p.seen_by_one[k]);
  }
  EXPECT_EQ(frames, 300);
  // With the authors' offsets LMC2 stands on LMC1's footprint in the paper's table.
  ASSERT_EQ(r.overlapping_pairs.size(), 1u);
  EXPECT_EQ(r.overlapping_pairs[0], "LMC1 and LMC2");
  const std::string md = format_layout_report_markdown(r);
  EXPECT_NE(md.find("# Layout report: paper-optimized"), std::string::npos);
  EXPECT_NE(md.find("**LMC1 does not count**"), std::string::npos) << md;
  EXPECT_NE(md.find("**LMC1 and LMC2 overlap**"), std::string::npos) << md;
  EXPECT_NE(md.find("| palm left, wrist extension |"), std::string::npos) << md;
  EXPECT_NE(md.find("| axis cut | share of seeing controller-frames with a seen marker beyond 250 mm | 0.2 |"),
            std::string::npos)
      << md;
  // What the controllers can measure: M with every finger beyond a controller's cut unseen by it.
  EXPECT_NE(md.find("| M inside cut | "), std::string::npos) << md;
  EXPECT_NE(md.find("Counting only what lies inside each controller's cut"), std::string::npos) << md;
  EXPECT_GT(r.terms_all.metric_m_inside_cut, r.terms_all.metric_m);
  // Each controller counted the same way: LMC1 sees nothing, so nothing inside its cut either.
  EXPECT_FALSE(r.controllers[0].counts_inside_cut);
  EXPECT_EQ(r.controllers[0].seeing_inside_cut_share, 0.0);
  EXPECT_NE(md.find("**LMC1 adds nothing inside its cut**"), std::string::npos) << md;
  EXPECT_NE(md.find("| controller | sees some finger inside its cut | M inside cut without it |"), std::string::npos)
      << md;
}

TEST(LayoutReport, ALayoutWhereEveryControllerCountsSaysSo) {
  const Layout l = load_layout_or_preset("paper-initial");
  const LayoutReport r = build_layout_report(l, report_poses().set, report_poses().prepared);
  for (const auto& c : r.controllers) EXPECT_TRUE(c.counts) << c.slot;
  EXPECT_TRUE(r.overlapping_pairs.empty());
  EXPECT_NE(format_layout_report_markdown(r).find("Every controller counts"), std::string::npos);
  // paper-initial's controllers sit under the hand, within their cuts: each counts inside it too.
  for (const auto& c : r.controllers) EXPECT_TRUE(c.counts_inside_cut) << c.slot;
  EXPECT_NE(format_layout_report_markdown(r).find("Inside the axis cuts too"), std::string::npos);
}

}  // namespace layout_report_test
}  // namespace lmc
