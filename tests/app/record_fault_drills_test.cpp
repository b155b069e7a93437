// Fault drills for `lmc record` run as a user would, each with the exact outcome it
// expects: killed with SIGKILL mid-trial, and pointed at a folder it may not write.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <string>
#include <thread>
#include <tuple>

#include "core/io/lmc_recording.h"
#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace record_fault_drills_test {

namespace fs = std::filesystem;
using lmc::test::CliRun;
using lmc::test::complete_rows;
using lmc::test::run_lmc;
using lmc::test::shell_quote;
using lmc::test::spawn_lmc;
using ::testing::HasSubstr;

std::string q(const fs::path& p) {
  return shell_quote(p.string());
}

// Rows keyed by device and device timestamp: the simulator's rows are the same whatever the pace
// (real time or --fast) for one seed, so a killed real-time trial can be compared row by row.
using RowKey = std::tuple<int, std::int64_t>;
std::map<RowKey, lmc::HandFrame> rows_by_key(const lmc::LmcRecording& rec) {
  std::map<RowKey, lmc::HandFrame> out;
  for (const auto& r : rec.rows) out.emplace(RowKey{r.device_id, r.timestamp_us}, r);
  return out;
}

TEST(RecordFaultDrills, SigkillMidTrialKeepsEveryRowUpToASecondBeforeAndInfoSaysItWasCutOff) {
  const auto dir = lmc::test::scratch_dir("record_kill");
  const std::string common = "record --backend sim --seed 11 --trial Naiv_Wrist101 --seconds 30 --quiet";
  const pid_t child = spawn_lmc(common + " -o " + q(dir / "killed"), dir / "l1");
  ASSERT_GT(child, 0);
  const fs::path raw = dir / "killed" / "LMC_Naiv_Wrist101.raw.txt";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);  // a hang guard only
  while (std::chrono::steady_clock::now() < deadline && (!fs::exists(raw) || complete_rows(raw) < 300))
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(fs::exists(raw)) << "the trial never started";
  // What is on disk now was generated more than a second before the kill below: it must all stay.
  const size_t rows_before = complete_rows(raw);
  std::this_thread::sleep_for(std::chrono::milliseconds(1200));
  ASSERT_EQ(::kill(child, SIGKILL), 0);
  int wstatus = 0;
  ::waitpid(child, &wstatus, 0);
  ASSERT_TRUE(WIFSIGNALED(wstatus));

  // The same seed, run to the end at full speed: what the simulator generated.
  const CliRun full = run_lmc(common + " --fast -o " + q(dir / "full"), dir / "l2");
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const auto reference = rows_by_key(lmc::read_lmc_recording(dir / "full" / "LMC_Naiv_Wrist101.raw.txt"));

  const lmc::LmcRecording killed = lmc::read_lmc_recording(raw);  // a cut last line is dropped, not an error
  ASSERT_GE(killed.rows.size(), rows_before);
  // Every row that reached the file is the simulator's row, unchanged...
  std::int64_t last_us = 0;
  for (const auto& r : killed.rows) {
    const auto it = reference.find({r.device_id, r.timestamp_us});
    ASSERT_NE(it, reference.end()) << "row of LMC" << r.device_id << " at " << r.timestamp_us
                                   << " µs was not generated";
    EXPECT_EQ(it->second.points[0], r.points[0]) << "row of LMC" << r.device_id << " at " << r.timestamp_us;
    last_us = std::max(last_us, r.timestamp_us);
  }
  // ...and none is missing up to a second before the last one written: no hole, only a tail.
  const auto killed_rows = rows_by_key(killed);
  for (const auto& [key, frame] : reference) {
    if (std::get<1>(key) > last_us - 1'000'000) continue;
    EXPECT_TRUE(killed_rows.count(key)) << "row of LMC" << std::get<0>(key) << " at " << std::get<1>(key)
                                        << " µs was lost";
  }

  const CliRun info = run_lmc("info " + q(dir / "killed" / "LMC_Naiv_Wrist101.session.json"), dir / "l3");
  EXPECT_THAT(info.all(), HasSubstr("status is still \"recording\": the program stopped before the trial was closed"));
}

TEST(RecordFaultDrills, AFolderItMayNotWriteIsRefusedNamingTheFileAndLeavesNothingHalfWritten) {
  const auto dir = lmc::test::scratch_dir("record_read_only");
  const fs::path ro = dir / "read-only";
  fs::create_directories(ro);
  ASSERT_EQ(::chmod(ro.c_str(), 0555), 0);
  // Root writes anywhere: the drill runs lmc as an unprivileged user then (setpriv, util-linux).
  const std::string launcher = ::geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups" : "";
  const CliRun as_nobody = run_lmc("record --backend sim --fast --seconds 1 --trial Naiv_Static101 --quiet -o " + q(ro),
                                   dir / "logs", "", launcher);
  EXPECT_NE(as_nobody.exit_code, 0);
  EXPECT_THAT(as_nobody.err, HasSubstr(ro.string()));
  EXPECT_THAT(as_nobody.err, HasSubstr("Permission denied"));
  EXPECT_TRUE(fs::is_empty(ro)) << "nothing may be left behind in a folder the trial could not use";
  ::chmod(ro.c_str(), 0755);
  fs::remove_all(dir);
}

}  // namespace record_fault_drills_test
