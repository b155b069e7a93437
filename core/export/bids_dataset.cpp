// The BIDS export's order of work: plan everything (bids_study), refuse before writing anything,
// write the dataset-level files, then one trial at a time, rewriting participants.tsv and the
// subject's scans.tsv after each so the dataset on disk is complete and valid whenever it stops.
#include "core/export/bids_dataset.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include "core/common/error.h"
#include "core/export/bids_dataset_files.h"
#include "core/export/bids_motion_files.h"
#include "core/export/bids_names.h"
#include "core/export/bids_study.h"
#include "core/export/bids_trial_sidecar.h"
#include "core/io/atomic_write.h"
#include "core/io/json_checked.h"
#include "core/io/layout_json.h"
#include "core/io/recorder_sidecar.h"

namespace fs = std::filesystem;

namespace lmc {
namespace bids_dataset_detail {  // named: core compiles in unity batches

void write_json(const fs::path& path, const nlohmann::json& j) {
  write_file_atomically(path, j.dump(2) + "\n");
}

// True when `path` is `dir` or lies under it (both resolved, so "a/../b" and symlinks count).
bool lies_inside(const fs::path& path, const fs::path& dir) {
  const fs::path p = fs::weakly_canonical(fs::absolute(path));
  const fs::path d = fs::weakly_canonical(fs::absolute(dir));
  const fs::path rel = p.lexically_relative(d);
  return !rel.empty() && *rel.begin() != "..";
}

void check_anonymise_key(const BidsExportRequest& request) {
  if (!request.anonymise) return;
  if (request.anonymise_key.empty()) throw Error("--anonymise needs a key file (id → label) outside the dataset");
  if (lies_inside(request.anonymise_key, request.out_dir)) {
    throw Error(ErrorLocation(request.anonymise_key.string()),
                "the anonymisation key must lie outside the dataset folder " + request.out_dir.string() +
                    " (it links the labels back to the subject ids); nothing was written");
  }
  if (fs::exists(request.anonymise_key) && !request.force) {
    throw Error(ErrorLocation(request.anonymise_key.string()),
                "the key file exists (use --force to replace it); nothing was written");
  }
}

// Refuses a non-empty folder unless forced. Forced into a dataset this program wrote, its subject
// folders and layouts go first: a subject left from an earlier export would otherwise stay in the
// folder without a row in participants.tsv.
void prepare_dataset_dir(const BidsExportRequest& request, std::vector<std::string>& notes) {
  const fs::path& out = request.out_dir;
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw Error(ErrorLocation(out.string()), "exists and is not a folder");
  if (fs::exists(out, ec) && !fs::is_empty(out, ec)) {
    if (!request.force) {
      throw Error(ErrorLocation(out.string()),
                  "the dataset folder is not empty (use --force to replace its files); nothing was written");
    }
    bool ours = false;
    try {
      ours = fs::exists(out / "dataset_description.json") &&
             bids_dataset_is_ours(read_json_file(out / "dataset_description.json"));
    } catch (const std::exception&) {
      ours = false;
    }
    if (ours) {
      for (const auto& entry : fs::directory_iterator(out)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory() && (name.rfind("sub-", 0) == 0 || name == kBidsLayoutsDir))
          fs::remove_all(entry.path());
      }
    } else {
      notes.push_back(out.string() +
                      " was not written by lmc export bids: its files were kept, those of the same name replaced");
    }
  }
  fs::create_directories(out);
}

struct Writer {
  const BidsExportRequest& request;
  BidsExportReport& report;
  std::vector<BidsParticipant> participants;
  std::map<std::string, std::vector<BidsScan>> scans;  // subject label → its files so far
  std::set<std::string> layouts_written;

