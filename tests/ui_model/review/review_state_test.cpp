// The Review tab's model without ImGui: a quick simulated subject session (2 trials
// with truth) is processed by the batch job into table rows; a second opening comes from the cache;
// a changed file, a changed method, a cancelled batch and a damaged cache entry behave as a lab
// would expect; the state selects a trial and loads its series; filters and sorting.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/processing/length_correction_json.h"
#include "tests/support/cli_runner.h"
#include "tests/support/quick_session.h"
#include "tests/support/reference_data.h"
#include "ui/model/review/review_state.h"

namespace lmc::ui {
namespace review_state_test {  // named: test files share unity batches

namespace fs = std::filesystem;

// One quick simulated session for the whole suite (about two seconds to record).
class ReviewModel : public test::QuickSessionSuite<ReviewModel> {
 public:
  static constexpr const char* kScratchName = "review_model";
  static constexpr int kSeed = 5;

 protected:
  ReviewBatchInput input(const fs::path& cache) const {
    ReviewBatchInput in;
    in.folders = {session()};
    in.cache_dir = cache;
    return in;
  }
  static ReviewBatch run(const ReviewBatchInput& in) {
    std::stop_source never;
    return run_review_batch(in, never.get_token(), {});
  }
};

TEST_F(ReviewModel, ProcessesASessionIntoRowsAndReopensItFromTheCache) {
  const fs::path cache = test::scratch_dir("review_cache_a");
  int last_done = -1, last_total = -1;
  std::stop_source never;
  const ReviewBatch first = run_review_batch(input(cache), never.get_token(), [&](int d, int t) {
    last_done = std::max(last_done, d);
    last_total = t;
  });
  ASSERT_EQ(first.trials.size(), 2u);
  EXPECT_EQ(first.processed_now, 2);
  EXPECT_EQ(first.from_cache, 0);
  EXPECT_EQ(last_done, 2);
  EXPECT_EQ(last_total, 2);
  for (const auto& t : first.trials) {
    ASSERT_TRUE(t.outcome.ok) << t.outcome.error;
    EXPECT_EQ(t.row.subject, "S01");
    EXPECT_EQ(t.row.status, TrialRowStatus::kOk);  // the simulator writes the truth as Vicon would
    EXPECT_EQ(t.row.layout, "initial");
    EXPECT_EQ(t.row.pose, "horizontal");
    ASSERT_EQ(t.row.visibility_rate.size(), 4u);
    for (double v : t.row.visibility_rate) {
      if (std::isfinite(v)) {
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
      }
    }
    // Fused against truth: the simulated fingers are within a few centimetres.
    ASSERT_TRUE(std::isfinite(t.row.finger_length_diff_mm));
    EXPECT_LT(std::abs(t.row.finger_length_diff_mm), 30.0);
  }
  // Nothing was written into the recorded session.
  for (const auto& e : fs::directory_iterator(session()))
    EXPECT_EQ(e.path().filename().string().find("summary"), std::string::npos);

  const ReviewBatch second = run(input(cache));
  EXPECT_EQ(second.from_cache, 2);
  EXPECT_EQ(second.processed_now, 0);
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_TRUE(second.trials[k].from_cache);
    EXPECT_EQ(second.trials[k].outcome.summary, first.trials[k].outcome.summary);
  }
}

// A subject is a person, not a folder: a second session folder of subject S01 named otherwise
// ("S01-visit2") gives rows of subject S01, so agreement counts one subject.
TEST_F(ReviewModel, TwoSessionFoldersOfOneSubjectIdAreOneSubject) {
  const fs::path second = test::scratch_dir("review_second_visit") / "S01-visit2";
  fs::remove_all(second);
  fs::copy(session(), second, fs::copy_options::recursive);
  fs::remove(second / ".lock");
  ReviewBatchInput in = input(test::scratch_dir("review_cache_two_visits"));
  in.folders.push_back(second);
  const ReviewBatch both = run(in);
  ASSERT_EQ(both.trials.size(), 4u);
  for (const auto& t : both.trials) EXPECT_EQ(t.row.subject, "S01") << t.folder;
  fs::remove_all(second.parent_path());
}

// `--review` with a typo: the missing folder gets no chip of its own and the problem line names it.
TEST_F(ReviewModel, AFolderThatDoesNotExistIsNotOpenedAndSaysSo) {
  ReviewState state;
  state.set_cache_dir(test::scratch_dir("review_cache_missing"));
  const fs::path missing = session().parent_path() / "no-such-session";
  state.open_folders({missing});
  EXPECT_TRUE(state.folders().empty());
  EXPECT_EQ(state.problem(), "not opened: " + missing.string() + ": no such folder");
  state.open_folders({session(), missing});
  ASSERT_EQ(state.folders().size(), 1u);
  EXPECT_EQ(state.folders()[0], session().lexically_normal());
  EXPECT_NE(state.problem().find(missing.string() + ": no such folder"), std::string::npos) << state.problem();
}

TEST_F(ReviewModel, AChangedFileOrMethodIsProcessedAgainAndADamagedEntryIsAMiss) {
  const fs::path cache = test::scratch_dir("review_cache_b");
  const ReviewBatch first = run(input(cache));
  ASSERT_EQ(first.processed_now, 2);
  // A newer modification time on one recording: only that trial is processed again.
  const fs::path lmc = first.trials[0].job.lmc;
  fs::last_write_time(lmc, fs::last_write_time(lmc) + std::chrono::seconds(5));
  ReviewBatch again = run(input(cache));
  EXPECT_EQ(again.processed_now, 1);
  EXPECT_FALSE(again.trials[0].from_cache);
  EXPECT_TRUE(again.trials[1].from_cache);
  // The other fusion method is another result.
  ReviewBatchInput ref = input(cache);
  ref.options.process.method = FusionMethod::kReference;
  const ReviewBatch by_reference = run(ref);
  EXPECT_EQ(by_reference.processed_now, 2);
  EXPECT_EQ(by_reference.trials[0].outcome.summary["method"], "reference");
  // Garbage in every entry: all misses, processed, and the entries written again.
  for (const auto& e : fs::directory_iterator(cache / "")) {
    std::ofstream(e.path(), std::ios::trunc) << "{ not json";
  }
  again = run(input(cache));
  EXPECT_EQ(again.processed_now, 2);
  again = run(input(cache));
  EXPECT_EQ(again.from_cache, 2);
}

TEST_F(ReviewModel, ACancelledBatchLeavesTrialsOutAndStoresNothingForThem) {
  const fs::path cache = test::scratch_dir("review_cache_c");
  std::stop_source stop;
  stop.request_stop();
  const ReviewBatch cancelled = run_review_batch(input(cache), stop.get_token(), {});
  ASSERT_EQ(cancelled.trials.size(), 2u);
  for (const auto& t : cancelled.trials) {
    EXPECT_TRUE(t.outcome.cancelled);
    EXPECT_EQ(t.row.status, TrialRowStatus::kCancelled);
  }
  EXPECT_EQ(run(input(cache)).processed_now, 2);
}

TEST_F(ReviewModel, AFolderThatCannotBeReadIsANoteNotAFailure) {
  ReviewBatchInput in = input(test::scratch_dir("review_cache_d"));
  in.folders.push_back(root() / "no-such-folder");
  const ReviewBatch b = run(in);
  EXPECT_EQ(b.trials.size(), 2u);
  ASSERT_FALSE(b.notes.empty());
  bool named = false;
  for (const auto& n : b.notes) named = named || n.find("no-such-folder") != std::string::npos;
  EXPECT_TRUE(named);
}

TEST_F(ReviewModel, TheStateSelectsATrialAndLoadsItsSeriesOnOneTimeAxis) {
  ReviewState state;
  state.set_cache_dir(test::scratch_dir("review_cache_e"));
  state.open_folder(session());
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while ((state.busy() || !state.view()) && std::chrono::steady_clock::now() < deadline) {
    state.update();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_EQ(state.trials().size(), 2u);
  ASSERT_EQ(state.selected(), 0);  // the first trial with Vicon is shown without a click
  const auto view = state.view();
  ASSERT_TRUE(view);
  const TrialSeries& s = view->series;
  EXPECT_EQ(s.trial, state.trials()[0].job.trial);
  ASSERT_GT(s.frames(), 200);  // 3 s at 100 Hz
  EXPECT_TRUE(s.has_vicon);
  for (int f = 1; f < s.frames(); ++f) ASSERT_GT(s.time_s[f], s.time_s[f - 1]);
  EXPECT_EQ(s.devices.size(), 4u);
  for (const auto& d : s.devices) {
    for (const auto& l : d.label) {
      ASSERT_EQ(static_cast<int>(l.size()), s.frames());
      for (auto v : l) ASSERT_TRUE(v == -1 || v == 0 || v == 1);
    }
  }
  EXPECT_DOUBLE_EQ(state.x_range()->extent_lo(), s.time_s.front());
  EXPECT_DOUBLE_EQ(state.x_range()->extent_hi(), s.time_s.back());

  // A trial preferred after the batch is in (--capture's LMC_REVIEW_TRIAL, the tab shown last) is
  // selected at once, not only when a later batch arrives.
  const std::string other = state.trials()[1].job.trial;
  state.prefer_trial(other);
  EXPECT_EQ(state.selected(), 1);
  while ((state.busy() || !state.view() || state.view()->series.trial != other) &&
         std::chrono::steady_clock::now() < deadline) {
    state.update();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(state.view());
  EXPECT_EQ(state.view()->series.trial, other);
  state.select(0);

  // Filtering by motion keeps one of the two trials; a text filter is case-blind.
  TrialFilter f;
  f.motion = "static";
  state.set_filter(f);
  ASSERT_EQ(state.visible_trials().size(), 1u);
  EXPECT_EQ(state.trials()[static_cast<size_t>(state.visible_trials()[0])].row.motion, "static");
  f = {};
  f.text = "INDEX";
  state.set_filter(f);
  EXPECT_EQ(state.visible_trials().size(), 1u);
}

// A subject's finger-length correction chosen for one opened folder (the Review tab's "lengths..."):
// its trials are processed with it after the default fusion (the trial it was fitted on says so),
// the cache keeps corrected and plain results apart, the reference fusion is never corrected, and a
// file that cannot be used changes nothing and is named.
TEST_F(ReviewModel, ALengthCorrectionAppliesToItsFolderWithTheDefaultFusionOnly) {
  const fs::path dir = test::scratch_dir("review_length_correction");
  const fs::path cache = dir / "cache";
  const ReviewBatch plain = run(input(cache));
  ASSERT_EQ(plain.trials.size(), 2u);
  const std::string fit_trial = plain.trials[0].job.trial;
  const fs::path file = dir / "S01-lengths.json";
  const test::CliRun fit =
      test::run_lmc("length-correction fit " + test::shell_quote(session().string()) + " --trial " + fit_trial +
                        " --subject S01 -o " + test::shell_quote(file.string()),
                    dir);
  ASSERT_EQ(fit.exit_code, 0) << fit.all();

  ReviewBatchInput in = input(cache);
  in.corrections.emplace(session(), FolderLengthCorrection{file, read_length_correction(file)});
  const ReviewBatch corrected = run(in);
  ASSERT_EQ(corrected.trials.size(), 2u);
  EXPECT_EQ(corrected.processed_now, 2);  // not the plain results from the cache
  for (size_t k = 0; k < 2; ++k) {
    ASSERT_TRUE(corrected.trials[k].outcome.ok) << corrected.trials[k].outcome.error;
    EXPECT_NE(corrected.trials[k].row.finger_length_diff_mm, plain.trials[k].row.finger_length_diff_mm);
    EXPECT_NEAR(corrected.trials[k].row.rom_abs_diff_deg, plain.trials[k].row.rom_abs_diff_deg, 1e-9);  // angles keep
  }
  // Fitted on trial 0 against Vicon: its mean length difference nearly vanishes, and it says it
  // is not an independent test.
  EXPECT_LT(std::abs(corrected.trials[0].row.finger_length_diff_mm),
            std::abs(plain.trials[0].row.finger_length_diff_mm));
  EXPECT_LT(std::abs(corrected.trials[0].row.finger_length_diff_mm), 1.0);
  EXPECT_EQ(corrected.trials[0].row.warnings, plain.trials[0].row.warnings + 1);

  // The reference fusion stays the study's algorithm: nothing corrected, and a note says why.
  in.options.process.method = FusionMethod::kReference;
  const ReviewBatch reference = run(in);
  ASSERT_TRUE(reference.trials[0].outcome.ok) << reference.trials[0].outcome.error;
  EXPECT_FALSE(folder_options(in.options, in.corrections, session()).process.length_correction.has_value());
  bool noted = false;
  for (const auto& n : reference.notes)
    noted = noted || n.find("not applied with the reference fusion") != std::string::npos;
  EXPECT_TRUE(noted);

  // Through the state: a bad file is named and changes nothing; a good one is shown in the view.
  ReviewState state;
  state.set_cache_dir(cache);
  state.open_folder(session());
  const fs::path bad = dir / "broken.json";
  std::ofstream(bad) << "{\"factor\": [1, 2";
  EXPECT_FALSE(state.set_length_correction(session(), bad));
  EXPECT_NE(state.problem().find("broken.json"), std::string::npos) << state.problem();
  EXPECT_EQ(state.length_correction(session()), nullptr);
  ASSERT_TRUE(state.set_length_correction(session(), file));
  ASSERT_NE(state.length_correction(session()), nullptr);
  EXPECT_EQ(state.length_correction(session())->correction.subject, "S01");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while ((state.busy() || !state.view() || !state.view()->result->length_correction) &&
         std::chrono::steady_clock::now() < deadline) {
    state.update();
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_TRUE(state.view());
  EXPECT_TRUE(state.view()->result->length_correction.has_value());
  state.clear_length_correction(session());
  EXPECT_EQ(state.length_correction(session()), nullptr);
  fs::remove_all(dir);
}

}  // namespace review_state_test
}  // namespace lmc::ui
