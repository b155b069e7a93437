// `lmc export bids` (core/export/bids_dataset.h) on a small simulated study of two subjects (the
// quick protocol, 1 s trials): the dataset's file names, channel rows, motion.json fields, events
// and participants as documented, no operator field anywhere, anonymised labels with the key kept
// outside the dataset (a key inside it refused before anything is written), a cancel part-way that
// leaves a dataset whose every listed file exists, a non-empty folder refused without --force, and
// a session with an unsafe subject id refused with a message naming its file, and two sessions of
// one subject written as BIDS sessions.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/common/error.h"
#include "core/export/bids_dataset.h"
#include "core/io/recorder_sidecar.h"
#include "tests/support/cli_runner.h"
#include "tests/support/scratch_dir.h"

namespace lmc {
namespace bids_export_test {  // named: test files share unity batches

namespace fs = std::filesystem;
using test::CliRun;
using test::read_text_file;
using test::run_lmc;
using test::shell_quote;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> cells_of(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, '\t');) cells.push_back(cell);
  return cells;
}

nlohmann::json read_json(const fs::path& p) {
  return nlohmann::json::parse(read_text_file(p));
}

// Two subject sessions recorded once for every test: S_01 (a '_' the BIDS label drops) and S02. A
// study folder's sessions go in name order: S02 before S_01 ('0' sorts before '_').
class BidsExport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = new fs::path(test::scratch_dir("lmc_bids_export"));
    for (const char* subject : {"S_01", "S02"}) {
      const fs::path s = study() / subject;
      CliRun r = run_lmc(std::string("session new --subject ") + subject +
                             " --protocol quick --seconds 1 --hand-length-mm 185 " +
                             "--hand-breadth-mm 84 --operator " + shell_quote("Operator Olga") + " --notes " +
                             shell_quote("private remark") + " -o " + shell_quote(s.string()),
                         *root_ / "l");
      ASSERT_EQ(r.exit_code, 0) << r.all();
      r = run_lmc("session run " + shell_quote(s.string()) + " --backend sim --fast --auto --quiet --seed 3",
                  *root_ / "l");
      ASSERT_EQ(r.exit_code, 0) << r.all();
    }
  }
  static void TearDownTestSuite() {
    delete exported_;
    exported_ = nullptr;
    delete root_;
    root_ = nullptr;
  }
  static fs::path study() { return *root_ / "study"; }
  static BidsExportRequest request(const std::string& out) {
    BidsExportRequest req;
    req.inputs = {study()};
    req.out_dir = *root_ / out;
    return req;
  }
  // The study exported once with the default settings, for the tests that read what it wrote.
  struct Exported {
    fs::path dir;
    BidsExportReport report;
    std::vector<std::pair<int, int>> progress;  // each on_progress call: done, total
  };
  static const Exported& documented() {
    if (exported_ == nullptr) {
      auto e = std::make_unique<Exported>();
      BidsExportRequest req = request("dataset");
      req.on_progress = [&e](int done, int total) { e->progress.emplace_back(done, total); };
      e->report = export_bids(req);
      e->dir = req.out_dir;
      exported_ = e.release();
    }
    return *exported_;
  }
  static fs::path motion_file(const std::string& system, const std::string& suffix) {
    return documented().dir / "sub-S01" / "motion" /
           ("sub-S01_task-Index_tracksys-" + system + "_acq-Naiv_run-101" + suffix);
  }
  static fs::path* root_;
  static Exported* exported_;
};
fs::path* BidsExport::root_ = nullptr;
BidsExport::Exported* BidsExport::exported_ = nullptr;

TEST_F(BidsExport, ReportsEveryTrialOfBothSubjectsWithItsProgress) {
  const BidsExportReport& report = documented().report;
  EXPECT_EQ(report.subjects, 2);
  EXPECT_EQ(report.trials, 4);
  EXPECT_EQ(report.left_out, 0);
  EXPECT_FALSE(report.cancelled);
  EXPECT_EQ(documented().progress, (std::vector<std::pair<int, int>>{{0, 4}, {1, 4}, {2, 4}, {3, 4}, {4, 4}}));
}

