// `lmc calibrate` end to end: a simulated still-hand trial recorded with errors in the
// controllers' placement, calibrated against its ground-truth TRC and without it; bad inputs.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace calibrate_test {

// Records Naiv_Static101 on the simulator with seeded errors of up to 40 mm and 6° per controller.
std::filesystem::path record_trial(const std::filesystem::path& dir) {
  const auto config = dir / "sim.json";
  std::ofstream(config) << R"({"calibration_random_translation_mm": 40, "calibration_random_rotation_deg": 6})";
  const auto r = lmc::test::run_lmc(
      "record --backend sim --fast --quiet --seconds 6 --seed 4 --layout paper-initial --trial Naiv_Static101 "
      "--motion static --sim-config " +
      config.string() + " -o " + (dir / "S").string());
  EXPECT_EQ(r.exit_code, 0) << r.all();
  return dir / "S";
}

}  // namespace calibrate_test

TEST(CalibrateCli, CalibratesASimulatedTrialWithAndWithoutVicon) {
  const auto dir = lmc::test::scratch_dir("calibrate_cli");
  const auto session = calibrate_test::record_trial(dir);
  const auto trial = session / "LMC_Naiv_Static101.raw.txt";
  ASSERT_TRUE(std::filesystem::exists(trial));
  const auto out = dir / "calibrated.json";
  const auto r =
      lmc::test::run_lmc("calibrate " + trial.string() + " --vicon " + (session / "Naiv_Static101.trc").string() +
                         " --layout paper-initial -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.all();
  EXPECT_NE(r.out.find("against Vicon"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("grid lined up with Vicon frame 0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("4 of 4 controllers calibrated"), std::string::npos) << r.out;
  const auto layout = nlohmann::json::parse(lmc::test::read_text_file(out));
  EXPECT_EQ(layout["name"], "paper-initial (calibrated)");
  EXPECT_NE(layout["description"].get<std::string>().find("from trial Naiv_Static101 against Vicon file"),
            std::string::npos);
  // The calibrated layout is a layout like any other: `lmc info` reads it.
  const auto info = lmc::test::run_lmc("info " + out.string());
  EXPECT_EQ(info.exit_code, 0) << info.all();

  const auto plain = dir / "consensus.json";
  const auto c = lmc::test::run_lmc("calibrate " + trial.string() + " --layout paper-initial -o " + plain.string());
  ASSERT_EQ(c.exit_code, 0) << c.all();
  EXPECT_NE(c.out.find("against the other controllers"), std::string::npos) << c.out;
  EXPECT_NE(c.out.find("Naiv_Static101.trc lies next to the trial"), std::string::npos) << c.out;
  EXPECT_TRUE(std::filesystem::exists(plain));
}

TEST(CalibrateCli, BadInputsNameTheFile) {
  const auto dir = lmc::test::scratch_dir("calibrate_cli_bad");
  const auto missing = dir / "LMC_Nothing.raw.txt";
  auto r =
      lmc::test::run_lmc("calibrate " + missing.string() + " --layout paper-initial -o " + (dir / "o.json").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(missing.string() + ": no such file"), std::string::npos) << r.err;

  const auto broken = dir / "LMC_Broken.raw.txt";
  std::ofstream(broken) << "not a recording\n";
  r = lmc::test::run_lmc("calibrate " + broken.string() + " --layout paper-initial -o " + (dir / "o.json").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(broken.string()), std::string::npos) << r.err;

  r = lmc::test::run_lmc("calibrate " + broken.string() + " --vicon " + (dir / "none.trc").string() +
                         " --layout paper-initial -o " + (dir / "o.json").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("none.trc: no such Vicon file"), std::string::npos) << r.err;

  r = lmc::test::run_lmc("calibrate " + broken.string() + " -o " + (dir / "o.json").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("give --layout"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "o.json"));
}
