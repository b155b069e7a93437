#include <gtest/gtest.h>

#include <sstream>

#include "core/common/error.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/pose_set_tsv.h"
#include "core/io/pose_source.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace {

PoseSet small_set(std::uint64_t seed, int frames = 200) {
  PoseSetSettings s;
  s.frames = frames;
  s.seed = seed;
  return generate_pose_set(HandModel(), s);
}

TEST(PoseSetGenerator, SameSeedSameNumbersOtherSeedOtherNumbers) {
  const PoseSet a = small_set(42), b = small_set(42), c = small_set(43);
  ASSERT_EQ(a.size(), 200);
  ASSERT_EQ(a.labels.size(), 200u);
  for (int i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a.frames[static_cast<size_t>(i)].points, b.frames[static_cast<size_t>(i)].points);
    EXPECT_EQ(a.labels[static_cast<size_t>(i)], b.labels[static_cast<size_t>(i)]);
  }
  EXPECT_NE(a.frames[0].points[kPalm], c.frames[0].points[kPalm]);
}

TEST(PoseSetGenerator, CoversEveryLabelWithJitteredHandsAround150mm) {
  const PoseSet set = small_set(1, 2000);
  int counts[kNumHandOrientations][kNumHandMotions] = {};
  double mean_y = 0;
  for (size_t i = 0; i < set.frames.size(); ++i) {
    const PoseLabel& l = set.labels[i];
    ++counts[static_cast<int>(l.orientation)][static_cast<int>(l.motion)];
    EXPECT_GE(l.progress, 0.0);
    EXPECT_LE(l.progress, 1.0);
    if (l.motion == HandMotion::kOpen) {
      EXPECT_EQ(l.progress, 0.0);
    }
    EXPECT_TRUE(set.frames[i].hand_present);
    mean_y += set.frames[i].point(kPalm).y();  // the palm stays put while the wrist bends
  }
  for (auto& row : counts) {
    for (int c : row) EXPECT_GT(c, 120);  // 2000 / 10 = 200 expected
  }
  EXPECT_NEAR(mean_y / set.size(), 150.0, 2.0);
  EXPECT_EQ(set.indices_with(HandOrientation::kHorizontal).size() + set.indices_with(HandOrientation::kVertical).size(),
            2000u);
}

TEST(PoseSetTsv, RoundTripsExactly) {
  const PoseSet a = small_set(7, 50);
  std::stringstream ss;
  write_pose_set(ss, a);
  const PoseSet b = parse_pose_set(ss, "mem");
  EXPECT_EQ(b.description, a.description);
  ASSERT_EQ(b.size(), a.size());
  for (size_t i = 0; i < a.frames.size(); ++i) {
    EXPECT_EQ(a.frames[i].points, b.frames[i].points);  // bit-exact
    EXPECT_EQ(a.labels[i], b.labels[i]);
  }
  const auto dir = test::scratch_dir("pose_set_tsv");
  save_pose_set(dir / "p.tsv", a);
  EXPECT_EQ(load_pose_set(dir / "p.tsv").frames.back().points, a.frames.back().points);
  EXPECT_EQ(load_poses((dir / "p.tsv").string()).size(), 50);
}

void expect_error(const std::string& text, long line, long column) {
  std::istringstream in(text);
  try {
    parse_pose_set(in, "bad.tsv");
    ADD_FAILURE() << "no error for:\n" << text.substr(0, 200);
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, "bad.tsv");
    EXPECT_EQ(e.where().line, line) << e.what();
    EXPECT_EQ(e.where().column, column) << e.what();
  }
}

TEST(PoseSetTsv, ErrorsNameLineAndColumn) {
  std::stringstream ss;
  write_pose_set(ss, small_set(3, 2));
  const std::string good = ss.str();
  expect_error("hello\n", 1, 1);
  // Line 1 magic, 2 description, 3 header, 4 and 5 rows.
  std::string bad = good;
  const size_t row2 = bad.find("\n1\t") + 1;
  bad.replace(bad.find('\t', row2) + 1, 0, "x");  // orientation "xhorizontal"/"xvertical"
  expect_error(bad, 5, 2);
  bad = good;
  const size_t row1 = bad.find("\n0\t") + 1;
  const size_t col5 = [&] {
    size_t p = row1;
    for (int i = 0; i < 4; ++i) p = bad.find('\t', p) + 1;
    return p;
  }();
  bad.replace(col5, 0, "z");
  expect_error(bad, 4, 5);
  bad = good.substr(0, good.rfind('\t')) + "\n";  // last row one field short
  expect_error(bad, 5, 94);
}

}  // namespace
}  // namespace lmc