TEST_F(BidsExport, WritesEveryTrackingSystemsFilesAndTheLayouts) {
  const fs::path ds = documented().dir;
  for (const char* system : {"LMCfused", "LMC1", "LMC2", "LMC3", "LMC4", "Vicon"}) {
    for (const char* suffix : {"_motion.tsv", "_motion.json", "_channels.tsv", "_channels.json"}) {
      EXPECT_TRUE(fs::exists(motion_file(system, suffix))) << motion_file(system, suffix);
    }
  }
  EXPECT_TRUE(fs::exists(ds / "sub-S02" / "motion" / "sub-S02_task-Static_tracksys-Vicon_acq-Naiv_run-101_motion.tsv"));
  EXPECT_TRUE(fs::exists(ds / "layouts" / "sub-S01_acq-Naiv_layout.json"));
  EXPECT_EQ(read_json(ds / "layouts" / "sub-S01_acq-Naiv_layout.json")["devices"].size(), 4u);
}

TEST_F(BidsExport, ChannelsAndMotionRowsAreAsDocumented) {
  // Channels: 28 points × x, y, z of type POS in mm.
  const std::vector<std::string> channels = lines_of(read_text_file(motion_file("LMC2", "_channels.tsv")));
  ASSERT_EQ(channels.size(), 85u);
  EXPECT_EQ(cells_of(channels[1]),
            (std::vector<std::string>{"Palm_x", "x", "POS", "Palm", "mm", "world", "LMC2 realigned: palm position"}));
  // Motion rows: as many as the recording lasts at 100 Hz, 84 cells each, no header.
  const nlohmann::json mj = read_json(motion_file("LMC2", "_motion.json"));
  const std::vector<std::string> rows = lines_of(read_text_file(motion_file("LMC2", "_motion.tsv")));
  EXPECT_NEAR(static_cast<double>(rows.size()), mj["RecordingDuration"].get<double>() * 100.0, 1e-6);
  EXPECT_GE(rows.size(), 90u);
  // Every cell a number in mm with three decimals or n/a (a controller that had not seen the hand).
  int numbers = 0, missing = 0;
  for (const auto& row : rows) {
    const std::vector<std::string> cells = cells_of(row);
    ASSERT_EQ(cells.size(), 84u);
    for (const auto& c : cells) {
      if (c == "n/a") {
        ++missing;
        continue;
      }
      size_t used = 0;
      std::stod(c, &used);
      EXPECT_EQ(used, c.size()) << c;
      EXPECT_EQ(c.size() - c.find('.'), 4u) << c;
      ++numbers;
    }
  }
  EXPECT_GT(numbers, 84 * 50);
  EXPECT_EQ(missing % 3, 0) << "a point is missing with all three coordinates";
}

TEST_F(BidsExport, MotionJsonSaysWhatTheSidecarSays) {
  const nlohmann::json mj = read_json(motion_file("LMC2", "_motion.json"));
  const RecorderSidecar sidecar = read_recorder_sidecar(study() / "S_01" / "LMC_Naiv_Index101.session.json");
  ASSERT_NE(sidecar.device(2), nullptr);
  EXPECT_EQ(mj["DeviceSerialNumber"], sidecar.device(2)->serial);
  EXPECT_EQ(mj["TaskName"], "Index");
  EXPECT_EQ(mj["SamplingFrequency"], 100.0);
  EXPECT_EQ(mj["Manufacturer"], "Ultraleap");
  EXPECT_EQ(mj["ManufacturersModelName"], "simulated Leap Motion Controller");
  EXPECT_EQ(mj["MissingValues"], "n/a");
  EXPECT_NE(mj["SoftwareVersions"].get<std::string>().find("lmc-workbench " LMC_VERSION), std::string::npos);
  EXPECT_EQ(read_json(motion_file("Vicon", "_motion.json"))["Manufacturer"], "Vicon");
}

