#pragma once
// What a BIDS export will write, before anything is written: the subject session folders found in
// the inputs, each subject's label and each accepted trial's BIDS entities. Read-only. Names that
// come from files (subject ids, trial names, motion and layout keys) are checked with
// safe_name_problem before they become paths and mapped to labels with bids_label; whatever cannot
// be exported (a folder without sessions, an unreadable journal, a label already taken by another
// subject id, a trial that is not accepted) is left out with a note naming the file. Sessions of one
// subject id are never dropped for each other: each is written as a BIDS session.
#include <filesystem>
#include <string>
#include <vector>

#include "core/export/bids_names.h"
#include "core/processing/batch.h"
#include "core/session/session_state.h"

namespace lmc {

struct BidsTrialPlan {
  TrialSources job;          // the accepted attempt (core/session/session_trials.h)
  BidsEntities entities;     // tracksys left empty: one per tracking system when written
  std::string motion;        // the protocol's trial type key ("Index")
  std::string layout_key;    // "Naiv"
  std::string subject_cue;   // what the subject was shown
  std::string operator_cue;  // what the operator read
};

// One session folder. Two folders with one subject id are two sessions of one subject: the same
// label, each with its session label (1, 2, … in the order they were created).
struct BidsSubjectPlan {
  std::filesystem::path session_dir;
  SubjectInfo subject;        // as the manifest says; the id is the session's own
  std::string label;          // the BIDS label (anonymised or from the id)
  std::string session_label;  // "" when the subject has one session in the dataset
  std::vector<BidsTrialPlan> trials;
};

struct BidsStudyPlan {
  std::vector<BidsSubjectPlan> subjects;  // one per session folder: in input order, a study folder's by name
  std::vector<std::string> notes;         // what is left out and why
  int left_out = 0;                       // trials or inputs left out
  int trial_count() const;
};

// A session folder, or a folder whose direct sub-folders are session folders. With `anonymise`
// the labels are 01, 02, … in that order; else each id's bids_label.
BidsStudyPlan plan_bids_study(const std::vector<std::filesystem::path>& inputs, bool anonymise);

}  // namespace lmc
