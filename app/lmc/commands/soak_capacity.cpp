// lmc soak-capacity REPORT.json… [--svg OUT.svg] [--title T]: the capacity curve from the reports
// of `lmc soak … --json` runs (one per controllers × rate point; a point measured more than once
// shows every run). Prints a Markdown table — controllers down, rates across, each cell the frames
// lost per run (and what lost them: the recorder's queue, the writer; the source's share when the
// simulator could not keep the rate) — and with --svg writes the curve with the project's SVG
// figure code: frames written per second of trial against controllers, one line per rate
// (without loss it is controllers × rate), every run that lost a frame marked.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/figures/figure.h"
#include "core/figures/svg_writer.h"
#include "core/io/atomic_write.h"
#include "core/io/json_checked.h"

namespace {

struct CapacityOptions {
  std::vector<std::string> reports;
  std::string svg;
  std::string title = "Recorder capacity on the simulated rig";
};

// What one `lmc soak --json` report says about its run: the point measured, the frames lost and
// why, the frames written and the trials' seconds.
struct SoakRunReport {
  int devices = 0;
  double rate_hz = 0;
  std::int64_t lost = 0, lost_queue = 0, lost_writer = 0, written = 0;
  double trial_s = 0, source_fraction = 0;  // trial_s: the trials' planned seconds, summed
};

SoakRunReport read_soak_run_report(const std::string& path) {
  const nlohmann::json j = lmc::read_json_file(path);
  const lmc::JsonReader r(j, path);
  SoakRunReport run;
  run.devices = r.at("devices").integer();
  run.rate_hz = r.number("rate_hz");
  run.lost = static_cast<std::int64_t>(r.number("lost"));
  run.lost_queue = static_cast<std::int64_t>(r.number("lost_queue_full"));
  run.lost_writer = static_cast<std::int64_t>(r.number("lost_writer"));
  run.written = static_cast<std::int64_t>(r.number("frames_written"));
  const lmc::JsonReader trials = r.at("trials");
  for (size_t i = 0; i < trials.array_size(); ++i) run.trial_s += trials.at(i).number("seconds");
  run.source_fraction = r.number("source_rate_fraction");
  return run;
}

std::string losses_cell(const SoakRunReport& r) {
  std::string s = std::to_string(r.lost);
  if (r.lost > 0) {
    std::vector<std::string> why;
    if (r.lost_queue > 0) why.push_back("queue " + std::to_string(r.lost_queue));
    if (r.lost_writer > 0) why.push_back("writer " + std::to_string(r.lost_writer));
    std::string joined;
    for (const auto& w : why) joined += (joined.empty() ? "" : ", ") + w;
    if (!joined.empty()) s += " (" + joined + ")";
  }
  if (r.source_fraction < 0.95) {
    char buf[48];
    std::snprintf(buf, sizeof buf, ", source %.0f %%", 100 * r.source_fraction);
    s += buf;
  }
  return s;
}

void run_capacity(const CapacityOptions& opt) {
  std::map<std::pair<int, double>, std::vector<SoakRunReport>> points;
  std::set<int> devices;
  std::set<double> rates;
  for (const auto& path : opt.reports) {
    const SoakRunReport r = read_soak_run_report(path);
    points[{r.devices, r.rate_hz}].push_back(r);
    devices.insert(r.devices);
    rates.insert(r.rate_hz);
  }
  std::cout << "| controllers |";
  for (double hz : rates) std::cout << " " << hz << " Hz |";
  std::cout << "\n|---:|";
  for (size_t i = 0; i < rates.size(); ++i) std::cout << "---|";
  std::cout << "\n";
  for (int n : devices) {
    std::cout << "| " << n << " |";
    for (double hz : rates) {
      const auto it = points.find({n, hz});
      std::string text = "—";
      if (it != points.end()) {
        text.clear();
        for (const SoakRunReport& r : it->second) text += (text.empty() ? "" : " / ") + losses_cell(r);
      }
      std::cout << " " << text << " |";
    }
    std::cout << "\n";
  }
  std::cout << "\nFrames lost per run (of every frame the simulator produced inside a trial); \" / "
               "\" separates runs "
               "of the same point.\n";
  if (opt.svg.empty()) return;

  lmc::Figure f;
  f.title = opt.title;
  f.x = {"controllers", "", std::nullopt};
  f.y = {"frames written per second of trial", "1/s", std::nullopt};
  lmc::Series lossy;
  lossy.name = "a run that lost frames";
  lossy.style = lmc::SeriesStyle::points;
  lossy.colour = lmc::Rgb{200, 30, 30};
  for (double hz : rates) {
    lmc::Series s;
    char name[32];
    std::snprintf(name, sizeof name, "%.0f Hz", hz);
    s.name = name;
    s.style = lmc::SeriesStyle::line_and_points;
    for (int n : devices) {
      const auto it = points.find({n, hz});
      if (it == points.end()) continue;
      for (const SoakRunReport& r : it->second) {
        const double kept = r.trial_s > 0 ? static_cast<double>(r.written) / r.trial_s : std::nan("");
        s.x.push_back(n);
        s.y.push_back(kept);
        if (r.lost > 0) {
          lossy.x.push_back(n);
          lossy.y.push_back(kept);
        }
      }
    }
    f.series.push_back(std::move(s));
  }
  if (!lossy.x.empty()) f.series.push_back(std::move(lossy));
  f.notes.push_back(
      "Each point: one lmc soak run, rows written / the trials' seconds; without loss it is "
      "controllers x rate. Red: a run that lost frames.");
  lmc::write_file_atomically(opt.svg, lmc::to_svg(f));
  std::cout << "figure: " << opt.svg << "\n";
}

void setup_capacity(CLI::App& app) {
  auto opt = std::make_shared<CapacityOptions>();
  app.add_option("reports", opt->reports, "lmc soak --json reports")->required()->check(CLI::ExistingFile);
  app.add_option("--svg", opt->svg, "Write the capacity curve as SVG");
  app.add_option("--title", opt->title, "Figure title")->capture_default_str();
  app.callback([opt] { run_capacity(*opt); });
}

const lmc::cli::CommandRegistration capacity_command{
    "soak-capacity", "The recorder's capacity table and curve from lmc soak --json reports", 92, setup_capacity};

}  // namespace
