// Runs the built `lmc visibility` (lmc::test::cli_path()) on the studys validation trial.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace {

using lmc::test::CliRun;
using lmc::test::read_text_file;
using lmc::test::run_lmc;

}  // namespace

#include "core/io/lmc_recording.h"

namespace {

TEST(LmcVisibility, ReproducesTheAuthorsLabelsForAllRows) {
  const auto input = lmc::test::reference_file("validation/Interp_LMC_Naiv_Static101.txt");
  const auto expected = lmc::test::reference_file("validation/Interp_LMC_Naiv_Static101.raytraced.txt");
  LMC_REQUIRE_REFERENCE_FILE(input);
  LMC_REQUIRE_REFERENCE_FILE(expected);
  const auto dir = lmc::test::scratch_dir("cli_visibility");
  const auto out = dir / "labels.txt";
  const CliRun r = run_lmc(
      "visibility " + lmc::test::shell_quote(input.string()) + " -o " + lmc::test::shell_quote(out.string()), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const lmc::LmcRecording got = lmc::read_lmc_recording(out);
  const lmc::LmcRecording want = lmc::read_lmc_recording(expected);
  ASSERT_EQ(got.visibility.size(), want.visibility.size());
  int labels = 0;
  for (size_t i = 0; i < got.visibility.size(); ++i) {
    for (size_t k = 0; k < 5; ++k) {
      EXPECT_EQ(got.visibility[i][k], want.visibility[i][k]) << "row " << i + 1;
      ++labels;
    }
    EXPECT_EQ(got.rows[i].points, want.rows[i].points);
  }
  EXPECT_EQ(labels, 1000);
}

TEST(LmcVisibility, ShorterRangeHidesAndExplains) {
  const auto input = lmc::test::reference_file("validation/Interp_LMC_Naiv_Static101.txt");
  LMC_REQUIRE_REFERENCE_FILE(input);
  const auto dir = lmc::test::scratch_dir("cli_visibility_range");
  const auto out = dir / "labels.txt";
  const CliRun r = run_lmc("visibility " + lmc::test::shell_quote(input.string()) + " --range-mm 250 --explain -o " +
                               lmc::test::shell_quote(out.string()),
                           dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("out of range"), std::string::npos);
  const lmc::LmcRecording got = lmc::read_lmc_recording(out);
  int hidden = 0;
  for (const auto& l : got.visibility) hidden += l[0] == 0;
  EXPECT_GT(hidden, 0);
}

TEST(LmcVisibility, BadInputNamesTheFile) {
  const auto dir = lmc::test::scratch_dir("cli_visibility_bad");
  {
    std::ofstream bad(dir / "bad.txt");
    bad << "not a recording\n1\t2\n";
  }
  const CliRun r = run_lmc("visibility " + lmc::test::shell_quote((dir / "bad.txt").string()) + " -o " +
                               lmc::test::shell_quote((dir / "o.txt").string()),
                           dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.txt"), std::string::npos) << r.err;
}

}  // namespace