TEST_F(BidsExport, EventsAreGoTheSimulatedViconsTimeZeroAndStop) {
  const std::vector<std::string> events = lines_of(
      read_text_file(documented().dir / "sub-S01" / "motion" / "sub-S01_task-Index_acq-Naiv_run-101_events.tsv"));
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(events[0], "onset\tduration\ttrial_type");
  std::set<std::string> types;
  for (size_t i = 1; i < events.size(); ++i) types.insert(cells_of(events[i])[2]);
  EXPECT_EQ(types, (std::set<std::string>{"go", "stop", "vicon_capture_start"}));
  // The Vicon's time zero is where the grid starts.
  for (size_t i = 1; i < events.size(); ++i) {
    if (cells_of(events[i])[2] == "vicon_capture_start") {
      EXPECT_EQ(cells_of(events[i])[0], "0.000");
    }
  }
}

TEST_F(BidsExport, ParticipantsAndScansComeFromTheManifestsWithoutOperatorOrNotes) {
  const fs::path ds = documented().dir;
  EXPECT_EQ(read_text_file(ds / "participants.tsv"),
            "participant_id\thandedness\thand_length_mm\thand_breadth_mm\nsub-S02\tright\t185.0\t84.0\nsub-"
            "S01\tright\t185.0\t84.0\n");
  const std::vector<std::string> scans = lines_of(read_text_file(ds / "sub-S01" / "sub-S01_scans.tsv"));
  ASSERT_EQ(scans.size(), 1u + 2 * 6);
  for (size_t i = 1; i < scans.size(); ++i) EXPECT_TRUE(fs::exists(ds / "sub-S01" / cells_of(scans[i])[0])) << scans[i];
  EXPECT_EQ(read_json(ds / "dataset_description.json")["GeneratedBy"][0]["Name"], "lmc-workbench");
  for (const auto& e : fs::recursive_directory_iterator(ds)) {
    if (!e.is_regular_file()) continue;
    const std::string text = read_text_file(e.path());
    EXPECT_EQ(text.find("Olga"), std::string::npos) << e.path();
    EXPECT_EQ(text.find("private remark"), std::string::npos) << e.path();
  }
}

TEST_F(BidsExport, ASecondExportNeedsForceWhichReplacesTheEarlierSubjects) {
  BidsExportRequest req = request("dataset-again");
  EXPECT_EQ(export_bids(req).trials, 4);
  EXPECT_THROW(export_bids(req), Error);
  req.force = true;
  req.inputs = {study() / "S02"};
  EXPECT_EQ(export_bids(req).trials, 2);
  EXPECT_FALSE(fs::exists(req.out_dir / "sub-S01")) << "an earlier export's subject stays without a participants row";
  EXPECT_EQ(lines_of(read_text_file(req.out_dir / "participants.tsv")).size(), 2u);
}

