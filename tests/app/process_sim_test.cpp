// End to end on the simulator: `lmc record --backend
// sim --fast` writes trials with known truth (<trial>.trc), `lmc process --compare-methods` fuses
// them with both methods and prints each method's RMSE against truth; the default method must
// beat the reference method overall and on frames some device could not see. Then `lmc report`
// aggregates the session. Short trials keep this quick; the README figures come from the full
// simulated subject (see the processing report).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace lmc {
namespace {

using lmc::test::CliRun;

// Both streams together: these tests look for per-trial messages wherever they were printed.
CliRun run(const std::string& args) {
  return lmc::test::run_lmc(args);
}

// The four RMSE cells of a table row: reference all, default all, reference not seen, default not seen.
std::array<double, 4> row_values(const std::string& table, const std::string& row_name) {
  std::istringstream in(table);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| " + row_name + " (", 0) != 0) continue;
    std::array<double, 4> v{};
    std::istringstream ls(line);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(ls, cell, '|')) cells.push_back(cell);
    // cells[0] empty, [1] name, [2..5] values.
    for (size_t k = 0; k < 4; ++k) v[k] = std::stod(cells.at(k + 2));
    return v;
  }
  ADD_FAILURE() << "row '" << row_name << "' not in table:\n" << table;
  return {};
}

TEST(ProcessSim, DefaultMethodBeatsReferenceOnSimulatedTruth) {
  const auto dir = test::scratch_dir("process_sim");
  const auto session = dir / "S01";
  for (const char* spec : {"Naiv_Index101 horizontal/index", "Opti_Thumb201 vertical/thumb"}) {
    std::istringstream s(spec);
    std::string trial, motion;
    s >> trial >> motion;
    const std::string layout = trial.rfind("Naiv", 0) == 0 ? "paper-initial" : "paper-optimized";
    const CliRun r = run("record --backend sim --fast --quiet --seconds 3 --seed 7 --layout " + layout + " --trial " +
                         trial + " --motion " + motion + " -o " + session.string());
    ASSERT_EQ(r.exit_code, 0) << r.all();
  }
  const auto out = dir / "out";
  const CliRun p = run("process " + session.string() + " --compare-methods -o " + out.string());
  ASSERT_EQ(p.exit_code, 0) << p.all();
  EXPECT_NE(p.all().find("processed 2 of 2 trial(s)"), std::string::npos) << p.all();
  EXPECT_NE(p.all().find("(recorded layout)"), std::string::npos) << p.all();
  const auto fingers = row_values(p.all(), "finger length, all fingers");
  const auto angles = row_values(p.all(), "joint angle, all joints");
  EXPECT_LT(fingers[1], fingers[0]) << p.all();
  EXPECT_LT(fingers[3], fingers[2]) << p.all();
  EXPECT_LT(angles[1], angles[0]) << p.all();
  EXPECT_LT(angles[3], angles[2]) << p.all();
  // The default method is close to truth on this simulator (noise ≈1 mm, guesses down-weighted).
  EXPECT_LT(fingers[1], 5.0) << p.all();
  EXPECT_TRUE(std::filesystem::exists(out / "method_comparison.md"));

  const CliRun rep = run("report " + out.string() + " -o " + (dir / "report").string());
  ASSERT_EQ(rep.exit_code, 0) << rep.all();
  std::ifstream md(dir / "report" / "report.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("| optimized | vertical | thumb |"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("| initial | horizontal | index |"), std::string::npos) << text.str();
}

}  // namespace
}  // namespace lmc
