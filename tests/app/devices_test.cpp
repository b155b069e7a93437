// Runs the real `lmc devices` binary (lmc::test::cli_path()) on the simulator, a replay and bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace {

using ::testing::HasSubstr;

using lmc::test::CliRun;
using lmc::test::read_text_file;
using lmc::test::run_lmc;

CliRun run(const std::string& args, const std::string& scratch) {
  return run_lmc(args, lmc::test::scratch_dir(scratch));
}

TEST(LmcDevices, SimulatorListsFourSerialsInTheirSlots) {
  const CliRun r = run("devices --backend sim --json", "devices_sim");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("backend"), "sim");
  EXPECT_EQ(j.at("layout"), "paper-initial");
  ASSERT_EQ(j.at("devices").size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const auto& d = j["devices"][static_cast<size_t>(i)];
    EXPECT_EQ(d.at("slot"), "LMC" + std::to_string(i + 1));
    EXPECT_EQ(d.at("backend"), "sim");
    EXPECT_THAT(d.at("serial").get<std::string>(), HasSubstr("SIM-LMC" + std::to_string(i + 1)));
    EXPECT_EQ(d.at("model"), "simulated Leap Motion Controller");
    EXPECT_EQ(d.at("tracking_mode"), "desktop") << "every controller of paper-initial looks up";
  }
  const CliRun text = run("devices", "devices_sim_text");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("4 devices on backend sim (layout paper-initial)"));
  EXPECT_THAT(text.out, HasSubstr("SERIAL"));
  EXPECT_THAT(text.out, HasSubstr("desktop"));
}

TEST(LmcDevices, ReplayListsTheRecordedDevices) {
  const auto path = lmc::test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const CliRun r =
      run("devices --json --backend " + lmc::test::shell_quote("replay:" + path.string()), "devices_replay");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("devices").size(), 4u);
  EXPECT_EQ(j["devices"][2].at("serial"), "REPLAY-LMC3");
  EXPECT_EQ(j["devices"][2].at("slot"), "LMC3");
}

TEST(LmcDevices, BadBackendOrMissingSdkIsAClearError) {
  const CliRun r = run("devices --backend usb", "devices_bad");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("unknown backend 'usb'"));
  const CliRun missing = run("devices --backend replay:/nonexistent/LMC_x.raw.txt", "devices_missing");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, HasSubstr("/nonexistent/LMC_x.raw.txt"));
}

}  // namespace
