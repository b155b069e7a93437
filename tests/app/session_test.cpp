// Runs the real `lmc session` the way a lab would: a whole quick session on the simulated rig then
// `lmc process` on it, the whole study protocol with short trials, a SIGKILL in the middle of a
// trial and the resume after it, refused subject ids, an unplugged controller and an unreachable
// Vicon host.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <thread>

#include "core/common/paths.h"
#include "core/io/lmc_recording.h"
#include "tests/support/cli_runner.h"
#include "tests/support/reference_data.h"

namespace session_cli_test {  // named: test files share unity batches

namespace fs = std::filesystem;
using lmc::test::CliRun;
using lmc::test::complete_rows;
using lmc::test::run_lmc;
using lmc::test::shell_quote;
using lmc::test::spawn_lmc;
using ::testing::HasSubstr;

const bool kPrivateStateDir = [] {
  const auto dir = lmc::test::scratch_dir("state");
  ::setenv("LMC_STATE_DIR", dir.c_str(), 1);
  return true;
}();

std::string q(const fs::path& p) {
  return shell_quote(p.string());
}

nlohmann::json status_of(const fs::path& session, const fs::path& logs) {
  const CliRun r = run_lmc("session status " + q(session) + " --json", logs);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

std::vector<nlohmann::json> journal_of(const fs::path& session) {
  std::vector<nlohmann::json> lines;
  std::ifstream in(session / "journal.jsonl");
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

TEST(LmcSession, QuickSessionRecordsEveryTrialWithAVerdictAndProcesses) {
  const auto dir = lmc::test::scratch_dir("session_quick");
  const fs::path session = dir / "S01";
  CliRun r = run_lmc("session new --subject S01 --protocol quick --hand-length-mm 185 -o " + q(session), dir / "l1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("Naiv_Static101"));
  EXPECT_THAT(r.out, HasSubstr("Naiv_Index101"));

  r = run_lmc("session run " + q(session) + " --backend sim --fast --auto --seed 3 --quiet", dir / "l2");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const nlohmann::json st = status_of(session, dir / "l3");
  EXPECT_EQ(st["subject"], "S01");
  EXPECT_EQ(st["protocol"], "quick");
  ASSERT_EQ(st["trials"].size(), 2U);
  for (const auto& t : st["trials"]) {
    EXPECT_EQ(t["status"], "accepted") << t.dump();
    EXPECT_EQ(t["attempts"], 1);
    ASSERT_TRUE(t["qc"].is_object());
    EXPECT_NE(t["qc"]["verdict"], "fail") << t.dump();
    const std::string name = t["name"];
    EXPECT_TRUE(fs::exists(session / ("LMC_" + name + ".raw.txt")));
    EXPECT_TRUE(fs::exists(session / ("LMC_" + name + ".session.json")));
    EXPECT_TRUE(fs::exists(session / (name + ".trc")));
  }
  // The manifest is the journal's digest: the same statuses.
  const auto manifest = nlohmann::json::parse(lmc::test::read_text_file(session / "session.json"));
  ASSERT_TRUE(manifest.contains("trials"));
  for (size_t k = 0; k < 2; ++k) EXPECT_EQ(manifest["trials"][k]["status"], st["trials"][k]["status"]);
  // The subject's hand length reached the simulator.
  const auto sidecar = nlohmann::json::parse(lmc::test::read_text_file(session / "LMC_Naiv_Static101.session.json"));
  EXPECT_DOUBLE_EQ(sidecar["extra"]["simulator"]["hand_length_mm"].get<double>(), 185.0);

  r = run_lmc("process " + q(session) + " -o " + q(dir / "processed"), dir / "l4");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("processed 2 of 2 trial(s)"));
  EXPECT_TRUE(fs::exists(dir / "processed" / "Naiv_Index101.summary.json"));

  // Running a finished session again records nothing.
  r = run_lmc("session run " + q(session) + " --backend sim --fast --auto --quiet", dir / "l5");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(status_of(session, dir / "l6")["trials"][0]["attempts"], 1);
}

TEST(LmcSession, WholeStudyProtocolWithShortTrialsGivesEightyAcceptedTrialsPairedWithTruth) {
  const auto dir = lmc::test::scratch_dir("session_study");
  const fs::path session = dir / "S02";
  CliRun r = run_lmc("session new --subject S02 --protocol study --seconds 2 -o " + q(session), dir / "l1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_lmc("session run " + q(session) + " --backend sim --fast --auto --quiet", dir / "l2");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const nlohmann::json st = status_of(session, dir / "l3");
  ASSERT_EQ(st["trials"].size(), 80U);
  std::set<std::string> names;
  for (const auto& t : st["trials"]) {
    const std::string name = t["name"];
    names.insert(name);
    EXPECT_EQ(t["status"], "accepted") << t.dump();
    EXPECT_TRUE(fs::exists(session / (name + ".trc"))) << name;
    EXPECT_TRUE(fs::exists(session / ("LMC_" + name + ".raw.txt"))) << name;
  }
  EXPECT_EQ(names.size(), 80U);
  // The study's names, block order: layout → pose → motion → repetitions.
  EXPECT_EQ(st["trials"][0]["name"], "Naiv_Static101");
  EXPECT_EQ(st["trials"][1]["name"], "Naiv_Static102");
  EXPECT_EQ(st["trials"][5]["name"], "Naiv_Index101");
  EXPECT_EQ(st["trials"][20]["name"], "Naiv_Static201");
  EXPECT_EQ(st["trials"][40]["name"], "Opti_Static101");
  EXPECT_EQ(st["trials"][79]["name"], "Opti_Wrist205");
}

TEST(LmcSession, KillMidTrialLosesAtMostASecondAndTheNextRunResumes) {
  const auto dir = lmc::test::scratch_dir("session_kill");
  const fs::path session = dir / "S03";
  ASSERT_EQ(run_lmc("session new --subject S03 --protocol quick --seconds 20 -o " + q(session), dir / "l1").exit_code,
            0);
  // Real time: the trial runs long enough to be killed in its middle.
  const pid_t child =
      spawn_lmc("session run " + q(session) + " --backend sim --auto --countdown 0 --quiet", dir / "l2");
  ASSERT_GT(child, 0);
  const fs::path raw = session / "LMC_Naiv_Static101.raw.txt";
  // Wait (generously) until the trial has written a few seconds of rows, then kill it hard.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline && (!fs::exists(raw) || complete_rows(raw) < 200))
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_TRUE(fs::exists(raw)) << "the trial never started";
  const size_t rows_seen = complete_rows(raw);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  ASSERT_EQ(::kill(child, SIGKILL), 0);
  int wstatus = 0;
  ::waitpid(child, &wstatus, 0);
  ASSERT_TRUE(WIFSIGNALED(wstatus));

  // Resume (fast from here): the interrupted trial is kept aside and recorded again.
  const CliRun r = run_lmc("session run " + q(session) + " --backend sim --fast --auto --quiet", dir / "l3");
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("Naiv_Static101 was cut off"));
  const fs::path kept = session / "superseded" / "Naiv_Static101.attempt1" / "LMC_Naiv_Static101.raw.txt";
  ASSERT_TRUE(fs::exists(kept));
  // Everything flushed up to a second before the kill reads back: at least what was there 1.5 s before it.
  const lmc::LmcRecording partial = lmc::read_lmc_recording(kept);
  EXPECT_GE(partial.rows.size(), rows_seen);
  EXPECT_TRUE(fs::exists(session / "superseded" / "Naiv_Static101.attempt1" / "LMC_Naiv_Static101.session.json"));

  const nlohmann::json st = status_of(session, dir / "l4");
  EXPECT_EQ(st["trials"][0]["status"], "accepted");
  EXPECT_EQ(st["trials"][0]["attempts"], 2);
  EXPECT_EQ(st["trials"][0]["attempt_history"][0]["outcome"], "interrupted");
  EXPECT_EQ(st["trials"][1]["status"], "accepted");
  EXPECT_EQ(st["trials"][1]["attempts"], 1);
  bool journaled = false;
  for (const auto& e : journal_of(session)) journaled = journaled || e.value("type", "") == "trial_interrupted";
  EXPECT_TRUE(journaled);
  const auto manifest = nlohmann::json::parse(lmc::test::read_text_file(session / "session.json"));
  EXPECT_EQ(manifest["trials"][0]["status"], "accepted");
}

TEST(LmcSession, ACalibratingProtocolCalibratesEachBlockFirstOrSkipsItWhenTold) {
  const auto dir = lmc::test::scratch_dir("session_calibrating");
  nlohmann::json protocol = nlohmann::json::parse(std::ifstream(lmc::assets_dir() / "protocols" / "quick.json"));
  protocol["name"] = "quick-calibrated";
  protocol["calibration"] = {{"duration_s", 3}};
  const fs::path protocol_file = dir / "quick-calibrated.json";
  std::ofstream(protocol_file) << protocol.dump();
  const fs::path sim = dir / "sim.json";
  std::ofstream(sim) << R"({"calibration_random_translation_mm": 25, "calibration_random_rotation_deg": 3})";
  for (const bool skip : {false, true}) {
    const fs::path session = dir / (skip ? "S02" : "S01");
    CliRun r = run_lmc("session new --subject " + std::string(skip ? "S02" : "S01") + " --protocol " +
                           q(protocol_file) + " --seconds 1 -o " + q(session),
                       dir / "new");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run_lmc("session run " + q(session) + " --auto --fast --quiet --sim-config " + q(sim) +
                    (skip ? " --skip-calibration 'rehearsal'" : ""),
                dir / "run");
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
    const nlohmann::json st = status_of(session, dir / "status");
    const auto& cal = st.at("calibration").at("Naiv");
    if (skip) {
      EXPECT_EQ(cal.at("status"), "nominal");
      EXPECT_THAT(cal.at("reason").get<std::string>(), HasSubstr("rehearsal"));
      EXPECT_FALSE(fs::exists(session / "LMC_Calib_Naiv01.raw.txt"));
    } else {
      EXPECT_THAT(r.out, HasSubstr("Residuals, RMS mm before > after calibration (against Vicon)"));
      EXPECT_EQ(cal.at("status"), "applied") << r.out;
      EXPECT_EQ(cal.at("trial"), "Calib_Naiv01");
      EXPECT_TRUE(fs::exists(session / "LMC_Calib_Naiv01.raw.txt"));
      EXPECT_THAT(r.out, HasSubstr("calibration of block Naiv: applied (Calib_Naiv01)"));
    }
    for (const auto& t : st.at("trials")) EXPECT_EQ(t.at("status"), "accepted") << t.dump();
  }
}

TEST(LmcSession, SubjectIdsThatCouldEscapeTheFolderAreRefused) {
  const auto dir = lmc::test::scratch_dir("session_ids");
  for (const std::string& bad :
       {std::string("../escape"), std::string("a/b"), std::string(200, 'x'), std::string("-rf")}) {
    const CliRun r =
        run_lmc("session new --subject " + shell_quote(bad) + " --protocol quick -o " + q(dir / "s"), dir / "l");
    EXPECT_NE(r.exit_code, 0) << bad;
    EXPECT_THAT(r.err, HasSubstr("subject")) << bad;
    EXPECT_FALSE(fs::exists(dir / "s")) << bad;
  }
}

TEST(LmcSession, AControllerUnpluggedMidTrialFailsTheVerdictNamingIt) {
  const auto dir = lmc::test::scratch_dir("session_unplug");
  const fs::path session = dir / "S04";
  ASSERT_EQ(run_lmc("session new --subject S04 --protocol quick -o " + q(session), dir / "l1").exit_code, 0);
  std::ofstream(dir / "sim.json") << R"({"unplugs": [{"slot": "LMC2", "at_s": 0.5, "duration_s": 2.0}]})";
  const CliRun r =
      run_lmc("session run " + q(session) + " --backend sim --fast --auto --quiet --sim-config " + q(dir / "sim.json"),
              dir / "l2");
  EXPECT_EQ(r.exit_code, 2) << r.out << r.err;  // ran, but trials failed
  const nlohmann::json st = status_of(session, dir / "l3");
  const auto& t = st["trials"][0];
  EXPECT_EQ(t["status"], "failed");
  EXPECT_EQ(t["attempts"], 2);  // --auto retries a failed trial once
  EXPECT_EQ(t["qc"]["verdict"], "fail");
  EXPECT_THAT(t["qc"]["reasons"].dump(), HasSubstr("LMC2"));
  // The failed attempts are all kept.
  EXPECT_TRUE(fs::exists(session / "superseded" / "Naiv_Static101.attempt1" / "LMC_Naiv_Static101.raw.txt"));
  EXPECT_TRUE(fs::exists(session / "LMC_Naiv_Static101.raw.txt"));
}

TEST(LmcSession, AnUnreachableViconHostFailsThePreflight) {
  const auto dir = lmc::test::scratch_dir("session_vicon");
  const fs::path session = dir / "S05";
  ASSERT_EQ(
      run_lmc("session new --subject S05 --protocol quick --vicon no-such-host.invalid -o " + q(session), dir / "l1")
          .exit_code,
      0);
  const CliRun r = run_lmc("session run " + q(session) + " --backend sim --fast --auto --quiet", dir / "l2");
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("[FAIL] Vicon target"));
  EXPECT_THAT(r.out, HasSubstr("no-such-host.invalid"));
  const nlohmann::json st = status_of(session, dir / "l3");
  EXPECT_EQ(st["trials"][0]["status"], "pending");
  EXPECT_EQ(st["trials"][0]["attempts"], 0);
  bool journaled = false;
  for (const auto& e : journal_of(session)) journaled = journaled || e.value("type", "") == "preflight";
  EXPECT_TRUE(journaled);
}

}  // namespace session_cli_test
