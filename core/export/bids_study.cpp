#include "core/export/bids_study.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/common/safe_name.h"
#include "core/session/session_folder.h"
#include "core/session/session_trials.h"

namespace fs = std::filesystem;

namespace lmc {
namespace bids_study_detail {  // named: core compiles in unity batches

// The session folders an input stands for, in a stable order.
std::vector<fs::path> session_folders(const fs::path& input, BidsStudyPlan& plan) {
  if (is_session_folder(input)) return {input};
  std::error_code ec;
  if (!fs::is_directory(input, ec)) {
    plan.notes.push_back("left out " + input.string() + ": not a folder");
    ++plan.left_out;
    return {};
  }
  std::vector<fs::path> found;
  for (const auto& entry : fs::directory_iterator(input, ec)) {
    if (entry.is_directory(ec) && is_session_folder(entry.path())) found.push_back(entry.path());
  }
  std::sort(found.begin(), found.end());
  if (found.empty()) {
    plan.notes.push_back("left out " + input.string() + ": no subject session folder (with " + kJournalFile +
                         ") in it");
    ++plan.left_out;
  }
  return found;
}

// The session's accepted trials with their entities; trials that cannot be named are left out.
void plan_trials(const SessionState& state, BidsSubjectPlan& subject, BidsStudyPlan& plan) {
  std::vector<std::string> notes;
  const std::vector<TrialSources> jobs = accepted_trial_jobs(subject.session_dir, std::nullopt, &notes);
  const std::string where = (subject.session_dir / kManifestFile).string();
  for (const auto& n : notes) {
    plan.notes.push_back(subject.session_dir.string() + ": " + n);
    ++plan.left_out;
  }
  std::set<std::string> stems;
  for (const auto& job : jobs) {
    auto leave_out = [&](const std::string& why) {
      plan.notes.push_back("left out " + job.trial + " of " + where + ": " + why);
      ++plan.left_out;
    };
    const int index = state.trial_index(job.trial);
    if (index < 0) {
      leave_out("not in the session's plan");
      continue;
    }
    const PlannedTrial& planned = state.trials[static_cast<size_t>(index)].plan;
    const TrialType& type = state.protocol.trial_types.at(static_cast<size_t>(planned.trial_type));
    const ProtocolPose& pose = state.protocol.poses.at(static_cast<size_t>(planned.pose));
    std::string problem = safe_name_problem(job.trial, "trial name");
    if (problem.empty()) problem = safe_name_problem(type.key, "motion key");
    if (problem.empty()) problem = safe_name_problem(planned.layout_key, "layout key");
    if (!problem.empty()) {
      leave_out(problem);
      continue;
    }
    BidsTrialPlan t;
    t.job = job;
    t.motion = type.key;
    t.layout_key = planned.layout_key;
    t.subject_cue = type.subject_cue;
    t.operator_cue = type.operator_cue;
    t.entities.subject = subject.label;
    t.entities.session = subject.session_label;
    t.entities.task = bids_label(type.key);
    t.entities.acq = bids_label(planned.layout_key);
    t.entities.run = bids_run_index(pose.code, planned.repetition);
    if (t.entities.task.empty() || t.entities.acq.empty()) {
      leave_out("its motion key '" + type.key + "' or layout key '" + planned.layout_key +
                "' has no letter or digit for a BIDS label");
      continue;
    }
    if (!stems.insert(bids_stem(t.entities)).second) {
      leave_out("another trial already gives " + bids_stem(t.entities));
      continue;
    }
    subject.trials.push_back(std::move(t));
  }
}

}  // namespace bids_study_detail

int BidsStudyPlan::trial_count() const {
  int n = 0;
  for (const auto& s : subjects) n += static_cast<int>(s.trials.size());
  return n;
}

BidsStudyPlan plan_bids_study(const std::vector<fs::path>& inputs, bool anonymise) {
  BidsStudyPlan plan;
  std::vector<std::pair<fs::path, SessionState>> sessions;
  std::set<fs::path> seen;
  for (const auto& input : inputs) {
    for (const auto& dir : bids_study_detail::session_folders(input, plan)) {
      if (!seen.insert(fs::weakly_canonical(dir)).second) continue;  // given twice
      try {
        sessions.emplace_back(dir, read_session_state(dir));
      } catch (const std::exception& e) {
        plan.notes.push_back("left out " + dir.string() + ": " + e.what());
        ++plan.left_out;
      }
    }
  }
  // A subject id seen in several folders is one person recorded in several sessions: numbered in
  // the order they were created (then by folder), so the first session stays ses-1 whatever the
  // inputs' order.
  std::map<std::string, std::vector<size_t>> sessions_of;
  for (size_t k = 0; k < sessions.size(); ++k) sessions_of[sessions[k].second.subject().subject_id].push_back(k);
  std::map<size_t, std::string> session_label;
  for (auto& [id, ks] : sessions_of) {
    if (ks.size() < 2) continue;
    std::sort(ks.begin(), ks.end(), [&](size_t a, size_t b) {
      const auto& [da, sa] = sessions[a];
      const auto& [db, sb] = sessions[b];
      if (sa.setup.created_utc != sb.setup.created_utc) return sa.setup.created_utc < sb.setup.created_utc;
      return da < db;
    });
    for (size_t n = 0; n < ks.size(); ++n) session_label[ks[n]] = std::to_string(n + 1);
  }
  std::map<std::string, std::string> id_of_label;  // BIDS label → the subject id that took it
  std::vector<std::string> subject_order;          // distinct ids as first met (anonymised labels)
  for (size_t k = 0; k < sessions.size(); ++k) {
    auto& [dir, state] = sessions[k];
    const std::string& id = state.subject().subject_id;
    const std::string where = (dir / kManifestFile).string();
    // The reader checks ids already; checked again here because the id becomes a folder name.
    std::string problem = safe_name_problem(id, "subject id");
    const std::string label = bids_label(id);
    if (problem.empty() && label.empty()) problem = "subject id '" + id + "' has no letter or digit for a BIDS label";
    if (problem.empty() && !anonymise) {
      const auto [it, added] = id_of_label.emplace(label, id);
      if (!added && it->second != id)
        problem = "subject id '" + id + "' becomes the BIDS label " + label + ", which subject " + it->second +
                  " already has";
    }
    if (!problem.empty()) {
      plan.notes.push_back("left out " + where + ": " + problem);
      ++plan.left_out;
      continue;
    }
    if (std::find(subject_order.begin(), subject_order.end(), id) == subject_order.end()) subject_order.push_back(id);
    BidsSubjectPlan s;
    s.session_dir = dir;
    s.subject = state.subject();
    s.label = label;
    if (const auto it = session_label.find(k); it != session_label.end()) s.session_label = it->second;
    plan.subjects.push_back(std::move(s));
    bids_study_detail::plan_trials(state, plan.subjects.back(), plan);
  }
  if (anonymise) {
    const int n = static_cast<int>(subject_order.size());
    for (auto& s : plan.subjects) {
      const auto at = std::find(subject_order.begin(), subject_order.end(), s.subject.subject_id);
      s.label = bids_anonymous_label(static_cast<int>(at - subject_order.begin()), n);
      for (auto& t : s.trials) t.entities.subject = s.label;
    }
  }
  return plan;
}

}  // namespace lmc
