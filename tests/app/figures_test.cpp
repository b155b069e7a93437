// `lmc figures` on two quick simulated subjects: the agreement table, a Bland–Altman
// plot per group and measure, the visibility map and the study's tables, each figure with its CSV
// and sidecar; a trial's figure on request; the second run comes from the processing cache; NaN
// never becomes 0 in any export; an unknown --trial is an error naming it.
#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/cli_runner.h"
#include "tests/support/quick_session.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace figures_cli_test {  // named: test files share unity batches

namespace fs = std::filesystem;
using test::CliRun;
using test::run_lmc;
using test::shell_quote;

TEST(LmcFigures, WritesTheAgreementFiguresAndTablesAndReusesTheCache) {
  const fs::path dir = test::scratch_dir("lmc_figures");
  ASSERT_EQ(test::record_quick_session(dir / "S01", dir / "l" / "S01", "S01", 1), "");
  ASSERT_EQ(test::record_quick_session(dir / "S02", dir / "l" / "S02", "S02", 2), "");
  const std::string cache = test::env_prefix("LMC_CACHE_DIR", (dir / "cache").string());
  const fs::path out = dir / "out";
  const std::string args = "figures " + shell_quote((dir / "S01").string()) + " " +
                           shell_quote((dir / "S02").string()) + " --trial Naiv_Index101 -o " +
                           shell_quote(out.string());
  CliRun r = run_lmc(args, dir / "l", cache);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_NE(r.out.find("figures of 4 trial(s) (0 from the cache, 0 failed)"), std::string::npos) << r.out;
  for (const char* f :
       {"agreement.csv", "agreement.json", "visibility-map.svg", "visibility-map.csv", "visibility-map.json",
        "visibility-map-table.csv", "study-tables.md", "study-finger-length.csv",
        "bland-altman-all-all-finger_length_index.svg", "bland-altman-initial-horizontal-rom_index_mcp.csv",
        "trial-s01-naiv_index101.svg", "trial-s01-naiv_index101.json", "trial-s02-naiv_index101.series.csv"}) {
    ASSERT_TRUE(fs::exists(out / f)) << f << "\n" << r.all();
    EXPECT_GT(fs::file_size(out / f), 100u) << f;
  }
  const std::string svg = test::read_text_file(out / "bland-altman-all-all-finger_length_index.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("S02"), std::string::npos);  // points of both subjects, named in the legend
  // Two subjects with two trials each: the repeated-measures form, and real numbers in the table.
  const std::string agreement = test::read_text_file(out / "agreement.csv");
  EXPECT_NE(agreement.find("repeated"), std::string::npos) << agreement.substr(0, 600);
  for (const fs::path& p : fs::directory_iterator(out)) {
    if (p.extension() != ".csv") continue;
    const std::string text = test::read_text_file(p);
    EXPECT_EQ(text.find("nan"), std::string::npos) << p;
    EXPECT_EQ(text.find("NaN"), std::string::npos) << p;
  }
  // Again: every trial from the cache.
  r = run_lmc(args, dir / "l", cache);
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_NE(r.out.find("(4 from the cache, 0 failed)"), std::string::npos) << r.out;
  r = run_lmc("figures " + shell_quote((dir / "S01").string()) + " --trial Nope101 -o " + shell_quote(out.string()),
              dir / "l", cache);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--trial Nope101: no such trial"), std::string::npos) << r.all();
}

}  // namespace figures_cli_test
}  // namespace lmc
