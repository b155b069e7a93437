// The BIDS export's order of work: plan everything (bids_study), refuse before writing anything,
// write the dataset-level files, then one trial at a time, rewriting participants.tsv and the
// subject's scans.tsv after each so the dataset on disk is complete and valid whenever it stops.
#include "core/export/bids_dataset.h"

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <set>

#include "core/common/error.h"
#include "core/export/bids_dataset_files.h"
#include "core/export/bids_motion_files.h"
#include "core/export/bids_names.h"
#include "core/export/bids_study.h"
#include "core/io/atomic_write.h"
#include "core/io/json_checked.h"
#include "core/io/layout_json.h"
#include "core/io/recorder_sidecar.h"

namespace fs = std::filesystem;

namespace lmc {
namespace bids_dataset_detail {  // named: core compiles in unity batches

void write_json(const fs::path& path, const nlohmann::json& j) { write_file_atomically(path, j.dump(2) + "\n"); }

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
    throw Error(ErrorLocation(request.anonymise_key.string()), "the key file exists (use --force to replace it); nothing was written");
  }
}

// Refuses a non-empty folder unless forced. Forced into a dataset this program wrote, its subject
// folders and layouts go first: a subject left from an earlier export would otherwise stay in the
// folder without a row in participants.tsv.
void prepare_dataset_dir(const BidsExportRequest& request, std::vector<std::string>& notes) {
  const fs::path& out = request.out_dir;
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) throw Error(ErrorLocation(out.string()), "exists and is not a folder");
  if (fs::exists(out, ec) && !fs::is_empty(out, ec)) {
    if (!request.force) {
      throw Error(ErrorLocation(out.string()), "the dataset folder is not empty (use --force to replace its files); nothing was written");
    }
    bool ours = false;
    try {
      ours = fs::exists(out / "dataset_description.json") && bids_dataset_is_ours(read_json_file(out / "dataset_description.json"));
    } catch (const std::exception&) {
      ours = false;
    }
    if (ours) {
      for (const auto& entry : fs::directory_iterator(out)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory() && (name.rfind("sub-", 0) == 0 || name == kBidsLayoutsDir)) fs::remove_all(entry.path());
      }
    } else {
      notes.push_back(out.string() + " was not written by lmc export bids: its files were kept, those of the same name replaced");
    }
  }
  fs::create_directories(out);
}

std::string software_line(const RecorderSidecar* sidecar) {
  std::string s;
  if (sidecar != nullptr && !sidecar->software_name.empty()) {
    s = "recorded with " + sidecar->software_name + " " + sidecar->software_version + " (" + sidecar->backend + " backend); ";
  }
  return s + "processed with lmc-workbench " LMC_VERSION;
}

// The recorder keeps no model name; a newer sidecar's device entry may carry one.
std::string controller_model(const RecorderSidecar* sidecar, int device_id) {
  if (sidecar == nullptr) return "Leap Motion Controller";
  if (const SidecarDevice* d = sidecar->device(device_id); d != nullptr && d->unknown.contains("model") && d->unknown["model"].is_string()) {
    return d->unknown["model"].get<std::string>();
  }
  return sidecar->backend == "sim" ? "simulated Leap Motion Controller" : "Leap Motion Controller";
}

