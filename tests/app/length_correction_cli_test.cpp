// `lmc length-correction fit` and `lmc process --length-correction` as a user
// runs them: fit on one simulated static trial against its truth, apply to another trial, and the
// refusals (reference method, method comparison, bad hand size, a folder without --trial, a
// malformed file) each with a message naming what to fix.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace length_correction_cli_test {

using lmc::test::CliRun;
using lmc::test::run_lmc;
using lmc::test::shell_quote;

TEST(LmcLengthCorrection, FitsOnOneTrialAppliesToAnotherAndRefusesWhatItCannotDo) {
  const auto dir = lmc::test::scratch_dir("length_correction_cli");
  const auto sim = dir / "S01";
  const std::string q = shell_quote(sim.string());
  for (const char* spec : {"Naiv_Static101 horizontal/static", "Naiv_Index101 horizontal/index"}) {
    const std::string s(spec);
    const std::string trial = s.substr(0, s.find(' ')), motion = s.substr(s.find(' ') + 1);
    const CliRun rec =
        run_lmc("record --backend sim --fast --quiet --seconds 2 --seed 4 --layout paper-initial --trial " + trial +
                " --motion " + motion + " -o " + q);
    ASSERT_EQ(rec.exit_code, 0) << rec.err;
  }
  const std::string file = (dir / "S01.lengths.json").string();

  const CliRun many = run_lmc("length-correction fit " + q + " --subject S01 -o " + shell_quote(file));
  EXPECT_EQ(many.exit_code, 1);
  EXPECT_NE(many.err.find("holds 2 trials: name the one to fit on with --trial"), std::string::npos) << many.err;

  const CliRun fit =
      run_lmc("length-correction fit " + q + " --trial Naiv_Static101 --subject S01 -o " + shell_quote(file));
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  EXPECT_NE(fit.out.find("length correction for subject S01 from trial Naiv_Static101 (Vicon "), std::string::npos)
      << fit.out;
  EXPECT_NE(fit.out.find("  finger     fused mm  target mm  factor\n  thumb"), std::string::npos) << fit.out;
  const std::string json = lmc::test::read_text_file(file);
  EXPECT_NE(json.find("\"source\": \"vicon\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"fit_trial\": \"Naiv_Static101\""), std::string::npos) << json;

  const CliRun applied =
      run_lmc("process " + shell_quote((sim / "LMC_Naiv_Index101.raw.txt").string()) + " --length-correction " +
              shell_quote(file) + " -o " + shell_quote((dir / "out").string()));
  ASSERT_EQ(applied.exit_code, 0) << applied.all();
  EXPECT_NE(applied.out.find("length correction of subject S01 (fitted on Naiv_Static101, vicon): factors"),
            std::string::npos);
  EXPECT_NE(lmc::test::read_text_file(dir / "out" / "Naiv_Index101.summary.json").find("\"length_correction\""),
            std::string::npos);

  // lmc validate shows the corrected fusion as a third method beside the study's and ours.
  const CliRun validated = run_lmc("validate " + shell_quote((sim / "LMC_Naiv_Index101.raw.txt").string()) +
                                   " --length-correction " + shell_quote(file));
  ASSERT_EQ(validated.exit_code, 0) << validated.all();
  EXPECT_NE(validated.out.find("corrected = default fusion with the finger-length correction of subject S01 ("),
            std::string::npos)
      << validated.out;
  EXPECT_NE(validated.out.find("\n  default fusion "), std::string::npos) << validated.out;
  EXPECT_NE(validated.out.find("\n  corrected fusion "), std::string::npos) << validated.out;
  EXPECT_NE(validated.out.find("\n  corrected: finger RMSE (mm)"), std::string::npos) << validated.out;

  const CliRun reference = run_lmc("process " + q + " --method reference --length-correction " + shell_quote(file) +
                                   " -o " + shell_quote((dir / "ref").string()));
  EXPECT_EQ(reference.exit_code, 1);
  EXPECT_NE(reference.err.find("--length-correction applies to the default fusion only"), std::string::npos)
      << reference.err;
  const CliRun compare = run_lmc("process " + q + " --compare-methods --length-correction " + shell_quote(file) +
                                 " -o " + shell_quote((dir / "cmp").string()));
  EXPECT_EQ(compare.exit_code, 1);
  EXPECT_NE(compare.err.find("--compare-methods runs the reference method too"), std::string::npos) << compare.err;

  const CliRun hand = run_lmc("length-correction fit " + q +
                              " --trial Naiv_Static101 --subject S01 --hand-length-mm -5 "
                              "--hand-breadth-mm 80 -o " +
                              shell_quote((dir / "h.json").string()));
  EXPECT_EQ(hand.exit_code, 1);
  EXPECT_NE(hand.err.find(
                "give both --hand-length-mm and --hand-breadth-mm, each a positive length in mm (given -5.0 and 80.0)"),
            std::string::npos)
      << hand.err;

  std::ofstream(dir / "bad.json")
      << "{\"format\": \"lmc-length-correction\", \"version\": 1, \"method\": \"default\", "
         "\"subject\": \"S01\", \"source\": \"vicon\", \"fit_trial\": \"T\", \"factor\": [1.1, 1.2]}";
  const CliRun bad = run_lmc("process " + q + " --length-correction " + shell_quote((dir / "bad.json").string()) +
                             " -o " + shell_quote((dir / "bad").string()));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find((dir / "bad.json").string() + ": at /factor: expected 5 numbers"), std::string::npos)
      << bad.err;
  const CliRun bad_validate =
      run_lmc("validate " + q + " --length-correction " + shell_quote((dir / "bad.json").string()));
  EXPECT_EQ(bad_validate.exit_code, 1);
  EXPECT_NE(bad_validate.err.find((dir / "bad.json").string() + ": at /factor: expected 5 numbers"), std::string::npos)
      << bad_validate.err;
}

}  // namespace length_correction_cli_test
