// `lmc poses --from`, `lmc evaluate --poses recorded.tsv` and `lmc optimize --poses recipe.json`,
// run as a lab would: on the study's real static trial (the one kernel: the recorded set sees what
// `lmc visibility` sees) and on a simulated subject session made and processed with `lmc`.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/pose_set_tsv.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"
#include "tests/support/cli_runner.h"
#include "tests/support/quick_session.h"
#include "tests/support/reference_data.h"

namespace {

using lmc::test::CliRun;
using lmc::test::run_lmc;
using lmc::test::shell_quote;

TEST(LmcPosesFrom, OneControllersRecordedSetSeesWhatLmcVisibilitySees) {
  const auto raw = lmc::test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(raw);
  const auto dir = lmc::test::scratch_dir("cli_poses_from_visibility");
  const auto set_file = dir / "lmc3.tsv", labelled = dir / "labelled.txt";
  CliRun r =
      run_lmc("poses --from " + shell_quote(raw.string()) + " --source LMC3 -o " + shell_quote(set_file.string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_NE(r.out.find("from 1 trials"), std::string::npos) << r.out;
  r = run_lmc("visibility " + shell_quote(raw.string()) + " -o " + shell_quote(labelled.string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.all();

  // `lmc visibility`: each row in its controller's own frame. The recorded set: LMC3's rows with a
  // hand, in the world frame; the kernel with LMC3 where the trial's layout puts it.
  const lmc::LmcRecording rec = lmc::read_lmc_recording(labelled);
  std::vector<lmc::FingerBits> expected;
  for (size_t i = 0; i < rec.rows.size(); ++i) {
    if (rec.rows[i].device_id != 3 || !rec.rows[i].hand_present) continue;
    lmc::FingerBits bits = 0;
    for (int k = 0; k < lmc::kNumDigits; ++k) bits |= (rec.visibility[i][static_cast<size_t>(k)] == 1 ? 1u : 0u) << k;
    expected.push_back(bits);
  }
  const lmc::PoseSet set = lmc::load_pose_set(set_file);
  ASSERT_EQ(set.size(), static_cast<int>(expected.size()));
  const lmc::Layout layout = lmc::load_layout_or_preset("paper-initial");
  const lmc::DeviceView view = lmc::DeviceView::from_device(layout.devices[2]);
  const auto prepared = lmc::prepare_frames(set.frames);
  const lmc::VisibilityTable table = lmc::compute_visibility(std::span<const lmc::DeviceView>(&view, 1), prepared,
                                                             lmc::VisibilityParams{400.0, 150.0, 120.0, 10.0});
  int visible = 0;
  for (int j = 0; j < set.size(); ++j) {
    ASSERT_EQ(table.at(0, j), expected[static_cast<size_t>(j)]) << "frame " << j;
    visible += table.at(0, j) != 0;
  }
  EXPECT_GT(visible, 0);  // not a comparison of nothing with nothing
}

struct RecordedSession : lmc::test::QuickSessionSuite<RecordedSession> {
  static constexpr const char* kScratchName = "cli_recorded_poses";
  static constexpr int kSeed = 8;
};

TEST_F(RecordedSession, FusedSetScoredBesideTheMonteCarloSetAndMixedInARecipe) {
  const auto dir = root() / "work";
  const auto processed = dir / "processed";
  CliRun r = run_lmc("process " + shell_quote(session().string()) + " -o " + shell_quote(processed.string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  const auto set_file = dir / "fused.tsv";
  r = run_lmc("poses --from " + shell_quote(processed.string()) + " --every 2 -o " + shell_quote(set_file.string()),
              dir);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  const lmc::PoseSet set = lmc::load_pose_set(set_file);
  ASSERT_GT(set.size(), 50);
  ASSERT_FALSE(set.provenance.empty());
  EXPECT_NE(set.provenance[0].find("fused hand"), std::string::npos) << set.provenance[0];

  const auto report = dir / "report";
  r = run_lmc("evaluate --layout paper-initial --frames 500 --json --poses " + shell_quote(set_file.string()) +
                  " --report " + shell_quote(report.string()),
              dir);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["pose_sets"].size(), 2u);
  EXPECT_EQ(j["pose_sets"][0]["frames"], set.size());
  EXPECT_EQ(j["pose_sets"][1]["label"], "Monte Carlo");
  EXPECT_EQ(j["pose_sets"][1]["frames"], 500);
  EXPECT_DOUBLE_EQ(j["pose_sets"][0]["metric"].get<double>(), j["all"]["metric"].get<double>());
  const std::string md = lmc::test::read_text_file(report / "report.md");
  EXPECT_NE(md.find("## On each pose set"), std::string::npos);
  EXPECT_NE(md.find("| Monte Carlo | 500 |"), std::string::npos);
  EXPECT_NE(md.find("* source: fused hand"), std::string::npos);

  // A recipe: this set 1 part, plus a quarter Monte Carlo; the search on it is the same twice.
  const auto recipe = dir / "recipe.json";
  {
    std::ofstream out(recipe);
    out << R"({"format": "lmc-pose-recipe", "format_version": 1, "frames": 400,
      "parts": [{"poses": "fused.tsv"}], "monte_carlo": {"share": 0.25, "seed": 3}})";
  }
  const std::string search = "optimize --particles 4 --iterations 2 --devices 2 --no-progress --poses " +
                             shell_quote(recipe.string()) + " -o ";
  r = run_lmc(search + shell_quote((dir / "a.json").string()) + " --threads 1", dir);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_NE(r.out.find("300 recorded + 100 Monte Carlo"), std::string::npos) << r.out;
  r = run_lmc(search + shell_quote((dir / "b.json").string()) + " --threads 2", dir);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_EQ(lmc::load_layout(dir / "a.json"), lmc::load_layout(dir / "b.json"));
  EXPECT_NE(lmc::load_layout(dir / "a.json").description.find("recipe"), std::string::npos);
}

TEST(LmcPosesFrom, AFolderWithoutRecordingsIsRefusedNamingIt) {
  const auto dir = lmc::test::scratch_dir("cli_poses_from_empty");
  const CliRun r = run_lmc("poses --from " + shell_quote(dir.string()) + " -o " + shell_quote((dir / "p.tsv").string()),
                           dir / "logs");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(dir.string()), std::string::npos) << r.err;
}

}  // namespace