BidsMotionInfo motion_info(const BidsTrialPlan& t, const BidsTrackingSystem& system, const RecorderSidecar* sidecar,
                           const BidsExportRequest& request) {
  BidsMotionInfo info;
  info.task_name = t.motion;
  info.task_description = t.operator_cue;
  info.instructions = t.subject_cue;
  info.software_versions = software_line(sidecar);
  const std::string method = fusion_method_name(request.session.process.method);
  if (system.name == kBidsViconTracksys) {
    info.manufacturer = "Vicon";
    info.tracking_system_name = "Vicon markers of the trial's " + (t.job.vicon ? t.job.vicon->filename().string() : std::string("Vicon file")) +
                                ", frame f on the processing grid's frame f";
    if (sidecar != nullptr && sidecar->backend == "sim") info.model = "simulated (the simulated rig's ground truth)";
    return info;
  }
  info.manufacturer = "Ultraleap";
  if (system.name == kBidsFusedTracksys) {
    info.tracking_system_name = "the hand fused from every controller by lmc-workbench (" + method + " method)";
    info.model = controller_model(sidecar, 1);
    info.software_versions += " (" + method + " fusion)";
    return info;
  }
  info.tracking_system_name = "the Leap Motion Controller in slot " + system.name + ", realigned into the world frame";
  info.model = controller_model(sidecar, system.device_id);
  if (sidecar != nullptr) {
    if (const SidecarDevice* d = sidecar->device(system.device_id)) info.serial = d->serial;
  }
  return info;
}

std::optional<std::int64_t> json_int(const nlohmann::json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<std::int64_t>();
}

// go, stop and the Vicon trigger on the device clock (the grid's), as seconds from the first row.
std::vector<BidsEvent> trial_events(const TrialResult& r, const RecorderSidecar* sidecar) {
  std::vector<BidsEvent> events;
  if (sidecar == nullptr) return events;
  const double start = static_cast<double>(r.world.start_us);
  std::int64_t first = std::numeric_limits<std::int64_t>::max(), last = std::numeric_limits<std::int64_t>::min();
  for (const auto& d : sidecar->devices) {
    if (d.frames_written <= 0) continue;
    first = std::min(first, d.first_timestamp_us);
    last = std::max(last, d.last_timestamp_us);
  }
  const bool rows = first <= last;
  // The file starts at go only when the sidecar has the trial window and the trial reached go.
  const bool has_go = rows && json_int(sidecar->trial_window, "go_host_ns").has_value();
  if (has_go) events.push_back({(static_cast<double>(first) - start) * 1e-6, (static_cast<double>(last - first)) * 1e-6, "go"});
  if (rows) events.push_back({(static_cast<double>(last) - start) * 1e-6, 0.0, "stop"});
  std::optional<std::int64_t> vicon;
  if (sidecar->vicon_alignment.is_object() && sidecar->vicon_alignment.contains("devices") && sidecar->vicon_alignment["devices"].is_array()) {
    for (const auto& d : sidecar->vicon_alignment["devices"]) {
      if ((vicon = json_int(d, "device_clock_at_event_us"))) break;
    }
  }
  if (!vicon && sidecar->ground_truth) vicon = sidecar->ground_truth->device_clock_at_time_zero_us;
  if (vicon) events.push_back({(static_cast<double>(*vicon) - start) * 1e-6, 0.0, "vicon_capture_start"});
  std::stable_sort(events.begin(), events.end(), [](const BidsEvent& a, const BidsEvent& b) { return a.onset_s < b.onset_s; });
  return events;
}

