// lmc evaluate: the placement metric and coverage of a fixed layout on a pose set, for all frames
// and split by hand orientation (horizontal / vertical) — the same summary `lmc optimize` prints.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "app/lmc/command.h"
#include "core/io/atomic_write.h"
#include "core/io/layout_json.h"
#include "core/io/pose_source.h"
#include "core/metric/controller_contribution.h"
#include "core/metric/coverage.h"
#include "core/metric/layout_report.h"
#include "core/metric/pose_set_score.h"
#include "core/poses/pose_recipe.h"
#include "core/reports/coverage_report.h"
#include "core/reports/layout_report_files.h"
#include "core/reports/robust_terms_report.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_kernel.h"

namespace {

struct EvaluateOptions {
  std::string layout;
  std::string models;  // --models: catalogue ids, one or one per device
  std::string poses = "mc";
  int frames = lmc::kDefaultMonteCarloFrames;
  std::uint64_t seed = lmc::kDefaultMonteCarloSeed;
  std::string hand;
  double range_mm = 0;  // 0: the layout's own sensor model
  double radius_mm = 10.0;
  bool json = false;
  std::string report_dir;
  std::string against;  // --against: a second set to score the layout on, side by side
};

std::string pose_set_label(const std::string& spec) {
  return spec == "mc" ? "Monte Carlo" : std::filesystem::path(spec).filename().string();
}

nlohmann::json controllers_json(const lmc::Layout& layout, const lmc::LayoutReport& report) {
  nlohmann::json cj = nlohmann::json::array();
  for (const auto& c : report.controllers) {
    const auto& dev = layout.devices[cj.size()];
    cj.push_back({{"slot", c.slot},
                  {"model", dev.model},
                  {"range_mm", dev.sensor.range_mm},
                  {"fov_long_deg", dev.sensor.fov_long_deg},
                  {"fov_short_deg", dev.sensor.fov_short_deg},
                  {"seeing_share", c.seeing_share},
                  {"sole_share", c.sole_share},
                  {"axis_cut_share", c.cut_share},
                  {"off_centre", c.off_centre},
                  {"metric_without", c.metric_without},
                  {"redundant_share_without", c.redundant_without},
                  {"counts", c.counts},
                  {"seeing_inside_cut_share", c.seeing_inside_cut_share},
                  {"metric_inside_cut_without", c.metric_inside_cut_without},
                  {"redundant_share_inside_cut_without", c.redundant_inside_cut_without},
                  {"counts_inside_cut", c.counts_inside_cut}});
  }
  return cj;
}

void print_evaluation_json(const EvaluateOptions& opt, const lmc::Layout& layout, const lmc::PoseSet& poses,
                           const lmc::LayoutReport& report, const std::vector<std::string>& slots, double seconds) {
  nlohmann::json j;
  j["layout"] = layout.name;
  j["poses"] = poses.description;
  // The shared range of a uniform rig (null for a mixed one; each controller names its own).
  j["range_mm"] =
      lmc::uniform_sensors(layout) ? nlohmann::json(layout.devices.front().sensor.range_mm) : nlohmann::json(nullptr);
  j["phalanx_radius_mm"] = opt.radius_mm;
  j["all"] = lmc::coverage_to_json(report.coverage.all, slots);
  j["horizontal"] = lmc::coverage_to_json(report.coverage.horizontal, slots);
  j["vertical"] = lmc::coverage_to_json(report.coverage.vertical, slots);
  j["robust_terms"] = {{"all", lmc::robust_terms_to_json(report.terms_all, report.weights)},
                       {"horizontal", lmc::robust_terms_to_json(report.terms_horizontal, report.weights)},
                       {"vertical", lmc::robust_terms_to_json(report.terms_vertical, report.weights)}};
  j["controllers"] = controllers_json(layout, report);
  nlohmann::json sets = nlohmann::json::array();
  for (const auto& set : report.sets) {
    sets.push_back({{"label", set.label},
                    {"description", set.description},
                    {"frames", set.frames},
                    {"metric", set.metric},
                    {"every_finger_two_or_more", set.redundant_share},
                    {"finger_seen", set.finger_seen},
                    {"controller_seeing", set.controller_seeing}});
  }
  j["pose_sets"] = sets;
  j["poses_provenance"] = poses.provenance;
  j["seconds"] = seconds;
  std::cout << j.dump(2) << "\n";
}

void print_rig(const EvaluateOptions& opt, const lmc::Layout& layout, const lmc::PoseSet& poses) {
  if (lmc::uniform_sensors(layout)) {
    const lmc::SensorModel& s = layout.devices.front().sensor;
    std::cout << "layout " << layout.name << " on " << poses.description << " (range " << s.range_mm << " mm, FOV "
              << s.fov_long_deg << "°×" << s.fov_short_deg << "°, radius " << opt.radius_mm << " mm)\n";
  } else {
    std::cout << "layout " << layout.name << " on " << poses.description << " (mixed rig, radius " << opt.radius_mm
              << " mm)\n";
    for (const auto& d : layout.devices) {
      std::cout << "  " << d.slot << ": " << d.model << ", range " << d.sensor.range_mm << " mm, FOV "
                << d.sensor.fov_long_deg << "°×" << d.sensor.fov_short_deg << "°\n";
    }
  }
}

// What each controller contributes, over all its markers and inside its axis cut.
void print_contributions(const lmc::LayoutReport& report) {
  const lmc::Coverage& all = report.coverage.all;
  std::printf("what each controller contributes (all frames; M %.6f, every finger seen by >= 2 in %.1f %%):\n",
              all.metric, 100.0 * lmc::redundant_share(all.c));
  std::printf("  %-6s %8s %8s %9s %10s %11s %13s  %s\n", "slot", "seeing", "sole", "axis cut", "off-centre",
              "M without", ">=2 without", "counts");
  for (const auto& c : report.controllers) {
    std::printf("  %-6s %7.1f%% %7.1f%% %8.1f%% %10.3f %11.6f %12.1f%%  %s\n", c.slot.c_str(), 100 * c.seeing_share,
                100 * c.sole_share, 100 * c.cut_share, c.off_centre, c.metric_without, 100 * c.redundant_without,
                c.counts ? "yes" : "NO: the layout is as good without it");
  }
  std::printf(
      "the same inside the axis cuts (a finger with a marker beyond a controller's cut unseen by it; M inside "
      "cut %.6f):\n",
      report.terms_all.metric_m_inside_cut);
  std::printf("  %-6s %8s %11s %13s  %s\n", "slot", "seeing", "M without", ">=2 without", "counts");
  for (const auto& c : report.controllers) {
    std::printf("  %-6s %7.1f%% %11.6f %12.1f%%  %s\n", c.slot.c_str(), 100 * c.seeing_inside_cut_share,
                c.metric_inside_cut_without, 100 * c.redundant_inside_cut_without,
                c.counts_inside_cut ? "yes" : "NO: nothing inside its cut that the others lack");
  }
}

void print_pose_sets(const lmc::LayoutReport& report) {
  if (report.sets.size() <= 1) return;
  std::printf(
      "the layout on each pose set (M; every finger seen by >= 2; each finger seen; each controller seeing):\n");
  for (const auto& set : report.sets) {
    std::printf("  %-24s %7d frames  M %.6f  >=2 %5.1f%%  fingers", set.label.c_str(), set.frames, set.metric,
                100 * set.redundant_share);
    for (const double v : set.finger_seen) std::printf(" %5.1f%%", 100 * v);
    std::printf("  controllers");
    for (const double v : set.controller_seeing) std::printf(" %5.1f%%", 100 * v);
    std::printf("\n");
  }
}

void print_evaluation_text(const EvaluateOptions& opt, const lmc::Layout& layout, const lmc::PoseSet& poses,
                           const lmc::LayoutReport& report, const std::vector<std::string>& slots,
                           const lmc::VisibilityTable& table, double seconds) {
  print_rig(opt, layout, poses);
  std::cout << "all frames:\n" << lmc::format_coverage(report.coverage.all, slots);
  std::cout << "horizontal poses:\n" << lmc::format_coverage(report.coverage.horizontal, slots);
  std::cout << "vertical poses:\n" << lmc::format_coverage(report.coverage.vertical, slots);
  std::cout << lmc::format_robust_terms_split({"all", "horizontal", "vertical"},
                                              {report.terms_all, report.terms_horizontal, report.terms_vertical},
                                              report.weights);
  print_contributions(report);
  print_pose_sets(report);
  for (const auto& line : poses.provenance) std::printf("pose set %s\n", line.c_str());
  std::fflush(stdout);
  const double evals = static_cast<double>(table.devices) * static_cast<double>(table.frames);
  std::cout << "time " << seconds << " s (" << (seconds > 0 ? evals / seconds : 0.0)
            << " device-frame evaluations/s incl. frame preparation)\n";
}

void run_evaluate(const EvaluateOptions& opt) {
  lmc::Layout layout = lmc::load_layout_or_preset(opt.layout);
  if (!opt.models.empty()) lmc::set_models_from_list(layout, opt.models, lmc::sensor_catalogue());
  if (opt.range_mm > 0) {
    for (auto& d : layout.devices) d.sensor.range_mm = opt.range_mm;
  }
  const auto hand = opt.hand.empty() ? std::nullopt : std::optional<std::string>(opt.hand);
  std::vector<std::string> notes;
  const lmc::PoseSet poses = lmc::load_pose_spec(opt.poses, opt.frames, opt.seed, hand, &notes);
  for (const auto& n : notes) std::cerr << "lmc: note: left out of the pose set: " << n << "\n";
  const auto t0 = std::chrono::steady_clock::now();
  const auto prepared = lmc::prepare_frames(poses.frames);
  const lmc::VisibilityTable table = lmc::compute_visibility(layout, prepared, opt.radius_mm);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<std::string> slots;
  for (const auto& d : layout.devices) slots.push_back(d.slot);
  // Coverage split by orientation, the robust terms and each controller's contribution: the
  // layout report's numbers (core/metric/layout_report.h), computed once for text, JSON and --report.
  lmc::LayoutReport report = lmc::build_layout_report(layout, poses, prepared, lmc::RobustWeights{}, opt.radius_mm);
  report.sets.front().label = pose_set_label(opt.poses);
  const std::string against = opt.against.empty() ? (opt.poses == "mc" ? "none" : "mc") : opt.against;
  if (against != "none") {
    const lmc::PoseSet other = lmc::load_pose_spec(against, opt.frames, opt.seed, hand, &notes);
    report.sets.push_back(
        lmc::pose_set_score(layout, other, lmc::prepare_frames(other.frames), pose_set_label(against), opt.radius_mm));
  }
  if (!opt.report_dir.empty()) {
    const auto md = lmc::write_layout_report_files(opt.report_dir, layout, poses, report, opt.radius_mm);
    std::cerr << "wrote " << md.string() << ", top-view.svg and pose-redundancy.svg (each with .csv and .json)\n";
  }
  if (opt.json) {
    print_evaluation_json(opt, layout, poses, report, slots, seconds);
  } else {
    print_evaluation_text(opt, layout, poses, report, slots, table, seconds);
  }
}

void setup_evaluate(CLI::App& app) {
  auto opt = std::make_shared<EvaluateOptions>();
  app.add_option("--layout", opt->layout, "Layout file or preset name (paper-initial, paper-optimized, …)")->required();
  app.add_option("--poses", opt->poses,
                 "\"mc\" (Monte Carlo set), a pose-set file from `lmc poses` (Monte Carlo or recorded) or a recipe "
                 "(.json) mixing recordings and the Monte Carlo set with weights");
  app.add_option("--frames", opt->frames, "Frames of the Monte Carlo set")->check(CLI::Range(1, 10'000'000));
  app.add_option("--seed", opt->seed, "Seed of the Monte Carlo set");
  app.add_option("--hand", opt->hand, "Monte Carlo set with the hand of this LMC recording's first row");
  app.add_option("--range-mm", opt->range_mm, "Override every controller's sensor range (mm)")
      ->check(CLI::PositiveNumber);
  app.add_option("--models", opt->models,
                 "What-if sensor models from the catalogue (assets/sensors/sensors.json): one id for every "
                 "controller, or one per controller in layout order (lmc2,lmc2,lmc,lmc)");
  app.add_option("--radius-mm", opt->radius_mm, "Phalanx radius (mm)")->check(CLI::NonNegativeNumber);
  app.add_flag("--json", opt->json, "Print JSON (keys: see core/reports/coverage_report.h) instead of text");
  app.add_option("--against", opt->against,
                 "Also score the layout on this pose set (mc, a file or a recipe), side by side; default with a "
                 "--poses other than mc: the Monte Carlo set (\"none\": no second set)");
  app.add_option("--report", opt->report_dir,
                 "Also write a one-page layout report (report.md) into this folder: verdict, metric terms, what "
                 "each controller contributes, coverage per reference pose");
  app.callback([opt] { run_evaluate(*opt); });
}

const lmc::cli::CommandRegistration evaluate_command{
    "evaluate", "Placement metric and coverage of a layout on a pose set", 51, setup_evaluate};

}  // namespace
