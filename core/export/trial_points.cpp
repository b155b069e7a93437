#include "core/export/trial_points.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include "core/common/error.h"
#include "core/common/safe_name.h"
#include "core/export/bids_dataset_files.h"
#include "core/hand/hand_frame.h"
#include "core/session/session_trials.h"

namespace lmc {
namespace {

namespace fs = std::filesystem;

constexpr double kNaNExport = std::numeric_limits<double>::quiet_NaN();

constexpr std::array<const char*, kNumDigits> kDigitLabels = {"Thumb", "Index", "Middle", "Ring", "Pinky"};
constexpr std::array<const char*, kJointsPerDigit> kJointLabels = {"Meta", "Proxi", "Inter", "Dist", "End"};

// World (x along the table, y up, z towards the subject) to OpenSim (X forward, Y up, Z right):
// the subject faces −z, so forward = −z and right = forward × up = +x. A proper rotation.
Eigen::Vector3d to_axes(const Eigen::Vector3d& p, ExportAxes axes) {
  if (axes == ExportAxes::kOpenSim) return {-p.z(), p.y(), p.x()};
  return p;
}

bool is_finite_point(const Eigen::Vector3d& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

void add_hand(PointTable& t, const HandTrack& track, const std::string& prefix, const std::string& who) {
  const int frames = t.frame_count();
  for (const int i : exported_hand_points()) {
    t.labels.push_back(prefix + landmark_name(i));
    t.descriptions.push_back(who + ": " + hand_point_words(i));
    for (int f = 0; f < frames; ++f) {
      Eigen::Vector3d p = Eigen::Vector3d::Constant(kNaNExport);
      if (f < track.frame_count && is_finite_point(track.at(f, i))) p = to_axes(track.at(f, i), t.axes);
      t.positions[static_cast<size_t>(f)].push_back(p);
    }
  }
}

}  // namespace

const char* export_axes_name(ExportAxes axes) {
  return axes == ExportAxes::kOpenSim ? "opensim" : "world";
}

ExportAxes export_axes_from_name(const std::string& name) {
  if (name == "world") return ExportAxes::kWorld;
  if (name == "opensim") return ExportAxes::kOpenSim;
  throw Error("unknown axes '" + name + "' (expected world or opensim)");
}

std::string export_axes_words(ExportAxes axes) {
  if (axes == ExportAxes::kOpenSim) {
    return "OpenSim axes: X forward from the subject (world -z), Y up (world y), Z to the subject's right (world x)";
  }
  return "world frame: x along the table, y up (table top y = 0), z towards the subject";
}

const std::vector<int>& exported_hand_points() {
  static const std::vector<int> points = [] {
    std::vector<int> p{kPalm, kElbow, kWrist};
    for (int d = 0; d < kNumDigits; ++d) {
      for (int j = 0; j < kJointsPerDigit; ++j) p.push_back(digit_point(d, j));
    }
    return p;
  }();
  return points;
}

std::string landmark_name(int hand_point) {
  if (hand_point == kPalm) return "Palm";
  if (hand_point == kElbow) return "Elbow";
  if (hand_point == kWrist) return "Wrist";
  if (hand_point < kFirstDigitPoint || hand_point >= kNumHandPoints) return {};
  const int d = (hand_point - kFirstDigitPoint) / kJointsPerDigit,
            j = (hand_point - kFirstDigitPoint) % kJointsPerDigit;
  return std::string(kDigitLabels[static_cast<size_t>(d)]) + "_" + kJointLabels[static_cast<size_t>(j)];
}

std::string export_label(const std::string& name) {
  std::string out;
  for (const char c : name) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
    out += keep ? c : '_';
  }
  return out.empty() ? std::string("_") : out;
}

int PointTable::label_index(const std::string& label) const {
  const auto it = std::find(labels.begin(), labels.end(), label);
  return it == labels.end() ? -1 : static_cast<int>(it - labels.begin());
}

PointTable trial_point_table(const TrialAnalysis& result, const MarkerSeries* vicon_markers, ExportAxes axes) {
  PointTable t;
  t.trial = result.tag.trial.empty() ? std::string("trial") : result.tag.trial;
  t.rate_hz = 1e6 / result.world.step_us;
  t.axes = axes;
  const int frames = std::max(result.world.frame_count, result.fused.frame_count);
  t.positions.resize(static_cast<size_t>(frames));
  add_hand(t, result.fused, "F_", "fused hand");
  for (const auto& d : result.world.devices) {
    const std::string name = "LMC" + std::to_string(d.device_id);
    add_hand(t, d.track, name + "_", name + " realigned");
  }
  if (vicon_markers != nullptr && result.has_vicon) {
    t.has_vicon = true;
    std::set<std::string> used(t.labels.begin(), t.labels.end());
    for (size_t m = 0; m < vicon_markers->names.size(); ++m) {
      // Two markers whose names differ only in characters the label cannot hold stay apart.
      std::string label = "V_" + export_label(vicon_markers->names[m]);
      for (int k = 2; used.count(label) != 0; ++k)
        label = "V_" + export_label(vicon_markers->names[m]) + "_" + std::to_string(k);
      used.insert(label);
      t.labels.push_back(label);
      t.descriptions.push_back("Vicon marker " + vicon_markers->names[m]);
      for (int f = 0; f < frames; ++f) {
        Eigen::Vector3d p = Eigen::Vector3d::Constant(kNaNExport);
        const auto& rows = vicon_markers->positions;
        if (static_cast<size_t>(f) < rows.size() && m < rows[static_cast<size_t>(f)].size() &&
            is_finite_point(rows[static_cast<size_t>(f)][m])) {
          p = to_axes(rows[static_cast<size_t>(f)][m], axes);
        }
        t.positions[static_cast<size_t>(f)].push_back(p);
      }
    }
  }
  return t;
}

C3dData point_table_c3d(const PointTable& table) {
  C3dData c;
  c.float_storage = true;
  c.point_scale = -1.0;
  c.point_rate_hz = table.rate_hz;
  c.units = "mm";
  c.first_frame = 1;
  c.labels = table.labels;
  c.descriptions = table.descriptions;
  c.positions = table.positions;
  c.manufacturer_company = "lmc-workbench";
  c.manufacturer_software = std::string("lmc export (") + export_axes_words(table.axes) + ")";
  c.manufacturer_version = LMC_VERSION;
  return c;
}

TrcData point_table_trc(const PointTable& table) {
  TrcData t;
  t.data_rate_hz = table.rate_hz;
  t.camera_rate_hz = table.rate_hz;
  t.units = "mm";
  t.orig_data_start_frame = 1;
  t.marker_names = table.labels;
  t.positions = table.positions;
  for (int f = 0; f < table.frame_count(); ++f) {
    t.frame_numbers.push_back(f + 1);
    t.times_s.push_back(f / table.rate_hz);
  }
  return t;
}

const char* export_format_extension(ExportFormat format) {
  return format == ExportFormat::kC3d ? ".c3d" : ".trc";
}

namespace {

struct PlannedExport {
  TrialSources job;
  fs::path target;
};

// Every trial of every input with its target file; inputs that cannot be read, unsafe trial names
// and repeated names are left out with a note.
std::vector<PlannedExport> plan_trial_exports(const TrialExportRequest& request, TrialExportReport& report) {
  std::vector<PlannedExport> planned;
  std::set<std::string> names;
  for (const auto& input : request.inputs) {
    std::vector<TrialSources> jobs;
    std::vector<std::string> notes;
    try {
      jobs = trial_sources_for_input(input, std::nullopt, &notes);
    } catch (const std::exception& e) {
      report.notes.push_back("left out " + input.string() + ": " + e.what());
      ++report.left_out;
      continue;
    }
    for (auto& n : notes) report.notes.push_back(n);
    for (auto& job : jobs) {
      // The trial name comes from a file name: it becomes a path only once it is a safe name.
      const std::string problem = safe_name_problem(job.trial, "trial name");
      if (!problem.empty()) {
        report.notes.push_back("left out " + job.lmc.string() + ": " + problem);
        ++report.left_out;
        continue;
      }
      if (!names.insert(job.trial).second) {
        report.notes.push_back("left out " + job.lmc.string() + ": another input already gives a trial named " +
                               job.trial);
        ++report.left_out;
        continue;
      }
      planned.push_back({job, request.out_dir / (job.trial + export_format_extension(request.format))});
    }
  }
  return planned;
}

// Nothing is written when a target exists and the request does not say to replace it.
void refuse_existing_exports(const std::vector<PlannedExport>& planned, bool force) {
  if (force) return;
  std::string existing;
  for (const auto& p : planned) {
    if (fs::exists(p.target)) existing += "\n  " + p.target.string();
  }
  if (!existing.empty())
    throw Error("these outputs exist (use --force to replace them); nothing was written:" + existing);
}

// Processes one trial in full and writes its points; returns the progress line. Throws what
// processing or writing throws.
std::string export_one_trial(const PlannedExport& p, const TrialExportRequest& request, TrialExportReport& report) {
  ProcessedTrial outcome;
  const TrialAnalysis r = process_sources_in_full(p.job, request.session, &outcome);
  std::optional<MarkerSeries> markers;
  if (p.job.vicon && r.has_vicon) markers = load_vicon_markers(*p.job.vicon);
  PointTable table = trial_point_table(r, markers ? &*markers : nullptr, request.axes);
  table.trial = p.job.trial;
  if (table.frame_count() == 0) throw Error("the processed trial has no frames");
  if (request.format == ExportFormat::kC3d) {
    save_c3d(p.target, point_table_c3d(table));
  } else {
    save_trc(p.target, point_table_trc(table));
  }
  report.written.push_back(p.target);
  report.exported.push_back(p.job.trial);
  std::string line = "wrote " + p.target.string() + " (" + std::to_string(table.frame_count()) + " frames, " +
                     std::to_string(table.point_count()) + " points";
  if (table.has_vicon) {
    line += ", with Vicon)";
  } else {
    line += ", no Vicon)";
    report.notes.push_back(p.job.trial + ": no Vicon file (" + p.job.trial +
                           ".trc or .c3d) next to it: fused and controller points only");
  }
  return line;
}

}  // namespace

TrialExportReport export_trials(const TrialExportRequest& request) {
  if (const std::filesystem::path dataset = bids_dataset_root_of(request.out_dir); !dataset.empty()) {
    throw Error(ErrorLocation(request.out_dir.string()),
                "lies in the BIDS dataset " + dataset.string() +
                    " (it holds dataset_description.json): a C3D or TRC file there is not part of the dataset "
                    "and makes it invalid; choose a folder outside it; nothing was written");
  }
  TrialExportReport report;
  const std::vector<PlannedExport> planned = plan_trial_exports(request, report);
  if (planned.empty()) {
    std::string why = "no trial to export";
    for (const auto& n : report.notes) why += "\n  " + n;
    throw Error(why);
  }
  refuse_existing_exports(planned, request.force);
  fs::create_directories(request.out_dir);
  const int total = static_cast<int>(planned.size());
  int done = 0;
  for (const auto& p : planned) {
    if (request.on_progress) request.on_progress(done, total);
    if (request.should_stop && request.should_stop()) {
      report.cancelled = true;
      report.notes.push_back("cancelled after " + std::to_string(done) + " of " + std::to_string(total) + " trial(s)");
      return report;
    }
    ++done;
    try {
      const std::string line = export_one_trial(p, request, report);
      if (request.on_trial) request.on_trial(line);
    } catch (const std::exception& e) {
      // Processing's messages already start with the trial's name.
      const std::string what = e.what();
      const std::string prefix = p.job.trial + ": ";
      report.notes.push_back("left out " + (what.rfind(prefix, 0) == 0 ? what : prefix + what));
      ++report.left_out;
    }
  }
  if (request.on_progress) request.on_progress(done, total);
  return report;
}

}  // namespace lmc
