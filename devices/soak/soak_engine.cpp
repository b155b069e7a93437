#include "devices/soak/soak_engine.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <mutex>
#include <thread>

#include "core/common/error.h"
#include "core/io/layout_json.h"
#include "core/io/lmc_recording.h"
#include "core/io/recorder_sidecar.h"
#include "core/session/trial_quality.h"
#include "devices/device_hub.h"
#include "devices/record/trial_engine.h"
#include "devices/sim/sim_source.h"
#include "devices/soak/counting_source.h"
#include "devices/soak/grouped_fusion.h"

namespace lmc::devices {
namespace {

using Clock = std::chrono::steady_clock;

// Problems listed one by one before the rest are summed up.
constexpr size_t kMaxListedProblems = 10;

std::string mb(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f", v);
  return buf;
}

void check_config(const SoakConfig& c) {
  if (!(c.seconds > 0)) throw Error("soak: the length must be > 0 s");
  if (c.devices < 1 || c.devices > kMaxSoakDevices)
    throw Error("soak: " + std::to_string(c.devices) + " controllers; give 1 to " + std::to_string(kMaxSoakDevices));
  if (!(c.rate_hz >= 1 && c.rate_hz <= 1000)) throw Error("soak: the rate must be 1 to 1000 Hz");
  if (!(c.trial_seconds >= 1)) throw Error("soak: a trial must last at least 1 s");
  if (c.output_dir.empty()) throw Error("soak: no output folder");
}

std::int64_t json_int(const nlohmann::json& j, const char* key) {
  return j.is_object() && j.contains(key) && j.at(key).is_number_integer() ? j.at(key).get<std::int64_t>() : -1;
}

// Per-second sampling on a thread of its own, so the samples go on between trials too.
class Sampler {
 public:
  Sampler(Clock::time_point t0, const SoakConfig& config, const GroupedFusion* fusion,
          const std::function<void(const std::string&)>& progress)
      : t0_(t0), config_(config), fusion_(fusion), progress_(progress) {
    thread_ = std::thread([this] { run(); });
  }
  ~Sampler() { stop(); }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  void note_queue_depth(std::int64_t depth) {
    std::int64_t seen = queue_max_.load();
    while (depth > seen && !queue_max_.compare_exchange_weak(seen, depth)) {
    }
  }
  std::atomic<std::int64_t> written{0};  // rows written by finished trials
  std::atomic<std::int64_t> lost{0};
  std::atomic<int> trials{0};
  std::vector<SoakSample> samples() const {
    std::lock_guard lock(mutex_);
    return samples_;
  }

 private:
  void run() {
    auto next = t0_ + std::chrono::seconds(1);
    double next_progress = config_.progress_every_s;
    while (!stop_) {
      std::this_thread::sleep_until(std::min(next, Clock::now() + std::chrono::milliseconds(50)));
      if (Clock::now() < next) continue;
      next += std::chrono::seconds(1);
      SoakSample s;
      s.t_s = std::chrono::duration<double>(Clock::now() - t0_).count();
      s.process = read_process_stats();
      s.queue_depth_max = queue_max_.exchange(0);
      s.fusion_dropped = fusion_ != nullptr ? fusion_->stats().frames_dropped : 0;
      s.frames_written = written.load();
      {
        std::lock_guard lock(mutex_);
        samples_.push_back(s);
      }
      if (progress_ && config_.progress_every_s > 0 && s.t_s >= next_progress) {
        next_progress += config_.progress_every_s;
        progress_("soak: " + mb(s.t_s) + " s of " + mb(config_.seconds) + ": " + std::to_string(s.frames_written) +
                  " frames written in " + std::to_string(trials.load()) + " trials, " + std::to_string(lost.load()) +
                  " lost, RSS " + mb(s.process.rss_mb) + " MB (heap in use " + mb(s.process.heap_in_use_mb) +
                  " MB), fds " + std::to_string(s.process.fds) + ", threads " + std::to_string(s.process.threads) +
                  ", fusion dropped " + std::to_string(s.fusion_dropped));
      }
    }
  }

