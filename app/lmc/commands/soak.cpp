// lmc soak [SECONDS] [DEVICES] [HZ] [--trial-seconds S] [-o DIR] [--keep] [--json]
// A subject session on the simulated rig — DEVICES controllers at HZ each, trials back to back
// for SECONDS — with the live fused hand and a workbench's other work (heatmap, search,
// processing) in the same process; every second it samples memory, descriptors, threads, the
// recorder's queue and the fusion's drops (devices/soak/soak_engine.h). Progress goes to stderr
// every --progress-every seconds; the last line is the summary:
//   soak: <frames> frames from <N> controllers in <s> s, <lost> lost, RSS <a>→<b> MB, fds <a>→<b>
// Exit code 1 when a frame was lost, a trial failed, or memory, descriptors or threads grew.
// --json prints the whole report on stdout instead (keys: ok, summary, devices, rate_hz, seconds,
// trial_seconds, elapsed_s, frames_produced, frames_written, lost, lost_queue_full, lost_writer,
// source_frames, source_rate_fraction, fusion{frames_tapped, frames_fused, frames_dropped,
// latency_p50_ms, latency_p95_ms, latency_max_ms}, background{heatmaps, searches,
// trials_processed}, process{start, baseline, end: {rss_mb, heap_in_use_mb, fds, threads}}, rss_max_mb,
// queue_depth_max, problems[], notes[], trials[{name, seconds, status, produced, written, lost,
// queue_dropped, writer_lost, verdict, reasons[]}], samples[{t_s, rss_mb, heap_in_use_mb, fds, threads,
// queue_depth_max, fusion_dropped, frames_written}]); the summary line still ends stderr.
// Without -o the trials go to a folder of their own under the temporary directory, removed at
// the end unless --keep.

#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/platform/process.h"
#include "devices/soak/soak_engine.h"

namespace {

struct SoakOptions {
  double seconds = 20;
  int devices = 4;
  double rate_hz = 120;
  double trial_seconds = 10;
  std::string out;
  bool keep = false;
  bool json = false;
  bool no_fusion = false;
  bool no_background = false;
  bool no_verdict = false;
  double progress_every_s = 60;
  double heap_allowance_mb = 8;
  double leak_mb_per_trial = 0;
  long long seed = 1;
};

void run_soak_command(const SoakOptions& opt) {
  using namespace lmc::devices;
  SoakConfig c;
  c.seconds = opt.seconds;
  c.devices = opt.devices;
  c.rate_hz = opt.rate_hz;
  c.trial_seconds = opt.trial_seconds;
  const bool own_folder = opt.out.empty();
  c.output_dir = own_folder ? std::filesystem::temp_directory_path() /
                                  ("lmc-soak-" + std::to_string(lmc::platform::current_process_id()))
                            : std::filesystem::path(opt.out);
  c.keep_files = opt.keep;
  c.fusion = !opt.no_fusion;
  c.background = !opt.no_background;
  c.verdict = !opt.no_verdict;
  c.progress_every_s = opt.progress_every_s;
  c.heap_allowance_mb = opt.heap_allowance_mb;
  c.leak_mb_per_trial = opt.leak_mb_per_trial;
  c.seed = static_cast<std::uint64_t>(opt.seed);
  std::cerr << "soak: " << c.devices << " controllers at " << c.rate_hz << " Hz for " << c.seconds << " s (trials of "
            << c.trial_seconds << " s) in " << c.output_dir.string() << "\n";
  const SoakReport r = run_soak(c, [](const std::string& line) { std::cerr << line << std::endl; });
  if (own_folder && !opt.keep) {
    std::error_code ec;
    std::filesystem::remove_all(c.output_dir, ec);
  }
  if (opt.json) {
    std::cout << soak_report_to_json(r).dump(2) << "\n";
  } else {
    for (const auto& t : r.trials)
      if (t.verdict == "fail") std::cout << "trial " << t.name << ": verdict fail: " << t.reasons.front() << "\n";
  }
  for (const auto& n : r.notes) std::cerr << "soak: note: " << n << "\n";
  for (const auto& p : r.problems) std::cerr << "soak: FAILED: " << p << "\n";
  std::cerr << "soak: fusion dropped " << r.fusion.frames_dropped << " of " << r.fusion.frames_tapped
            << " frames (display only); recorder queue at most " << r.queue_depth_max << "; background "
            << r.background.heatmaps << " heatmaps, " << r.background.searches << " searches, "
            << r.background.trials_processed << " trials processed\n";
  (opt.json ? std::cerr : std::cout) << soak_summary_line(r) << std::endl;
  if (!r.ok()) lmc::cli::command_exit_code() = 1;
}

void setup_soak(CLI::App& app) {
  auto opt = std::make_shared<SoakOptions>();
  app.add_option("seconds", opt->seconds, "How long")->capture_default_str();
  app.add_option("devices", opt->devices, "Simulated controllers (1-64)")->capture_default_str();
  app.add_option("hz", opt->rate_hz, "Frames per second of each controller")->capture_default_str();
  app.add_option("--trial-seconds", opt->trial_seconds, "Length of each trial (the last is cut to fit)")
      ->capture_default_str();
  app.add_option("-o,--output", opt->out, "Folder for the trials (default: one under the temporary directory)");
  app.add_flag("--keep", opt->keep, "Keep every trial's files (and the default folder)");
  app.add_flag("--json", opt->json, "Print the whole report as JSON on stdout");
  app.add_flag("--no-fusion", opt->no_fusion, "Without the live fused hand");
  app.add_flag("--no-background", opt->no_background, "Without the heatmap, search and processing thread");
  app.add_flag("--no-verdict", opt->no_verdict, "Without each trial's quality verdict");
  app.add_option("--progress-every", opt->progress_every_s, "Seconds between progress lines (0: none)")
      ->capture_default_str();
  app.add_option("--heap-allowance-mb", opt->heap_allowance_mb,
                 "The heap in use may end this much (plus a tenth) above the first trial's end")
      ->capture_default_str();
  app.add_option("--leak-mb-per-trial", opt->leak_mb_per_trial,
                 "Self-check: hold this much more memory after every trial, as a leak would (the soak must fail)")
      ->capture_default_str();
  app.add_option("--seed", opt->seed, "Simulator seed")->capture_default_str();
  app.callback([opt] { run_soak_command(*opt); });
}

const lmc::cli::CommandRegistration soak_command{
    "soak",
    "Soak the recorder: a long simulated session with fusion and background work, checked for loss "
    "and growth",
    91, setup_soak};

}  // namespace
