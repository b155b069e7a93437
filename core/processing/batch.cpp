#include "core/processing/batch.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <map>

#include "core/common/error.h"
#include "core/common/number_format.h"
#include "core/io/c3d.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "core/io/trc.h"
#include "core/processing/trial_summary.h"
#include "core/processing/trial_tag.h"

namespace fs = std::filesystem;

namespace lmc {
namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Rank of an LMC file kind: lower wins.
int lmc_rank(const std::string& name) {
  if (ends_with(name, ".raw.txt")) return 0;
  if (ends_with(name, ".resampled.txt")) return 2;
  if (ends_with(name, ".raytraced.txt")) return 3;
  return 1;  // Interp_LMC_<trial>.txt / LMC_<trial>.txt
}

bool is_lmc_file(const std::string& name) {
  if (!ends_with(name, ".txt")) return false;
  // Our own outputs are never inputs.
  for (const char* out : {".fused.txt", ".results.txt"}) {
    if (ends_with(name, out)) return false;
  }
  return name.rfind("LMC_", 0) == 0 || name.rfind("Interp_LMC_", 0) == 0;
}

std::optional<fs::path> find_vicon(const fs::path& dir, const std::string& trial) {
  for (const char* ext : {".trc", ".c3d", ".TRC", ".C3D"}) {
    const fs::path p = dir / (trial + ext);
    if (fs::exists(p)) return p;
  }
  return std::nullopt;
}

}  // namespace

std::vector<TrialSources> discover_trials(const fs::path& input, const std::optional<fs::path>& vicon,
                                          std::vector<std::string>* notes) {
  std::vector<TrialSources> jobs;
  if (!fs::exists(input)) throw Error(ErrorLocation(input.string()), "no such file or folder");
  if (!fs::is_directory(input)) {
    TrialSources j;
    j.lmc = input;
    j.trial = trial_name_of(input.filename().string());
    if (vicon && !fs::is_directory(*vicon)) {
      j.vicon = *vicon;
    } else {
      j.vicon = find_vicon(vicon ? *vicon : input.parent_path(), j.trial);
    }
    const fs::path side = input.parent_path() / ("LMC_" + j.trial + ".session.json");
    if (fs::exists(side)) j.sidecar = side;
    jobs.push_back(j);
    return jobs;
  }
  if (vicon && !fs::is_directory(*vicon)) {
    throw Error(ErrorLocation(vicon->string()), "--vicon must be a folder when the input is a session folder");
  }
  std::map<std::string, std::pair<int, fs::path>> best;
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(input)) {
    if (e.is_regular_file()) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  for (const auto& p : files) {
    const std::string name = p.filename().string();
    if (!is_lmc_file(name)) continue;
    const std::string trial = trial_name_of(name);
    const int rank = lmc_rank(name);
    auto it = best.find(trial);
    if (it == best.end() || rank < it->second.first) {
      if (it != best.end() && notes != nullptr)
        notes->push_back(trial + ": using " + name + " instead of " + it->second.second.filename().string());
      best[trial] = {rank, p};
    } else if (notes != nullptr) {
      notes->push_back(trial + ": using " + it->second.second.filename().string() + ", ignoring " + name);
    }
  }
  for (const auto& [trial, rp] : best) {
    TrialSources j;
    j.trial = trial;
    j.lmc = rp.second;
    j.vicon = find_vicon(vicon ? *vicon : rp.second.parent_path(), trial);
    const fs::path side = rp.second.parent_path() / ("LMC_" + trial + ".session.json");
    if (fs::exists(side)) j.sidecar = side;
    jobs.push_back(j);
  }
  return jobs;
}

MarkerSeries load_vicon_markers(const fs::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".c3d") return read_c3d(path).to_marker_series(path.string());
  TrcData trc = read_trc(path);
  trc.to_millimetres();
  MarkerSeries m;
  m.names = trc.marker_names;
  m.positions = std::move(trc.positions);
  m.rate_hz = trc.data_rate_hz;
  m.source = path.string();
  return m;
}

namespace {

// A trial's recorder sidecar, read when first needed and then only once (the layout and the
// simulator's ground truth both come from it).
class SidecarOnce {
 public:
  explicit SidecarOnce(const TrialSources& job) : job_(job) {}
  const RecorderSidecar& get() {
    if (!side_) side_ = read_recorder_sidecar(*job_.sidecar);
    return *side_;
  }

 private:
  const TrialSources& job_;
  std::optional<RecorderSidecar> side_;
};

Layout resolve_layout_with(const TrialSources& job, const std::optional<std::string>& layout, SidecarOnce& sidecar,
                           std::string* used) {
  if (layout) {
    if (used) *used = *layout;
    return load_layout_or_preset(*layout);
  }
  if (job.sidecar) {
    const RecorderSidecar& side = sidecar.get();
    if (side.layout.is_object()) {
      if (used) *used = job.sidecar->filename().string() + " (recorded layout)";
      return layout_from_json(side.layout, job.sidecar->string() + "#/layout");
    }
  }
  if (job.layout_json) {
    if (used) *used = "the session's layout for this block";
    return layout_from_json(*job.layout_json, job.trial + " (session manifest layout)");
  }
  const TrialTag tag = parse_trial_tag(job.trial);
  const char* preset = nullptr;
  if (tag.layout == "initial") preset = "paper-initial";
  if (tag.layout == "optimized") preset = "paper-optimized-as-processed";
  if (preset == nullptr) {
    throw Error("no layout for trial '" + job.trial +
                "': give --layout (the name is not Naiv_/Opti_… and there is no recorder sidecar)");
  }
  if (used) *used = preset;
  return load_layout_or_preset(preset);
}

}  // namespace

