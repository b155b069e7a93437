#pragma once
// A soak: a subject session on the simulated rig — N controllers at a fixed rate, trials back to
// back through the trial engine (trial_engine.h), each checked and given its verdict as the
// session runner does — with, in the same process, the live fused hand (grouped_fusion.h) and a
// workbench's other work on one thread (background_load.h). Every second it samples resident
// memory, open descriptors, threads, the recorder's queue depth and the live fusion's drops.
//
// Lost frames are counted from the source's side (counting_source.h): every frame the simulator
// produced inside a trial's window that is not a row of its file, whichever part lost it; the
// sidecar then says which: the recorder's queue (full: the writer fell behind) or the writer (a
// write error; the file's status says failed). The live fusion's drops are display-only and
// counted apart. Growth is judged on what the program holds (heap in use, descriptors, threads)
// against the first trial's end, when allocations a recording needs once have been made. Resident
// memory is reported, never judged: the allocator may keep freed pages, which is not a leak.
//
// The rig's frames cost what real controllers' would: the simulator models each controller's
// view (occlusion, field of view), and a rig too big for one simulator thread falls behind —
// reported as the source's rate, never as loss.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/layout/layout.h"
#include "devices/fusion/live_fusion.h"
#include "devices/record/byte_sink.h"
#include "devices/soak/background_load.h"
#include "devices/soak/process_stats.h"

namespace lmc::devices {

struct SoakConfig {
  double seconds = 20;
  int devices = 4;            // 1 … kMaxSoakDevices
  double rate_hz = 120;       // every controller, fixed
  double trial_seconds = 10;  // each trial of the session; the last one is cut to fit
  // The trials' files; each trial's are removed once checked unless keep_files.
  std::filesystem::path output_dir;
  bool keep_files = false;
  bool fusion = true;
  bool background = true;
  bool verdict = true;
  double progress_every_s = 60;
  // The heap in use may end this much above the first trial's end (plus a tenth of it) before the
  // soak calls it growth. Each is the least seen over a trial's length (heap_floors), so memory
  // that comes and goes with the background work is not counted.
  double heap_allowance_mb = 8;
  // A self-check of the growth test: the soak holds this much more memory after every trial, as a
  // leak would, and must then fail. 0 in every real soak.
  double leak_mb_per_trial = 0;
  std::uint64_t seed = 1;
  // Tests: where each trial's rows go (a sink that fails like a full disk); default the file.
  std::function<std::unique_ptr<ByteSink>(const std::filesystem::path&)> open_sink;
};

inline constexpr int kMaxSoakDevices = 64;

struct SoakSample {
  double t_s = 0;  // since the rig started
  ProcessStats process;
  std::int64_t queue_depth_max = 0;  // recorder queue, the most seen during the second
  std::int64_t fusion_dropped = 0;   // so far
  std::int64_t frames_written = 0;   // so far
};

struct SoakTrial {
  std::string name;
  double seconds = 0;
  std::string status;              // the sidecar's: completed | failed | aborted
  std::int64_t produced = 0;       // frames the source produced inside the trial's window
  std::int64_t written = 0;        // rows in the file (the sidecar's count)
  std::int64_t queue_dropped = 0;  // the recorder's queue was full
  std::int64_t writer_lost = 0;    // the rest of what was lost (a write error)
  std::int64_t lost() const { return produced - written; }
  std::string verdict;  // pass | warn | fail ("" when not judged: off, or more than kMaxDevices controllers)
  std::vector<std::string> reasons;
};

struct SoakReport {
  SoakConfig config;
  double elapsed_s = 0;
  std::int64_t produced = 0, written = 0, lost = 0, queue_dropped = 0, writer_lost = 0;
  std::int64_t source_frames = 0;   // everything the simulator produced, trials and the gaps between
  double source_rate_fraction = 0;  // source_frames / (devices × rate × time): < 1 when it fell behind
  LiveFusionStats fusion;
  BackgroundLoadCounts background;
  ProcessStats start, baseline,
      end;  // before the rig starts, after the first trial, after the last
  double rss_max_mb = 0;
  // The least heap in use over a trial's length after the first trial and at the end: what growth
  // is judged on.
  double heap_floor_baseline_mb = 0, heap_floor_end_mb = 0;
  std::int64_t queue_depth_max = 0;
  std::vector<SoakSample> samples;
  std::vector<SoakTrial> trials;
  std::vector<std::string> problems;  // why the soak failed: loss, growth, a trial that failed
  std::vector<std::string> notes;     // worth reading, not a failure
  bool ok() const { return problems.empty(); }
};

// N controllers: the study's initial layout repeated around the hand, slots LMC1…LMCN. Above
// kMaxDevices it is not a layout a lab could load (layouts hold 1–8 controllers): the soak's rig
// only, recorded and judged as one.
Layout soak_layout(int devices);

// Runs the soak; `progress` gets a line every config.progress_every_s (any thread, one at a
// time). Throws lmc::Error for a bad config or an output folder it cannot use.
SoakReport run_soak(const SoakConfig& config, const std::function<void(const std::string&)>& progress = {});

// "soak: 57600 frames from 16 controllers in 30 s, 0 lost, heap 10→10 MB, RSS 61→64 MB, fds 9→9" (contract-figure)
std::string soak_summary_line(const SoakReport& report);
nlohmann::json soak_report_to_json(const SoakReport& report);

}  // namespace lmc::devices
