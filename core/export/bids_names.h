#pragma once
// How a study's names become BIDS names (docs/export.md, "BIDS-motion"). BIDS labels hold letters
// and digits only, while the study's names (subject ids, motion and layout keys) also allow '_' and
// '-' (core/common/safe_name.h): those two are dropped, so "S_01" and "S-01" both become "S01".
// The dataset builder refuses a second name that maps to a label already taken, never merging two.
//   sub-<subject>/motion/sub-<subject>_task-<motion>_tracksys-<system>_acq-<layout>_run-<pose><rep>_<suffix>
// A subject recorded in two sessions (two session folders with one subject id) gets a session level:
//   sub-<subject>/ses-<n>/motion/sub-<subject>_ses-<n>_task-…
// The run index is the trial name's own digits: the palm pose code, then the repetition in two
// digits (Naiv_Index102 → run-102), so every trial of one motion and layout has its own run.
#include <string>

namespace lmc {

// Letters and digits of `name`, in order; empty when it has none.
std::string bids_label(const std::string& name);

// pose code × 100 + repetition (1…99): 102 for pose 1, repetition 2.
int bids_run_index(int pose_code, int repetition);

struct BidsEntities {
  std::string subject;   // label, without "sub-"
  std::string task;      // the motion ("Index")
  std::string tracksys;  // empty for files every tracking system of the trial shares (events)
  std::string acq;       // the layout key ("Naiv")
  int run = 0;
  std::string session;  // label without "ses-"; empty when the subject has one session in the dataset
};

// "sub-S01_task-Index_tracksys-LMC1_acq-Naiv_run-102" (entities in the order BIDS 1.9 gives them).
std::string bids_stem(const BidsEntities& e);
// "sub-S01".
std::string bids_subject_dir(const std::string& subject_label);
// Where one session's files go, relative to the dataset: "sub-S01/ses-2", or "sub-S01" when the
// subject has one session (no session level); and the file name prefix that goes with it
// ("sub-S01_ses-2", "sub-S01").
std::string bids_session_dir(const std::string& subject_label, const std::string& session_label);
std::string bids_session_prefix(const std::string& subject_label, const std::string& session_label);

// Tracking-system labels: each controller's slot ("LMC1"…), the fused hand, Vicon.
std::string bids_device_tracksys(int device_id);
inline constexpr const char* kBidsFusedTracksys = "LMCfused";
inline constexpr const char* kBidsViconTracksys = "Vicon";

// The label of the `index`-th (0-based) of `count` anonymised subjects: "01", "02", … with as many
// digits as `count` needs, at least two, so the labels sort in order.
std::string bids_anonymous_label(int index, int count);

}  // namespace lmc
