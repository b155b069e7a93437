// The Review tab's exports for motion-analysis tools without ImGui: the plan groups the chosen trials
// by opened folder with that folder's options; a quick simulated subject session (2 trials with
// truth written as Vicon) is exported as C3D on the worker thread with progress; a cancel after the
// first trial leaves one complete file and nothing else; existing files are refused before anything
// is written unless replacing; ReviewState starts, reports and cancels the export.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/common/error.h"
#include "core/io/c3d.h"
#include "core/io/trc.h"
#include "core/session/session_trials.h"
#include "tests/support/cli_runner.h"
#include "tests/support/quick_session.h"
#include "tests/support/scratch_dir.h"
#include "ui/model/review/motion_export_job.h"
#include "ui/model/review/review_state.h"

namespace lmc::ui {
namespace motion_export_job_test {  // named: test files share unity batches

namespace fs = std::filesystem;

ReviewTrial fake_trial(const fs::path& folder, const std::string& name) {
  ReviewTrial t;
  t.folder = folder;
  t.job.trial = name;
  t.job.lmc = folder / ("LMC_" + name + ".raw.txt");
  return t;
}

LengthCorrection fake_correction(double factor) {
  LengthCorrection c;
  c.subject = "S01";
  c.factor.fill(factor);
  return c;
}

TEST(MotionExportPlan, GroupsTrialsByFolderWithThatFoldersOptionsAndSubfolders) {
  const fs::path a = "/data/a/S01", b = "/data/b/S01";
  const std::vector<ReviewTrial> trials{fake_trial(a, "Naiv_Index101"), fake_trial(a, "Naiv_Static101"),
                                        fake_trial(b, "Naiv_Index101"), fake_trial(b, "Naiv_Static101")};
  FolderLengthCorrections corrections;
  corrections[a] = FolderLengthCorrection{"/data/a/S01-lengths.json", fake_correction(1.2)};
  BatchOptions options;
  // Every trial of a, one of b (in the table's order: b's first).
  const MotionExportPlan plan = trial_export_plan(trials, {2, 0, 1}, options, corrections, "/out", ExportFormat::kTrc,
                                                  ExportAxes::kOpenSim, true);
  EXPECT_EQ(plan.folder, fs::path("/out"));
  EXPECT_EQ(plan.trials_planned(), 3);
  ASSERT_EQ(plan.trial_runs.size(), 2u);
  const TrialExportRequest& first = plan.trial_runs[0].request;  // b: one trial of two, by its recording
  EXPECT_EQ(first.inputs, std::vector<fs::path>{b / "LMC_Naiv_Index101.raw.txt"});
  EXPECT_EQ(first.out_dir, fs::path("/out/S01"));
  EXPECT_FALSE(first.session.process.length_correction.has_value());
  EXPECT_EQ(first.format, ExportFormat::kTrc);
  EXPECT_EQ(first.axes, ExportAxes::kOpenSim);
  EXPECT_TRUE(first.force);
  const TrialExportRequest& second = plan.trial_runs[1].request;  // a: every trial, so the folder itself
  EXPECT_EQ(second.inputs, std::vector<fs::path>{a});
  EXPECT_EQ(second.out_dir, fs::path("/out/S01-2"));  // both folders are called S01
  ASSERT_TRUE(second.session.process.length_correction.has_value());
  EXPECT_DOUBLE_EQ(second.session.process.length_correction->factor[1], 1.2);
  EXPECT_EQ(plan.trial_runs[1].trials, (std::vector<std::string>{"Naiv_Index101", "Naiv_Static101"}));

  // One folder: straight into the chosen folder. The reference fusion never gets a correction.
  options.process.method = FusionMethod::kReference;
  const MotionExportPlan one =
      trial_export_plan(trials, {1}, options, corrections, "/out", ExportFormat::kC3d, ExportAxes::kWorld, false);
  ASSERT_EQ(one.trial_runs.size(), 1u);
  EXPECT_EQ(one.trial_runs[0].request.out_dir, fs::path("/out"));
  EXPECT_EQ(one.trial_runs[0].request.inputs, std::vector<fs::path>{a / "LMC_Naiv_Static101.raw.txt"});
  EXPECT_EQ(one.trial_runs[0].request.session.process.method, FusionMethod::kReference);
  EXPECT_FALSE(one.trial_runs[0].request.session.process.length_correction.has_value());
  // Nothing chosen: nothing planned, and running it says so.
  const MotionExportPlan none =
      trial_export_plan(trials, {}, options, corrections, "/out", ExportFormat::kC3d, ExportAxes::kWorld, false);
  EXPECT_TRUE(none.trial_runs.empty());
  EXPECT_THROW(run_motion_export(none, std::stop_token{}, {}, {}), Error);
}

TEST(MotionExportPlan, BidsTakesTheOpenedFoldersAndSaysWhichCorrectionsItCannotApply) {
  const fs::path a = "/data/S01", b = "/data/S02";
  FolderLengthCorrections corrections;
  corrections[b] = FolderLengthCorrection{"/data/S02-lengths.json", fake_correction(1.1)};
  BatchOptions options;
  const MotionExportPlan plan =
      bids_export_plan({a, b}, options, corrections, "/out/ds", fs::path("/out/ds-key.tsv"), false);
  ASSERT_TRUE(plan.bids.has_value());
  EXPECT_TRUE(plan.trial_runs.empty());
  EXPECT_EQ(plan.bids->inputs, (std::vector<fs::path>{a, b}));
  EXPECT_EQ(plan.bids->out_dir, fs::path("/out/ds"));
  EXPECT_TRUE(plan.bids->anonymise);
  EXPECT_EQ(plan.bids->anonymise_key, fs::path("/out/ds-key.tsv"));
  EXPECT_FALSE(plan.bids->force);
  EXPECT_FALSE(plan.bids->session.process.length_correction.has_value());
  ASSERT_EQ(plan.notes.size(), 1u);
  EXPECT_NE(plan.notes[0].find("S02"), std::string::npos);
  EXPECT_NE(plan.notes[0].find("not applied"), std::string::npos);
  const MotionExportPlan plain = bids_export_plan({a}, options, {}, "/out/ds", std::nullopt, true);
  EXPECT_FALSE(plain.bids->anonymise);
  EXPECT_TRUE(plain.bids->force);
  EXPECT_TRUE(plain.notes.empty());
}

// One quick simulated session for the suite (about two seconds to record).
class MotionExport : public test::QuickSessionSuite<MotionExport> {
 public:
  static constexpr const char* kScratchName = "motion_export";
  static constexpr int kSeed = 5;

