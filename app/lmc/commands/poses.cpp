// lmc poses: write a pose set in the format every --poses option reads (core/io/pose_set_tsv.h):
// the seeded Monte Carlo set (core/hand/pose_set_generator.h) or, with --from, the hands of recorded
// trials (core/poses/recorded_poses.h).
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/atomic_write.h"
#include "core/io/pose_set_tsv.h"
#include "core/io/pose_source.h"
#include "core/poses/pose_recipe.h"
#include "core/poses/pose_set_comparison.h"
#include "core/poses/recorded_poses.h"

namespace {

struct PosesOptions {
  int frames = lmc::kDefaultMonteCarloFrames;
  std::uint64_t seed = lmc::kDefaultMonteCarloSeed;
  std::string hand;
  std::string output;
  double joint_noise_deg = 5.0;
  double position_jitter_mm = 15.0;
  double orientation_jitter_deg = 5.0;
  std::vector<std::string> from;
  std::string source = "fused";
  int every = 1;
  std::string trials;
  std::string layout;
  std::string mapping;
};

void print_label_counts(const lmc::PoseSet& set) {
  int counts[lmc::kNumHandOrientations][lmc::kNumHandMotions] = {};
  for (const auto& l : set.labels) ++counts[static_cast<int>(l.orientation)][static_cast<int>(l.motion)];
  for (int o = 0; o < lmc::kNumHandOrientations; ++o) {
    std::cout << "  " << lmc::orientation_name(static_cast<lmc::HandOrientation>(o)) << ":";
    for (int m = 0; m < lmc::kNumHandMotions; ++m) {
      std::cout << " " << lmc::motion_name(static_cast<lmc::HandMotion>(m)) << "=" << counts[o][m];
    }
    std::cout << "\n";
  }
}

void write_recorded(const PosesOptions& opt) {
  lmc::RecordedPoseOptions r;
  lmc::parse_recorded_pose_source(opt.source, r);
  r.every = opt.every;
  r.trials_glob = opt.trials;
  if (!opt.layout.empty()) r.layout = opt.layout;
  if (!opt.mapping.empty()) r.mapping = opt.mapping;
  std::vector<std::filesystem::path> inputs(opt.from.begin(), opt.from.end());
  const lmc::RecordedPoseSet rec = lmc::pose_set_from_recordings(inputs, r);
  for (const auto& s : rec.skipped) std::cerr << "lmc poses: left out: " << s << "\n";
  lmc::save_pose_set(opt.output, rec.set);
  std::cout << "wrote " << rec.set.size() << " frames from " << rec.trials.size() << " trials (" << rec.frames_skipped
            << " frames skipped: no complete hand; " << rec.skipped.size() << " trials left out) to " << opt.output
            << "\n";
  for (const auto& line : rec.set.provenance) std::cout << "  " << line << "\n";
  print_label_counts(rec.set);
}

struct CompareOptions {
  std::string a, b;
  std::string a_label, b_label;
  std::string svg;
  bool json = false;
};

std::string spec_label(const std::string& spec) {
  return spec == "mc" ? "Monte Carlo" : std::filesystem::path(spec).filename().string();
}

void setup_compare(CLI::App& app) {
  auto opt = std::make_shared<CompareOptions>();
  app.add_option("a", opt->a, "First pose set: mc, a pose-set file or a recipe")->required();
  app.add_option("b", opt->b, "Second pose set: mc, a pose-set file or a recipe")->required();
  app.add_option("--label-a", opt->a_label, "Name of the first set in the figure (default: its file name)");
  app.add_option("--label-b", opt->b_label, "Name of the second set in the figure");
  app.add_option("--svg", opt->svg, "Write the figure (SVG) here");
  app.add_flag("--json", opt->json, "Print JSON instead of text");
  app.callback([opt] {
    std::vector<std::string> notes;
    const lmc::PoseSet a =
        lmc::load_pose_spec(opt->a, lmc::kDefaultMonteCarloFrames, lmc::kDefaultMonteCarloSeed, std::nullopt, &notes);
    const lmc::PoseSet b =
        lmc::load_pose_spec(opt->b, lmc::kDefaultMonteCarloFrames, lmc::kDefaultMonteCarloSeed, std::nullopt, &notes);
    for (const auto& n : notes) std::cerr << "lmc poses compare: left out: " << n << "\n";
    const lmc::PoseSetComparison c = lmc::compare_pose_sets(a, b);
    if (!opt->svg.empty()) {
      lmc::write_file_atomically(
          opt->svg, lmc::pose_set_comparison_svg(c, opt->a_label.empty() ? spec_label(opt->a) : opt->a_label,
                                                 opt->b_label.empty() ? spec_label(opt->b) : opt->b_label));
      std::cerr << "wrote " << opt->svg << "\n";
    }
    if (opt->json) {
      std::cout << lmc::pose_set_comparison_json(c).dump(2) << "\n";
      return;
    }
    std::cout << lmc::format_pose_set_comparison(c);
  });
}

void setup_poses(CLI::App& app) {
  auto opt = std::make_shared<PosesOptions>();
  CLI::App* compare = app.add_subcommand("compare", "Compare two pose sets: where the hands are, how turned, how bent");
  setup_compare(*compare);
  app.add_option("--frames", opt->frames, "Number of frames")->check(CLI::Range(1, 10'000'000));
  app.add_option("--seed", opt->seed, "Random seed (same seed, same numbers)");
  app.add_option("--hand", opt->hand,
                 "Use the hand of the first row with a hand in this LMC recording (default: average adult hand, "
                 "190 mm)");
  app.add_option("--joint-noise-deg", opt->joint_noise_deg, "σ of the per-joint noise (degrees)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--position-jitter-mm", opt->position_jitter_mm, "σ of the hand position jitter per axis (mm)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--orientation-jitter-deg", opt->orientation_jitter_deg, "σ of the hand orientation jitter (degrees)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--from", opt->from,
                 "Build the set from recorded trials instead: processed-trial folders or .fused.txt files (--source "
                 "fused), session or trial folders and LMC files (LMCn), or those and .trc/.c3d files (vicon)");
  app.add_option("--source", opt->source,
                 "With --from: fused (the fused hand, default), vicon (markers mapped to the hand's points) or LMCn "
                 "(one controller, realigned with the trial's layout)");
  app.add_option("--every", opt->every, "With --from: keep every N-th frame of each trial")
      ->check(CLI::Range(1, 100000));
  app.add_option("--trials", opt->trials, "With --from: only trials whose name matches this shell pattern (*Index*)");
  app.add_option("--layout", opt->layout, "With --source LMCn: realign with this layout instead of each trial's own");
  app.add_option("--mapping", opt->mapping, "With --source vicon: another marker mapping (default vicon-26-to-lmc)");
  app.add_option("-o,--output", opt->output, "Output pose-set file (.tsv); required unless comparing");
  app.callback([opt, compare] {
    if (compare->parsed()) return;
    if (opt->output.empty()) throw lmc::Error("--output is required");
    if (!opt->from.empty()) {
      write_recorded(*opt);
      return;
    }
    lmc::PoseSetSettings s;
    s.frames = opt->frames;
    s.seed = opt->seed;
    s.joint_noise_deg = opt->joint_noise_deg;
    s.position_jitter_mm = opt->position_jitter_mm;
    s.orientation_jitter_deg = opt->orientation_jitter_deg;
    const std::optional<std::string> hand = opt->hand.empty() ? std::nullopt : std::optional<std::string>(opt->hand);
    lmc::PoseSet set = lmc::generate_pose_set(lmc::load_hand_model(hand), s);
    if (hand) set.description += " hand=" + *hand;
    lmc::save_pose_set(opt->output, set);
    std::cout << "wrote " << set.size() << " frames (" << set.description << ") to " << opt->output << "\n";
    print_label_counts(set);
  });
}

const lmc::cli::CommandRegistration poses_command{
    "poses", "Write a pose set: seeded Monte Carlo, or from recorded trials", 30, setup_poses};

}  // namespace
