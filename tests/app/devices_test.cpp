// Runs the real `lmc devices` binary (LMC_CLI_PATH) on the simulator, a replay and bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tests/support/reference_data.h"

namespace {

using ::testing::HasSubstr;

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string quote(const std::string& s) {
  std::string q = "'";
  for (const char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

RunResult run(const std::string& args, const std::string& scratch) {
  const auto dir = lmc::test::scratch_dir(scratch);
  const std::string cmd = quote(LMC_CLI_PATH) + " " + args + " >" + quote((dir / "out").string()) + " 2>" +
                          quote((dir / "err").string());
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "out"), slurp(dir / "err")};
}

TEST(LmcDevices, SimulatorListsFourSerialsInTheirSlots) {
  const RunResult r = run("devices --backend sim --json", "devices_sim");
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
  }
  const RunResult text = run("devices", "devices_sim_text");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("4 devices on backend sim (layout paper-initial)"));
  EXPECT_THAT(text.out, HasSubstr("SERIAL"));
}

TEST(LmcDevices, ReplayListsTheRecordedDevices) {
  const auto path = lmc::test::reference_file("acquisition/LMC_Naiv_Static101.raw.txt");
  LMC_REQUIRE_REFERENCE_FILE(path);
  const RunResult r = run("devices --json --backend " + quote("replay:" + path.string()), "devices_replay");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("devices").size(), 4u);
  EXPECT_EQ(j["devices"][2].at("serial"), "REPLAY-LMC3");
  EXPECT_EQ(j["devices"][2].at("slot"), "LMC3");
}

TEST(LmcDevices, BadBackendOrMissingSdkIsAClearError) {
  const RunResult r = run("devices --backend usb", "devices_bad");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("unknown backend 'usb'"));
  const RunResult missing = run("devices --backend replay:/nonexistent/LMC_x.raw.txt", "devices_missing");
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_THAT(missing.err, HasSubstr("/nonexistent/LMC_x.raw.txt"));
}

}  // namespace
