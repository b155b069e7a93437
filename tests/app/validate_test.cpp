// `lmc validate`: real recordings first, then simulated ones; the reference method's
// finger lengths on the shared real trial are the authors' (ReferenceParity), so its rows are fixed.
#include <gtest/gtest.h>

#include <string>

#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace validate_cli_test {

using lmc::test::CliRun;
using lmc::test::run_lmc;
using lmc::test::shell_quote;

TEST(LmcValidate, RealDataRowsComeFirstAndReproduceThePublishedTrial) {
  const auto dir = lmc::test::scratch_dir("validate");
  const auto lmc_file = lmc::test::reference_file("validation/Interp_LMC_Naiv_Static101.txt");
  const auto trc = lmc::test::reference_file("validation/Naiv_Static101.trc");
  LMC_REQUIRE_REFERENCE_FILE(lmc_file);
  const auto sim = dir / "sim";
  const CliRun rec = run_lmc(
      "record --backend sim --fast --quiet --seconds 2 --seed 4 --layout paper-initial --trial "
      "Naiv_Static101 --motion horizontal/static -o " +
          shell_quote(sim.string()),
      dir / "rec");
  ASSERT_EQ(rec.exit_code, 0) << rec.err;
  // The simulated trial is named first on the command line; its rows still come last.
  const CliRun r = run_lmc("validate " + shell_quote(sim.string()) + " " + shell_quote(lmc_file.string()) +
                               " --vicon " + shell_quote(trc.string()) + " --layout paper-initial",
                           dir / "validate");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto real = r.out.find("REAL DATA: Naiv_Static101 (50 frames, layout paper-initial, with Vicon)");
  const auto simulated = r.out.find("SIMULATOR: Naiv_Static101");
  ASSERT_NE(real, std::string::npos) << r.out;
  ASSERT_NE(simulated, std::string::npos) << r.out;
  EXPECT_LT(real, simulated);
  const std::string block = r.out.substr(real, simulated - real);
  // Vicon's and the reference fusion's mean finger lengths as the issue measured them (mm).
  EXPECT_NE(block.find("Vicon                                       55.0    84.7   100.1    91.6    76.3"),
            std::string::npos)
      << block;
  EXPECT_NE(block.find("reference fusion                            47.8    77.1    82.5    76.3    60.4"),
            std::string::npos)
      << block;
  EXPECT_NE(block.find("median of the seeing controllers"), std::string::npos);
  EXPECT_NE(block.find("default: fused - median (mm)"), std::string::npos);
  EXPECT_NE(block.find("reference: RMSE"), std::string::npos);
}

}  // namespace validate_cli_test