TEST_F(BidsExport, AnonymisesWithTheKeyOutsideTheDataset) {
  BidsExportRequest req = request("anonymous");
  req.anonymise = true;
  req.anonymise_key = req.out_dir / "key.tsv";
  try {
    export_bids(req);
    ADD_FAILURE() << "a key inside the dataset was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("must lie outside the dataset folder"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(req.out_dir)) << "nothing is written when the key is refused";

  req.anonymise_key = req.out_dir.parent_path() / "keys" / "anonymous-key.tsv";
  const BidsExportReport report = export_bids(req);
  EXPECT_EQ(report.trials, 4);
  EXPECT_TRUE(fs::exists(req.out_dir / "sub-01" / "motion" /
                         "sub-01_task-Static_tracksys-LMCfused_acq-Naiv_run-101_motion.tsv"));
  EXPECT_TRUE(fs::exists(req.out_dir / "sub-02"));
  const std::vector<std::string> key = lines_of(read_text_file(req.anonymise_key));
  ASSERT_EQ(key.size(), 3u);
  EXPECT_EQ(key[0], "participant_id\tsubject_id\tsession_folder");
  EXPECT_EQ(cells_of(key[1])[0], "sub-01");
  EXPECT_EQ(cells_of(key[1])[1], "S02");
  EXPECT_EQ(cells_of(key[2])[1], "S_01");
  EXPECT_EQ(cells_of(key[2])[2], fs::absolute(study() / "S_01").string());
  for (const auto& e : fs::recursive_directory_iterator(req.out_dir)) {
    if (!e.is_regular_file()) continue;
    const std::string text = read_text_file(e.path());
    EXPECT_EQ(text.find("S_01"), std::string::npos) << e.path();
    EXPECT_EQ(text.find("S02"), std::string::npos) << e.path();
  }
  // Acquisition dates identify too: left out.
  EXPECT_EQ(cells_of(lines_of(read_text_file(req.out_dir / "sub-01" / "sub-01_scans.tsv"))[1])[1], "n/a");
}

TEST_F(BidsExport, CancelledPartWayLeavesACompleteSmallerDataset) {
  BidsExportRequest req = request("cancelled");
  int polls = 0;
  req.should_stop = [&] { return ++polls > 3; };  // three trials: both of S02, the first of S_01
  const BidsExportReport report = export_bids(req);
  EXPECT_TRUE(report.cancelled);
  EXPECT_EQ(report.trials, 3);
  EXPECT_EQ(report.subjects, 2);
  const fs::path ds = req.out_dir;
  EXPECT_EQ(lines_of(read_text_file(ds / "participants.tsv")).size(), 3u);
  const std::vector<std::string> scans = lines_of(read_text_file(ds / "sub-S01" / "sub-S01_scans.tsv"));
  ASSERT_EQ(scans.size(), 1u + 6);
  for (size_t i = 1; i < scans.size(); ++i) EXPECT_TRUE(fs::exists(ds / "sub-S01" / cells_of(scans[i])[0])) << scans[i];
  EXPECT_TRUE(fs::exists(ds / "sub-S01" / "motion" / "sub-S01_task-Static_tracksys-LMC1_acq-Naiv_run-101_motion.tsv"));
  EXPECT_FALSE(fs::exists(ds / "sub-S01" / "motion" / "sub-S01_task-Index_tracksys-LMC1_acq-Naiv_run-101_motion.tsv"));

  // Stopped before the first trial: the dataset-level files and no subject.
  BidsExportRequest none = request("cancelled-at-once");
  none.should_stop = [] { return true; };
  EXPECT_EQ(export_bids(none).trials, 0);
  EXPECT_TRUE(fs::exists(none.out_dir / "dataset_description.json"));
  EXPECT_EQ(read_text_file(none.out_dir / "participants.tsv"),
            "participant_id\thandedness\thand_length_mm\thand_breadth_mm\n");
}

TEST_F(BidsExport, UnsafeSubjectIdIsRefusedNamingTheFile) {
  const fs::path bad = study().parent_path() / "unsafe" / "S03";
  fs::create_directories(bad.parent_path());
  fs::copy(study() / "S02", bad, fs::copy_options::recursive);
  fs::remove(bad / ".lock");
  // The subject id in the journal's first event (the manifest is a view of the journal).
  std::vector<std::string> lines = lines_of(read_text_file(bad / "journal.jsonl"));
  nlohmann::json first = nlohmann::json::parse(lines.front());
  first["setup"]["subject"]["id"] = "../S03";
  lines.front() = first.dump();
  {
    std::ofstream out(bad / "journal.jsonl", std::ios::trunc);
    for (const auto& l : lines) out << l << "\n";
  }
  BidsExportRequest req = request("unsafe-dataset");
  req.inputs = {bad};
  try {
    export_bids(req);
    ADD_FAILURE() << "an unsafe subject id was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((bad / "journal.jsonl").string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("subject id"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(req.out_dir));
  // Beside a good session: that one is written, the other left out with the same note.
  req.inputs = {bad, study() / "S02"};
  const BidsExportReport report = export_bids(req);
  EXPECT_EQ(report.trials, 2);
  EXPECT_EQ(report.left_out, 1);
  ASSERT_FALSE(report.notes.empty());
  EXPECT_NE(report.notes.front().find((bad / "journal.jsonl").string()), std::string::npos) << report.notes.front();
}

// One person recorded twice (two folders with subject id S02, the second created later): both
// are written, as ses-1 and ses-2 of one participant, whichever order the folders are given in.
TEST_F(BidsExport, TwoSessionsOfOneSubjectAreBothWrittenAsSessions) {
  const fs::path again = study().parent_path() / "second-visit" / "S02-again";
  CliRun r = run_lmc("session new --subject S02 --protocol quick --seconds 1 -o " + shell_quote(again.string()),
                     study().parent_path() / "l");
  ASSERT_EQ(r.exit_code, 0) << r.all();
  r = run_lmc("session run " + shell_quote(again.string()) + " --backend sim --fast --auto --quiet --seed 5",
              study().parent_path() / "l");
  ASSERT_EQ(r.exit_code, 0) << r.all();
  BidsExportRequest req = request("two-sessions");
  req.inputs = {again, study() / "S02"};  // the later session first
  const BidsExportReport report = export_bids(req);
  EXPECT_EQ(report.left_out, 0) << (report.notes.empty() ? "" : report.notes.front());
  EXPECT_EQ(report.trials, 4);
  EXPECT_EQ(report.subjects, 1);
  const fs::path ds = req.out_dir;
  for (const char* ses : {"1", "2"}) {
    const std::string prefix = std::string("sub-S02_ses-") + ses;
    const fs::path dir = ds / "sub-S02" / (std::string("ses-") + ses);
    EXPECT_TRUE(fs::exists(dir / "motion" / (prefix + "_task-Static_tracksys-LMC1_acq-Naiv_run-101_motion.tsv")))
        << dir;
    const std::vector<std::string> scans = lines_of(read_text_file(dir / (prefix + "_scans.tsv")));
    ASSERT_EQ(scans.size(), 1u + 2 * 6) << dir;
    for (size_t i = 1; i < scans.size(); ++i) EXPECT_TRUE(fs::exists(dir / cells_of(scans[i])[0])) << scans[i];
    EXPECT_TRUE(fs::exists(ds / "layouts" / (prefix + "_acq-Naiv_layout.json")));
  }
  EXPECT_FALSE(fs::exists(ds / "sub-S02" / "motion")) << "no file outside the sessions";
  EXPECT_EQ(lines_of(read_text_file(ds / "participants.tsv")).size(), 2u) << "one participant";
  // ses-1 is the session created first, though it was given second: its trials were recorded first.
  const auto first_time = [&](const char* ses) {
    const std::string prefix = std::string("sub-S02_ses-") + ses;
    return cells_of(
               lines_of(read_text_file(ds / "sub-S02" / (std::string("ses-") + ses) / (prefix + "_scans.tsv"))).at(1))
        .at(1);
  };
  EXPECT_LT(first_time("1"), first_time("2"));
}

TEST_F(BidsExport, CommandLineWritesTheDataset) {
  const fs::path out = study().parent_path() / "cli-dataset";
  CliRun r = run_lmc("export bids " + shell_quote(study().string()) + " -o " + shell_quote(out.string()),
                     study().parent_path() / "l");
  EXPECT_EQ(r.exit_code, 0) << r.all();
  EXPECT_NE(r.out.find("exported 4 trial(s) of 2 subject(s) as BIDS-motion (default method)"), std::string::npos)
      << r.all();
  EXPECT_NE(
      r.out.find("wrote sub-S01/motion/sub-S01_task-Static_acq-Naiv_run-101 (Naiv_Static101): 6 tracking systems"),
      std::string::npos)
      << r.all();
  r = run_lmc("export bids " + shell_quote(study().string()) + " -o " + shell_quote(out.string()),
              study().parent_path() / "l");
  EXPECT_EQ(r.exit_code, 1) << r.all();
  EXPECT_NE(r.err.find("not empty (use --force"), std::string::npos) << r.all();
}

}  // namespace bids_export_test
}  // namespace lmc