Layout resolve_layout(const TrialSources& job, const std::optional<std::string>& layout, std::string* used) {
  SidecarOnce sidecar(job);
  return resolve_layout_with(job, layout, sidecar, used);
}

ProcessedTrial process_sources(const TrialSources& job, const BatchOptions& options, const ViconMapping& mapping) {
  ProcessedTrial out;
  out.trial = job.trial;
  try {
    SidecarOnce sidecar(job);
    const Layout layout = resolve_layout_with(job, options.layout, sidecar, &out.layout_used);
    const LmcRecording rec = read_lmc_recording(job.lmc);
    HandTrack vicon_track;
    const HandTrack* vicon = nullptr;
    if (job.vicon) {
      const MarkerSeries markers = load_vicon_markers(*job.vicon);
      if (std::abs(markers.rate_hz - 100.0) > 0.5) {
        throw Error(ErrorLocation(job.vicon->string()), "Vicon rate is " + format_fixed(markers.rate_hz, 2) +
                                                            " Hz; processing expects 100 Hz like the LMC grid");
      }
      vicon_track = apply_vicon_mapping(mapping, markers);
      if (vicon_track.frame_count < options.process.min_vicon_seconds * 100.0) {
        throw Error(ErrorLocation(job.vicon->string()),
                    "only " + std::to_string(vicon_track.frame_count) + " frames (" +
                        format_fixed(vicon_track.frame_count / 100.0, 2) +
                        " s at 100 Hz); a trial's Vicon capture must last at least " +
                        format_fixed(options.process.min_vicon_seconds, 1) + " s");
      }
      vicon = &vicon_track;
      out.has_vicon = true;
    } else {
      out.warnings.push_back("no Vicon file (" + job.trial + ".trc or .c3d) next to it: LMC measures only");
    }
    ProcessOptions popt = options.process;
    if (options.compare_methods && popt.length_correction) {
      // The comparison runs the reference method too, which never takes a length correction.
      throw Error("the method comparison runs without a length correction: drop one of the two");
    }
    if (job.sidecar && vicon != nullptr) {
      // The simulator notes which device-clock time its ground truth's frame 0 is (sessions/README.md).
      const RecorderSidecar& side = sidecar.get();
      if (side.ground_truth) popt.resample.grid_start_us = side.ground_truth->device_clock_at_time_zero_us;
    }
    TrialAnalysis r = process_trial(job.trial, rec, layout, vicon, popt);
    r.lmc_source = job.lmc.string();
    if (job.vicon) r.vicon_source = job.vicon->string();
    for (const auto& w : r.warnings) out.warnings.push_back(w);
    r.warnings = out.warnings;
    r.layout_source = out.layout_used;
    out.summary = trial_summary_json(r);
    if (options.on_result) options.on_result(r, out.summary);
    if (options.compare_methods && vicon != nullptr) {
      ProcessOptions other = popt;
      other.method =
          options.process.method == FusionMethod::kReference ? FusionMethod::kDefault : FusionMethod::kReference;
      // What the errors read of this method's result is kept aside; the rest (grids, labels,
      // tracks, Vicon: megabytes a trial) is handed to the other method, which fuses, measures and
      // compares again and leaves them as they are.
      TrialAnalysis mine;
      mine.has_vicon = r.has_vicon;
      mine.labels = r.labels;
      mine.lmc_frames = std::move(r.lmc_frames);
      mine.vicon_frames = std::move(r.vicon_frames);
      const TrialAnalysis theirs = process_trial_with_method(std::move(r), job.trial, other);
      const MethodErrors mine_errors = trial_errors(mine, &theirs);
      const MethodErrors their_errors = trial_errors(theirs, &mine);
      if (options.process.method == FusionMethod::kReference) {
        out.reference_errors = mine_errors;
        out.default_errors = their_errors;
      } else {
        out.default_errors = mine_errors;
        out.reference_errors = their_errors;
      }
    }
    out.ok = true;
  } catch (const std::exception& e) {
    out.ok = false;
    out.error = e.what();
  }
  return out;
}

TrialAnalysis process_sources_in_full(const TrialSources& job, const BatchOptions& options, ProcessedTrial* outcome) {
  BatchOptions o = options;
  std::optional<TrialAnalysis> kept;
  o.on_result = [&kept](const TrialAnalysis& r, const nlohmann::json&) { kept = r; };
  o.compare_methods = false;
  const ViconMapping mapping = o.mapping ? load_vicon_mapping(*o.mapping) : default_vicon_mapping();
  ProcessedTrial out = process_sources(job, o, mapping);
  if (!out.ok || !kept) throw Error(job.trial + ": " + (out.error.empty() ? "processing gave no result" : out.error));
  if (outcome != nullptr) *outcome = std::move(out);
  return std::move(*kept);
}

std::vector<ProcessedTrial> process_batch(const std::vector<TrialSources>& jobs, const BatchOptions& options) {
  const ViconMapping mapping = options.mapping ? load_vicon_mapping(*options.mapping) : default_vicon_mapping();
  std::vector<ProcessedTrial> outcomes(jobs.size());
  std::atomic<int> done{0};
  const int total = static_cast<int>(jobs.size());
  tbb::parallel_for(size_t{0}, jobs.size(), [&](size_t k) {
    if (options.stop.stop_requested()) {
      outcomes[k].trial = jobs[k].trial;
      outcomes[k].cancelled = true;
      outcomes[k].error = "cancelled before it was processed";
    } else {
      outcomes[k] = process_sources(jobs[k], options, mapping);
    }
    const int now = ++done;
    if (options.on_progress) options.on_progress(now, total);
  });
  return outcomes;
}

}  // namespace lmc