  // One trial's files; returns the line for on_trial. Throws lmc::Error when the trial cannot be
  // processed (nothing of it is then listed in scans.tsv).
  std::string write_trial(const BidsSubjectPlan& s, const BidsTrialPlan& t) {
    ProcessedTrial outcome;
    const TrialAnalysis r = process_sources_in_full(t.job, request.session, &outcome);
    std::optional<MarkerSeries> markers;
    if (t.job.vicon && r.has_vicon) markers = load_vicon_markers(*t.job.vicon);
    const PointTable table = trial_point_table(r, markers ? &*markers : nullptr, ExportAxes::kWorld);
    if (table.frame_count() == 0) throw Error("the processed trial has no frames");
    std::optional<RecorderSidecar> sidecar;
    if (t.job.sidecar) sidecar = read_recorder_sidecar(*t.job.sidecar);
    const RecorderSidecar* sc = sidecar ? &*sidecar : nullptr;

    const std::string where = bids_session_dir(s.label, s.session_label);  // "sub-S01" or "sub-S01/ses-2"
    const fs::path subject_dir = request.out_dir / where;
    fs::create_directories(subject_dir / "motion");
    const std::vector<BidsTrackingSystem> systems = bids_tracking_systems(table);
    const std::string when = bids_trial_acq_time(sc, request.anonymise);
    std::vector<BidsScan> added;
    for (const auto& system : systems) {
      BidsEntities e = t.entities;
      e.tracksys = system.name;
      const std::string stem = bids_stem(e);
      const fs::path base = subject_dir / "motion" / stem;
      write_file_atomically(base.string() + "_channels.tsv", bids_channels_tsv(table, system));
      write_json(base.string() + "_channels.json", bids_channels_json());
      const BidsMotionInfo info = bids_motion_info(t, system, sc, request.session.process.method);
      write_json(base.string() + "_motion.json", bids_motion_json(table, system, info));
      write_file_atomically(base.string() + "_motion.tsv", bids_motion_tsv(table, system));
      added.push_back({"motion/" + stem + "_motion.tsv", when});
    }
    const std::vector<BidsEvent> events = bids_trial_events(r.world.start_us, sc);
    if (!events.empty()) {
      write_file_atomically(subject_dir / "motion" / (bids_stem(t.entities) + "_events.tsv"), bids_events_tsv(events));
    }
    write_layout(s, t);
    auto& listed = scans[where];
    listed.insert(listed.end(), added.begin(), added.end());
    write_file_atomically(subject_dir / (bids_session_prefix(s.label, s.session_label) + "_scans.tsv"),
                          bids_scans_tsv(listed));
    if (std::none_of(participants.begin(), participants.end(),
                     [&](const BidsParticipant& p) { return p.label == s.label; })) {
      participants.push_back({s.label, s.subject.handedness, s.subject.hand_length_mm, s.subject.hand_breadth_mm});
      write_file_atomically(request.out_dir / "participants.tsv", bids_participants_tsv(participants));
      ++report.subjects;
    }
    std::string line = "wrote " + where + "/motion/" + bids_stem(t.entities) + " (" + t.job.trial +
                       "): " + std::to_string(systems.size()) + " tracking systems, " +
                       std::to_string(table.frame_count()) + " frames";
    if (!table.has_vicon) {
      line += ", no Vicon";
      report.notes.push_back(where + " " + t.job.trial + ": no Vicon file next to it: controllers and fused hand only");
    }
    return line;
  }

  void write_layout(const BidsSubjectPlan& s, const BidsTrialPlan& t) {
    const std::string name = bids_session_prefix(s.label, s.session_label) + "_acq-" + t.entities.acq + "_layout.json";
    if (!layouts_written.insert(name).second) return;
    std::string used;
    const Layout layout = resolve_layout(t.job, request.session.layout, &used);
    fs::create_directories(request.out_dir / kBidsLayoutsDir);
    write_json(request.out_dir / kBidsLayoutsDir / name, layout_to_json(layout));
  }
};

}  // namespace bids_dataset_detail

BidsExportReport export_bids(const BidsExportRequest& request) {
  using namespace bids_dataset_detail;
  BidsExportReport report;
  report.dataset = request.out_dir;
  if (request.out_dir.empty()) throw Error("no dataset folder given");
  BidsStudyPlan plan = plan_bids_study(request.inputs, request.anonymise);
  report.notes = plan.notes;
  report.left_out = plan.left_out;
  if (plan.trial_count() == 0) {
    std::string why = plan.subjects.empty() ? "no subject session to export" : "no accepted trial to export";
    for (const auto& n : plan.notes) why += "\n  " + n;
    throw Error(why);
  }
  check_anonymise_key(request);
  prepare_dataset_dir(request, report.notes);

  // The dataset-level files first: from here on the folder is a dataset, at first with no subject.
  const std::string name =
      "Leap Motion Controller hand tracking (" + std::to_string(plan.subjects.size()) + " subject session(s))";
  write_json(request.out_dir / "dataset_description.json", bids_dataset_description(name));
  write_file_atomically(request.out_dir / "README", bids_readme(request.anonymise));
  write_file_atomically(request.out_dir / ".bidsignore", bids_ignore());
  write_json(request.out_dir / "participants.json", bids_participants_json());
  write_file_atomically(request.out_dir / "participants.tsv", bids_participants_tsv({}));
  if (request.anonymise) {
    std::string key = "participant_id\tsubject_id\tsession_folder\n";
    for (const auto& s : plan.subjects) {
      // One row per session folder: two sessions of one subject share the participant.
      key +=
          bids_subject_dir(s.label) + "\t" + s.subject.subject_id + "\t" + fs::absolute(s.session_dir).string() + "\n";
    }
    if (request.anonymise_key.has_parent_path()) fs::create_directories(request.anonymise_key.parent_path());
    write_file_atomically(request.anonymise_key, key);
  }

  Writer writer{request, report, {}, {}, {}};
  const int total = plan.trial_count();
  int done = 0;
  for (const auto& s : plan.subjects) {
    for (const auto& t : s.trials) {
      if (request.on_progress) request.on_progress(done, total);
      if (request.should_stop && request.should_stop()) {
        report.cancelled = true;
        report.notes.push_back("cancelled after " + std::to_string(done) + " of " + std::to_string(total) +
                               " trial(s)");
        return report;
      }
      ++done;
      try {
        const std::string line = writer.write_trial(s, t);
        ++report.trials;
        if (request.on_trial) request.on_trial(line);
      } catch (const std::exception& e) {
        const std::string what = e.what();
        const std::string prefix = t.job.trial + ": ";
        const std::string note = "left out " + bids_session_dir(s.label, s.session_label) + " " +
                                 (what.rfind(prefix, 0) == 0 ? what : prefix + what);
        report.notes.push_back(note);
        ++report.left_out;
        if (request.on_trial) request.on_trial(note);
      }
    }
  }
  if (request.on_progress) request.on_progress(done, total);
  return report;
}

}  // namespace lmc
