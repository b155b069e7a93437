// Pose-set recipes (core/poses/pose_recipe.h): weights, the Monte Carlo share, the same set every
// time, and a bad recipe named to its key.
#include "core/poses/pose_recipe.h"

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/pose_set_tsv.h"
#include "tests/support/scratch_dir.h"

namespace {

namespace fs = std::filesystem;

// A pose-set file of `n` Monte Carlo frames whose labels all say `motion`.
fs::path write_part(const fs::path& dir, const std::string& name, int n, lmc::HandMotion motion, std::uint64_t seed) {
  lmc::PoseSetSettings s;
  s.frames = n;
  s.seed = seed;
  lmc::PoseSet set = lmc::generate_pose_set(lmc::HandModel(), s);
  for (auto& l : set.labels) l.motion = motion;
  const fs::path file = dir / name;
  lmc::save_pose_set(file, set);
  return file;
}

int count_motion(const lmc::PoseSet& set, lmc::HandMotion m) {
  return static_cast<int>(set.indices_with(m).size());
}

TEST(PoseRecipe, WeightsAndTheMonteCarloShareSetTheCounts) {
  const auto dir = lmc::test::scratch_dir("pose_recipe_mix");
  write_part(dir, "index.tsv", 300, lmc::HandMotion::kIndexFlexion, 2);
  write_part(dir, "thumb.tsv", 500, lmc::HandMotion::kThumbFlexion, 3);
  const std::string text = R"({"format": "lmc-pose-recipe", "format_version": 1, "frames": 1000,
    "parts": [{"poses": "index.tsv", "weight": 2}, {"poses": "thumb.tsv", "weight": 1}],
    "monte_carlo": {"share": 0.2, "seed": 9}})";
  const lmc::PoseRecipe recipe = lmc::parse_pose_recipe(text, "mix.json", dir);
  const lmc::PoseSet set = lmc::build_pose_set(recipe);
  ASSERT_EQ(set.size(), 1000);
  // 800 recorded frames 2:1 → 533 + 267; the Monte Carlo 200 hold every motion, index and thumb too.
  lmc::PoseSetSettings mc;
  mc.frames = 200;
  mc.seed = 9;
  const lmc::PoseSet mc_set = lmc::generate_pose_set(lmc::HandModel(), mc);
  EXPECT_EQ(count_motion(set, lmc::HandMotion::kIndexFlexion),
            533 + count_motion(mc_set, lmc::HandMotion::kIndexFlexion));
  EXPECT_EQ(count_motion(set, lmc::HandMotion::kThumbFlexion),
            267 + count_motion(mc_set, lmc::HandMotion::kThumbFlexion));
  // The Monte Carlo frames are the generator's, at the end.
  EXPECT_EQ(set.frames[800].point(lmc::kPalm), mc_set.frames[0].point(lmc::kPalm));
  // Same recipe, same set.
  const lmc::PoseSet again = lmc::build_pose_set(recipe);
  for (int j = 0; j < set.size(); ++j)
    ASSERT_EQ(set.frames[static_cast<size_t>(j)].points, again.frames[static_cast<size_t>(j)].points);
  EXPECT_NE(set.description.find("533 recorded + 267 recorded + 200 Monte Carlo"), std::string::npos)
      << set.description;
  EXPECT_GE(set.provenance.size(), 3u);
}

TEST(PoseRecipe, WithoutAFrameCountEveryRecordedFrameIsTakenOnce) {
  const auto dir = lmc::test::scratch_dir("pose_recipe_once");
  const fs::path a = write_part(dir, "a.tsv", 120, lmc::HandMotion::kOpen, 4);
  const std::string text = R"({"format": "lmc-pose-recipe", "format_version": 1,
    "parts": [{"poses": "a.tsv"}], "monte_carlo": {"share": 0.25}})";
  const lmc::PoseSet set = lmc::build_pose_set(lmc::parse_pose_recipe(text, "r.json", dir));
  ASSERT_EQ(set.size(), 160);  // 120 recorded + 40 Monte Carlo (a quarter)
  const lmc::PoseSet part = lmc::load_pose_set(a);
  for (int j = 0; j < 120; ++j)
    ASSERT_EQ(set.frames[static_cast<size_t>(j)].points, part.frames[static_cast<size_t>(j)].points);
}

TEST(PoseRecipe, ABadRecipeIsNamedToItsKey) {
  const auto dir = lmc::test::scratch_dir("pose_recipe_bad");
  auto message = [&](const std::string& text) {
    try {
      (void)lmc::parse_pose_recipe(text, "bad.json", dir);
    } catch (const lmc::Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string head = R"({"format": "lmc-pose-recipe", "format_version": 1, )";
  EXPECT_NE(message(head + R"("parts": [{"poses": "a.tsv", "weight": 0}]})").find("weight"), std::string::npos);
  EXPECT_NE(message(head + R"("parts": [{"poses": "a.tsv", "wieght": 2}]})").find("wieght"), std::string::npos);
  EXPECT_NE(message(head + R"("parts": [{"from": "x", "source": "kinect"}]})").find("kinect"), std::string::npos);
  EXPECT_NE(message(head + R"("parts": []})").find("no parts"), std::string::npos);
  EXPECT_NE(message(head + R"("parts": [{"poses": "a.tsv"}], "monte_carlo": {"share": 1.5}})").find("share"),
            std::string::npos);
  EXPECT_NE(message(R"({"format": "lmc-layout", "format_version": 1})").find("lmc-pose-recipe"), std::string::npos);
  // A recipe of Monte Carlo alone is fine.
  EXPECT_EQ(message(head + R"("frames": 10, "monte_carlo": {"share": 1}})"), "accepted");
}

}  // namespace