 protected:
  // The session's trials as the Review batch lists them (processing is not needed to plan).
  static std::vector<ReviewTrial> trials() {
    std::vector<ReviewTrial> out;
    for (auto& job : trial_sources_for_input(session(), std::nullopt)) {
      ReviewTrial t;
      t.folder = session();
      t.job = job;
      out.push_back(t);
    }
    return out;
  }
  static std::vector<fs::path> files_in(const fs::path& dir) {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename());
    std::sort(out.begin(), out.end());
    return out;
  }
};

TEST_F(MotionExport, WritesTheChosenTrialsAsC3dOnAWorkerWithProgress) {
  const auto all = trials();
  ASSERT_EQ(all.size(), 2u);
  const fs::path out = test::scratch_dir("motion_export_c3d") / "c3d";
  MotionExportJob job;
  job.start(trial_export_plan(all, {0, 1}, BatchOptions{}, {}, out, ExportFormat::kC3d, ExportAxes::kWorld, false));
  EXPECT_EQ(job.folder(), out);
  EXPECT_EQ(job.runs(), 1);  // the tab reports each run's outcome once by this count
  job.wait();
  ASSERT_EQ(job.state(), JobState::kCompleted) << job.error();
  const auto outcome = job.outcome();
  ASSERT_TRUE(outcome);
  EXPECT_EQ(outcome->folder, out);
  EXPECT_EQ(outcome->trials, 2);
  EXPECT_EQ(outcome->left_out, 0);
  EXPECT_FALSE(outcome->cancelled);
  EXPECT_FALSE(outcome->bids);
  EXPECT_EQ(job.done(), 2);
  EXPECT_EQ(job.total(), 2);
  EXPECT_NE(job.current_line().find("wrote "), std::string::npos);
  ASSERT_EQ(outcome->written.size(), 2u);
  std::vector<fs::path> expected{all[0].job.trial + ".c3d", all[1].job.trial + ".c3d"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(files_in(out), expected);
  for (const auto& file : outcome->written) {
    const C3dData c3d = read_c3d(file);
    EXPECT_GT(c3d.frame_count(), 100);
    EXPECT_EQ(c3d.point_rate_hz, 100.0);
    const auto has = [&](const std::string& label) {
      return std::find(c3d.labels.begin(), c3d.labels.end(), label) != c3d.labels.end();
    };
    EXPECT_TRUE(has("F_Index_Dist"));
    EXPECT_TRUE(has("LMC1_Palm"));
    // The simulator writes the truth beside the recording as Vicon would: its markers are in.
    EXPECT_TRUE(
        std::any_of(c3d.labels.begin(), c3d.labels.end(), [](const std::string& l) { return l.rfind("V_", 0) == 0; }));
  }
}

TEST_F(MotionExport, ACancelAfterTheFirstTrialLeavesOneCompleteFileAndNothingElse) {
  const auto all = trials();
  const fs::path out = test::scratch_dir("motion_export_cancel") / "c3d";
  std::stop_source stop;
  std::vector<std::pair<int, int>> progress;
  int lines = 0;
  const MotionExportOutcome outcome = run_motion_export(
      trial_export_plan(all, {0, 1}, BatchOptions{}, {}, out, ExportFormat::kC3d, ExportAxes::kWorld, false),
      stop.get_token(), [&](int done, int total) { progress.emplace_back(done, total); },
      [&](const std::string&) {
        ++lines;
        stop.request_stop();  // the first trial is written: stop before the second
      });
  EXPECT_TRUE(outcome.cancelled);
  EXPECT_EQ(lines, 1);
  EXPECT_EQ(outcome.trials, 1);
  ASSERT_EQ(outcome.written.size(), 1u);
  // Nothing half-written: the one file reads back whole, and no temporary file is left beside it.
  EXPECT_EQ(files_in(out), std::vector<fs::path>{all[0].job.trial + ".c3d"});
  EXPECT_GT(read_c3d(outcome.written[0]).frame_count(), 100);
  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.back(), std::make_pair(1, 2));
  ASSERT_FALSE(outcome.notes.empty());
  EXPECT_EQ(outcome.notes.back(), "cancelled after 1 trial of 2");
}

TEST_F(MotionExport, ExistingFilesAreRefusedBeforeAnythingIsWrittenUnlessReplacing) {
  const auto all = trials();
  const fs::path out = test::scratch_dir("motion_export_exists") / "trc";
  fs::create_directories(out);
  const fs::path existing = out / (all[1].job.trial + ".trc");
  std::ofstream(existing) << "an older export";
  const auto plan = [&](bool force) {
    return trial_export_plan(all, {0, 1}, BatchOptions{}, {}, out, ExportFormat::kTrc, ExportAxes::kOpenSim, force);
  };
  try {
    run_motion_export(plan(false), std::stop_token{}, {}, {});
    FAIL() << "an existing file was not refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(existing.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("nothing was written"), std::string::npos) << e.what();
  }
  EXPECT_EQ(files_in(out), std::vector<fs::path>{existing.filename()});  // the first trial was not written either
  EXPECT_EQ(test::read_text_file(existing), "an older export");
  const MotionExportOutcome replaced = run_motion_export(plan(true), std::stop_token{}, {}, {});
  EXPECT_EQ(replaced.trials, 2);
  const TrcData trc = read_trc(existing);
  EXPECT_GT(trc.positions.size(), 100u);
}

TEST_F(MotionExport, ReviewStateExportsWhatTheTableShowsAndCancels) {
  ReviewState state;
  state.set_cache_dir(test::scratch_dir("motion_export_cache"));
  state.open_folder(session());
  for (int i = 0; i < 6000 && (state.batch_job().running() || state.batch() == nullptr); ++i) {
    state.update();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_NE(state.batch(), nullptr);
  ASSERT_EQ(state.trials().size(), 2u);
  // The filter shows one trial: that one is exported, as TRC.
  TrialFilter filter;
  filter.text = state.trials()[1].job.trial;
  state.set_filter(filter);
  ASSERT_EQ(state.visible_trials().size(), 1u);
  const fs::path out = test::scratch_dir("motion_export_state");
  state.export_trial_points(TrialsToExport::kShown, out / "shown", ExportFormat::kTrc, ExportAxes::kWorld, false);
  EXPECT_TRUE(state.busy());
  state.motion_export().wait();
  ASSERT_EQ(state.motion_export().state(), JobState::kCompleted) << state.motion_export().error();
  EXPECT_EQ(files_in(out / "shown"), std::vector<fs::path>{state.trials()[1].job.trial + ".trc"});
  // The selected trial.
  state.select(0);
  state.export_trial_points(TrialsToExport::kSelected, out / "selected", ExportFormat::kC3d, ExportAxes::kWorld, false);
  state.motion_export().wait();
  EXPECT_EQ(files_in(out / "selected"), std::vector<fs::path>{state.trials()[0].job.trial + ".c3d"});
  // Both, cancelled at once: the worker stops before the second trial at the latest.
  state.set_filter({});
  state.export_trial_points(TrialsToExport::kShown, out / "cancelled", ExportFormat::kC3d, ExportAxes::kWorld, false);
  state.cancel_motion_export();
  state.motion_export().wait();
  EXPECT_EQ(state.motion_export().state(), JobState::kCancelled);
  const auto cancelled = state.motion_export().outcome();
  ASSERT_TRUE(cancelled);
  EXPECT_TRUE(cancelled->cancelled);
  EXPECT_LT(cancelled->trials, 2);
  EXPECT_FALSE(state.motion_export().running());
  // select(0) above started the selected trial's view; on a loaded machine it can still be running
  // here, and busy() rightly says so until it ends.
  for (int i = 0; i < 6000 && state.view_job().running(); ++i) {
    state.update();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_FALSE(state.busy());
}

TEST_F(MotionExport, ABidsExportEndsWithADatasetOrTheReasonItCouldNot) {
  ReviewState state;
  state.set_cache_dir(test::scratch_dir("motion_export_bids_cache"));
  state.open_folder(session());
  const fs::path out = test::scratch_dir("motion_export_bids") / "dataset";
  state.export_bids_dataset(out, std::nullopt, false);
  state.motion_export().wait();
  const MotionExportJob& job = state.motion_export();
  EXPECT_TRUE(job.is_bids());
  EXPECT_EQ(job.folder(), out);
  if (job.state() == JobState::kFailed) {
    // A build without the BIDS writer says so, and the job carries core's words to the panel.
    EXPECT_FALSE(job.error().empty());
    EXPECT_FALSE(job.outcome());
  } else {
    ASSERT_EQ(job.state(), JobState::kCompleted);
    ASSERT_TRUE(job.outcome());
    EXPECT_TRUE(job.outcome()->bids);
    EXPECT_EQ(job.outcome()->subjects, 1);
    EXPECT_EQ(job.outcome()->trials, 2);
  }
}

}  // namespace motion_export_job_test
}  // namespace lmc::ui