std::string acq_time(const RecorderSidecar* sidecar, bool anonymise) {
  // Dates identify a subject as well as a name does: an anonymised dataset leaves them out.
  if (sidecar == nullptr || anonymise) return {};
  if (sidecar->trial_window.is_object() && sidecar->trial_window.contains("go_host_utc") && sidecar->trial_window["go_host_utc"].is_string()) {
    return bids_acq_time(sidecar->trial_window["go_host_utc"].get<std::string>());
  }
  return bids_acq_time(sidecar->host_start_utc);
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
    TrialOutcome outcome;
    const TrialResult r = process_job_in_full(t.job, request.session, &outcome);
    std::optional<MarkerSeries> markers;
    if (t.job.vicon && r.has_vicon) markers = load_vicon_markers(*t.job.vicon);
    const PointTable table = trial_point_table(r, markers ? &*markers : nullptr, ExportAxes::kWorld);
    if (table.frame_count() == 0) throw Error("the processed trial has no frames");
    std::optional<RecorderSidecar> sidecar;
    if (t.job.sidecar) sidecar = read_recorder_sidecar(*t.job.sidecar);
    const RecorderSidecar* sc = sidecar ? &*sidecar : nullptr;

    const fs::path subject_dir = request.out_dir / bids_subject_dir(s.label);
    fs::create_directories(subject_dir / "motion");
    const std::vector<BidsTrackingSystem> systems = bids_tracking_systems(table);
    const std::string when = acq_time(sc, request.anonymise);
    std::vector<BidsScan> added;
    for (const auto& system : systems) {
      BidsEntities e = t.entities;
      e.tracksys = system.name;
      const std::string stem = bids_stem(e);
      const fs::path base = subject_dir / "motion" / stem;
      write_file_atomically(base.string() + "_channels.tsv", bids_channels_tsv(table, system));
      write_json(base.string() + "_channels.json", bids_channels_json());
      write_json(base.string() + "_motion.json", bids_motion_json(table, system, motion_info(t, system, sc, request)));
      write_file_atomically(base.string() + "_motion.tsv", bids_motion_tsv(table, system));
      added.push_back({"motion/" + stem + "_motion.tsv", when});
    }
    const std::vector<BidsEvent> events = trial_events(r, sc);
    if (!events.empty()) {
      write_file_atomically(subject_dir / "motion" / (bids_stem(t.entities) + "_events.tsv"), bids_events_tsv(events));
    }
    write_layout(s, t);
    auto& listed = scans[s.label];
    listed.insert(listed.end(), added.begin(), added.end());
    write_file_atomically(subject_dir / (bids_subject_dir(s.label) + "_scans.tsv"), bids_scans_tsv(listed));
    if (std::none_of(participants.begin(), participants.end(), [&](const BidsParticipant& p) { return p.label == s.label; })) {
      participants.push_back({s.label, s.subject.handedness, s.subject.hand_length_mm, s.subject.hand_breadth_mm});
      write_file_atomically(request.out_dir / "participants.tsv", bids_participants_tsv(participants));
      ++report.subjects;
    }
    std::string line = "wrote " + bids_subject_dir(s.label) + "/motion/" + bids_stem(t.entities) + " (" + t.job.trial + "): " +
                       std::to_string(systems.size()) + " tracking systems, " + std::to_string(table.frame_count()) + " frames";
    if (!table.has_vicon) {
      line += ", no Vicon";
      report.notes.push_back(bids_subject_dir(s.label) + " " + t.job.trial + ": no Vicon file next to it: controllers and fused hand only");
    }
    return line;
  }

  void write_layout(const BidsSubjectPlan& s, const BidsTrialPlan& t) {
    const std::string name = "sub-" + s.label + "_acq-" + t.entities.acq + "_layout.json";
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
  const std::string name = "Leap Motion Controller hand tracking (" + std::to_string(plan.subjects.size()) + " subject session(s))";
  write_json(request.out_dir / "dataset_description.json", bids_dataset_description(name));
  write_file_atomically(request.out_dir / "README", bids_readme(request.anonymise));
  write_file_atomically(request.out_dir / ".bidsignore", bids_ignore());
  write_json(request.out_dir / "participants.json", bids_participants_json());
  write_file_atomically(request.out_dir / "participants.tsv", bids_participants_tsv({}));
  if (request.anonymise) {
    std::string key = "participant_id\tsubject_id\tsession_folder\n";
    for (const auto& s : plan.subjects) {
      key += bids_subject_dir(s.label) + "\t" + s.subject.subject_id + "\t" + fs::absolute(s.session_dir).string() + "\n";
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
        report.notes.push_back("cancelled after " + std::to_string(done) + " of " + std::to_string(total) + " trial(s)");
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
        const std::string note = "left out " + bids_subject_dir(s.label) + " " + (what.rfind(prefix, 0) == 0 ? what : prefix + what);
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