  Clock::time_point t0_;
  const SoakConfig& config_;
  const GroupedFusion* fusion_;
  const std::function<void(const std::string&)>& progress_;
  std::atomic<bool> stop_{false};
  std::atomic<std::int64_t> queue_max_{0};
  mutable std::mutex mutex_;
  std::vector<SoakSample> samples_;
  std::thread thread_;
};

// One trial's files against what the source produced in its window, and its verdict.
SoakTrial check_trial(const TrialResult& result, const std::vector<std::int64_t>& frame_times, const Layout& layout,
                      const SoakConfig& config, double planned_s, std::shared_ptr<const LmcRecording>* recording) {
  SoakTrial t;
  t.name = result.trial;
  t.seconds = planned_s;
  const RecorderSidecar side = read_recorder_sidecar(result.paths.sidecar);
  t.status = side.status;
  const std::int64_t go = json_int(side.trial_window, "go_host_ns");
  const std::int64_t end = json_int(side.trial_window, "end_host_ns");
  if (go >= 0 && end > go)
    t.produced =
        std::count_if(frame_times.begin(), frame_times.end(), [&](std::int64_t ns) { return ns >= go && ns < end; });
  t.written = side.frames_written;
  t.queue_dropped = side.frames_dropped;
  t.writer_lost = std::max<std::int64_t>(0, t.produced - t.written - t.queue_dropped);
  // The study's recording format numbers devices 1 to kMaxDevices, and its reader holds to that:
  // a larger rig's file is counted by the recorder (rows that reached the file), not read back.
  if (config.verdict && layout.device_count() <= kMaxDevices) {
    std::shared_ptr<LmcRecording> rec;
    try {
      rec = std::make_shared<LmcRecording>(read_lmc_recording(result.paths.recording));
    } catch (const std::exception& e) {
      // A writer that failed mid-line (a full disk) leaves a file the reader refuses: that is a
      // failed trial with its reason, not the end of the soak.
      t.verdict = "fail";
      if (!side.error.empty()) t.reasons.push_back(side.error);
      t.reasons.push_back(std::string("the recording cannot be read: ") + e.what());
      return t;
    }
    QualityInputs in;
    in.recording = rec.get();
    in.sidecar = &side;
    in.layout = layout;
    in.planned_s = planned_s;
    const QualityReport q = assess_trial(in);
    t.verdict = q.verdict;
    t.reasons = q.reasons;
    if (static_cast<std::int64_t>(rec->rows.size()) != side.frames_written)
      t.reasons.push_back("the file has " + std::to_string(rec->rows.size()) + " rows, the sidecar counts " +
                          std::to_string(side.frames_written));
    *recording = std::move(rec);
  }
  return t;
}

std::string trial_problem(const SoakTrial& t) {
  std::string p = "trial " + t.name + ": ";
  if (t.lost() != 0) {
    p += std::to_string(t.lost()) + " of " + std::to_string(t.produced) +
         " frames lost (recorder queue full: " + std::to_string(t.queue_dropped) +
         ", writer: " + std::to_string(t.writer_lost) + ")";
  }
  if (t.status != "completed") p += std::string(t.lost() != 0 ? "; " : "") + "its sidecar says " + t.status;
  if (!t.verdict.empty()) {
    p += "; verdict " + t.verdict;
    if (!t.reasons.empty()) p += ": " + t.reasons.front();
  }
  return p;
}

// The least heap in use among the samples taken in [from, to), and `point` if less: memory that
// comes and goes (a trial processed in the background, a heatmap in flight) is above it; what the
// program keeps is under every sample.
double heap_floor(const std::vector<SoakSample>& samples, double from, double to, double point) {
  double floor = point;
  for (const SoakSample& s : samples)
    if (s.t_s >= from && s.t_s < to) floor = std::min(floor, s.process.heap_in_use_mb);
  return floor;
}

void judge_growth(SoakReport& r, double baseline_t_s) {
  if (r.trials.size() < 2) {
    r.notes.push_back("one trial only: growth is judged from the second trial on");
    return;
  }
  if (r.baseline.rss_mb <= 0) {
    r.notes.push_back("no /proc/self to read: growth not judged");
    return;
  }
  const double window = std::max(2.0, r.config.trial_seconds);
  r.heap_floor_baseline_mb = heap_floor(r.samples, baseline_t_s, baseline_t_s + window, r.baseline.heap_in_use_mb);
  r.heap_floor_end_mb = heap_floor(r.samples, r.elapsed_s - window, r.elapsed_s + 1, r.end.heap_in_use_mb);
  if (r.baseline.heap_in_use_mb <= 0) {
    r.notes.push_back("this allocator does not say how much it holds: memory growth not judged");
  } else {
    const double allowed = r.config.heap_allowance_mb + 0.1 * r.heap_floor_baseline_mb;
    if (r.heap_floor_end_mb - r.heap_floor_baseline_mb > allowed)
      r.problems.push_back("memory held by the program (heap in use) grew from " + mb(r.heap_floor_baseline_mb) +
                           " MB after the first trial to " + mb(r.heap_floor_end_mb) + " MB (more than " + mb(allowed) +
                           " MB)");
  }
  if (r.end.fds > r.baseline.fds)
    r.problems.push_back("open file descriptors grew from " + std::to_string(r.baseline.fds) +
                         " after the first trial to " + std::to_string(r.end.fds));
  if (r.end.threads > r.baseline.threads)
    r.problems.push_back("threads grew from " + std::to_string(r.baseline.threads) + " after the first trial to " +
                         std::to_string(r.end.threads));
}

// Memory held as a leak holds it (written, so that it is resident too), for leak_mb_per_trial.
void hold_deliberately(std::vector<std::unique_ptr<char[]>>& held, double mb_count) {
  if (mb_count <= 0) return;
  const auto bytes = static_cast<size_t>(mb_count * 1024 * 1024);
  held.push_back(std::make_unique<char[]>(bytes));
  std::fill_n(held.back().get(), bytes, static_cast<char>(held.size()));
}

// The engine's settings for soak trial `index`, `len` seconds long.
TrialEngineConfig soak_trial_config(const SoakConfig& config, const std::string& name, int index, double len) {
  TrialEngineConfig tc;
  tc.output_dir = config.output_dir;
  tc.trial = name;
  tc.seconds = len;
  tc.backend = "sim";
  tc.allow_overwrite = true;  // the soak's own folder: a run again replaces the last one's trials
  tc.stopped_by = "soak";
  tc.open_sink = config.open_sink;
  tc.extra["soak"] = {{"devices", config.devices}, {"rate_hz", config.rate_hz}, {"trial", index}};
  return tc;
}

// A checked trial's counts into the report and the sampler's running totals, and its problem
// when it lost frames or did not complete.
void count_soak_trial(SoakReport& report, Sampler& sampler, SoakTrial t) {
  report.produced += t.produced;
  report.written += t.written;
  report.lost += t.lost();
  report.queue_dropped += t.queue_dropped;
  report.writer_lost += t.writer_lost;
  sampler.written += t.written;
  sampler.lost += t.lost();
  ++sampler.trials;
  if (t.lost() != 0 || t.status != "completed") {
    if (report.problems.size() < kMaxListedProblems) report.problems.push_back(trial_problem(t));
  }
  report.trials.push_back(std::move(t));
}

// Stops the hub, then the live fused hand and the background work, keeping their counts.
void stop_soak_rig(SoakReport& report, DeviceHub& hub, GroupedFusion* fusion, BackgroundLoad* background) {
  if (fusion) hub.remove_tap(fusion);
  hub.stop();
  if (fusion) {
    fusion->stop();
    report.fusion = fusion->stats();
  }
  if (background) {
    background->stop();
    report.background = background->counts();
    if (!report.background.last_error.empty()) report.notes.push_back(report.background.last_error);
  }
}

// What the source delivered, the samples' peaks, and the notes and problems of the whole run.
void summarise_soak(SoakReport& report, const SoakConfig& config, const CountingSource& source,
                    const Sampler& sampler) {
  if (config.verdict && config.devices > kMaxDevices)
    report.notes.push_back("no verdicts: the recording format holds at most " + std::to_string(kMaxDevices) +
                           " controllers, so the files are counted by the recorder, not read back");
  report.source_frames = source.frames_produced();
  report.source_rate_fraction =
      static_cast<double>(report.source_frames) / (config.devices * config.rate_hz * report.elapsed_s);
  report.samples = sampler.samples();
  for (const SoakSample& s : report.samples) {
    report.rss_max_mb = std::max(report.rss_max_mb, s.process.rss_mb);
    report.queue_depth_max = std::max(report.queue_depth_max, s.queue_depth_max);
  }
  if (report.lost != 0 && report.problems.size() >= kMaxListedProblems)
    report.problems.push_back(std::to_string(report.lost) + " frames lost in all");
  if (report.source_rate_fraction < 0.95)
    report.notes.push_back("the simulator delivered " + mb(100 * report.source_rate_fraction) +
                           " % of the frames asked for: the rig, not the recorder, set the pace");
}

}  // namespace

Layout soak_layout(int devices) {
  const Layout base = load_layout_or_preset("paper-initial");
  Layout out = base;
  out.name = "soak-" + std::to_string(devices);
  out.description = "the study's initial layout repeated for " + std::to_string(devices) + " controllers (soak rig)";
  out.devices.clear();
  for (int i = 0; i < devices; ++i) {
    LayoutDevice d = base.devices[static_cast<size_t>(i % base.device_count())];
    d.slot = "LMC" + std::to_string(i + 1);
    d.serial.reset();
    out.devices.push_back(std::move(d));
  }
  return out;
}

SoakReport run_soak(const SoakConfig& config, const std::function<void(const std::string&)>& progress) {
  check_config(config);
  std::error_code ec;
  std::filesystem::create_directories(config.output_dir, ec);
  if (ec) throw Error("soak: cannot create " + config.output_dir.string() + ": " + ec.message());

  SoakReport report;
  report.config = config;
  const Layout layout = soak_layout(config.devices);
  SimConfig sim;
  sim.seed = config.seed;
  sim.rate_min_hz = sim.rate_max_hz = config.rate_hz;
  apply_motion_spec(sim, "index");  // a moving hand: fingers in and out of view, as in a real trial

  report.start = read_process_stats();
  DeviceHub hub(layout);
  auto counting =
      std::make_unique<CountingSource>(std::make_unique<SimSource>(layout, sim, SimSourceOptions{1.0, 0.0}));
  CountingSource* source = counting.get();
  hub.add_source(std::move(counting));
  std::unique_ptr<GroupedFusion> fusion;
  if (config.fusion) {
    fusion = std::make_unique<GroupedFusion>(layout);
    hub.add_tap(fusion.get());
  }
  std::unique_ptr<BackgroundLoad> background;
  if (config.background) {
    background = std::make_unique<BackgroundLoad>(layout);
    background->start();
  }

  const Clock::time_point t0 = Clock::now();
  Sampler sampler(t0, config, fusion.get(), progress);
  const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  hub.start();

  double baseline_t_s = 0;
  std::vector<std::unique_ptr<char[]>> deliberate_leak;
  const auto on_status = [&](const TrialSnapshot& s) {
    sampler.note_queue_depth(static_cast<std::int64_t>(s.recorder.queue_depth));
  };
  for (int index = 1;; ++index) {
    const double left = config.seconds - elapsed();
    if (index > 1 && left < 1.0) break;
    const double len = std::max(1.0, std::min(config.trial_seconds, left));
    char name[32];
    std::snprintf(name, sizeof name, "soak_%04d", index);
    TrialEngine engine(hub, nullptr, soak_trial_config(config, name, index, len));
    const TrialResult result = engine.run({}, on_status);
    const std::vector<std::int64_t> times = source->take_frame_times();
    if (!result.recorded) {
      report.problems.push_back(std::string("trial ") + name + " recorded nothing: " + result.reason);
      break;
    }
    std::shared_ptr<const LmcRecording> recording;
    SoakTrial t = check_trial(result, times, layout, config, len, &recording);
    if (background && recording) background->process_next(recording);
    recording.reset();
    if (!config.keep_files) {
      std::filesystem::remove(result.paths.recording, ec);
      std::filesystem::remove(result.paths.sidecar, ec);
    }
    count_soak_trial(report, sampler, std::move(t));
    if (index == 1) {
      report.baseline = read_process_stats();
      baseline_t_s = elapsed();
    }
    hold_deliberately(deliberate_leak, config.leak_mb_per_trial);
  }
  report.end = read_process_stats();
  report.elapsed_s = elapsed();
  sampler.stop();
  stop_soak_rig(report, hub, fusion.get(), background.get());
  summarise_soak(report, config, *source, sampler);
  judge_growth(report, baseline_t_s);
  return report;
}

std::string soak_summary_line(const SoakReport& r) {
  return "soak: " + std::to_string(r.written) + " frames from " + std::to_string(r.config.devices) +
         " controllers in " + mb(r.elapsed_s) + " s, " + std::to_string(r.lost) + " lost, heap " +
         mb(r.start.heap_in_use_mb) + "→" + mb(r.end.heap_in_use_mb) + " MB, RSS " + mb(r.start.rss_mb) + "→" +
         mb(r.end.rss_mb) + " MB, fds " + std::to_string(r.start.fds) + "→" + std::to_string(r.end.fds);
}

nlohmann::json soak_report_to_json(const SoakReport& r) {
  using nlohmann::json;
  const auto stats = [](const ProcessStats& p) {
    return json{{"rss_mb", p.rss_mb}, {"heap_in_use_mb", p.heap_in_use_mb}, {"fds", p.fds}, {"threads", p.threads}};
  };
  const auto number = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  json trials = json::array();
  for (const SoakTrial& t : r.trials)
    trials.push_back({{"name", t.name},
                      {"seconds", t.seconds},
                      {"status", t.status},
                      {"produced", t.produced},
                      {"written", t.written},
                      {"lost", t.lost()},
                      {"queue_dropped", t.queue_dropped},
                      {"writer_lost", t.writer_lost},
                      {"verdict", t.verdict.empty() ? json(nullptr) : json(t.verdict)},
                      {"reasons", t.reasons}});
  json samples = json::array();
  for (const SoakSample& s : r.samples)
    samples.push_back({{"t_s", s.t_s},
                       {"rss_mb", s.process.rss_mb},
                       {"heap_in_use_mb", s.process.heap_in_use_mb},
                       {"fds", s.process.fds},
                       {"threads", s.process.threads},
                       {"queue_depth_max", s.queue_depth_max},
                       {"fusion_dropped", s.fusion_dropped},
                       {"frames_written", s.frames_written}});
  return json{{"ok", r.ok()},
              {"summary", soak_summary_line(r)},
              {"devices", r.config.devices},
              {"rate_hz", r.config.rate_hz},
              {"seconds", r.config.seconds},
              {"trial_seconds", r.config.trial_seconds},
              {"elapsed_s", r.elapsed_s},
              {"frames_produced", r.produced},
              {"frames_written", r.written},
              {"lost", r.lost},
              {"lost_queue_full", r.queue_dropped},
              {"lost_writer", r.writer_lost},
              {"source_frames", r.source_frames},
              {"source_rate_fraction", r.source_rate_fraction},
              {"fusion",
               {{"frames_tapped", r.fusion.frames_tapped},
                {"frames_fused", r.fusion.frames_fused},
                {"frames_dropped", r.fusion.frames_dropped},
                {"latency_p50_ms", number(r.fusion.latency_p50_ms)},
                {"latency_p95_ms", number(r.fusion.latency_p95_ms)},
                {"latency_max_ms", number(r.fusion.latency_max_ms)}}},
              {"background",
               {{"heatmaps", r.background.heatmaps},
                {"searches", r.background.searches},
                {"trials_processed", r.background.trials_processed}}},
              {"process", {{"start", stats(r.start)}, {"baseline", stats(r.baseline)}, {"end", stats(r.end)}}},
              {"rss_max_mb", r.rss_max_mb},
              {"heap_floor_baseline_mb", r.heap_floor_baseline_mb},
              {"heap_floor_end_mb", r.heap_floor_end_mb},
              {"queue_depth_max", r.queue_depth_max},
              {"problems", r.problems},
              {"notes", r.notes},
              {"trials", trials},
              {"samples", samples}};
}

}  // namespace lmc::devices
