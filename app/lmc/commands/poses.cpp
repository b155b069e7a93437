// lmc poses: write a Monte Carlo pose set (core/hand/pose_set_generator.h) in the pose-set format
// that every --poses option reads (core/io/pose_set_tsv.h).
#include <iostream>
#include <optional>
#include <string>

#include "app/lmc/command.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/pose_set_tsv.h"
#include "core/io/pose_source.h"

namespace {

struct PosesOptions {
  int frames = lmc::kDefaultMonteCarloFrames;
  std::uint64_t seed = lmc::kDefaultMonteCarloSeed;
  std::string hand;
  std::string output;
  double joint_noise_deg = 5.0;
  double position_jitter_mm = 15.0;
  double orientation_jitter_deg = 5.0;
};

void setup_poses(CLI::App& app) {
  auto opt = std::make_shared<PosesOptions>();
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
  app.add_option("-o,--output", opt->output, "Output pose-set file (.tsv)")->required();
  app.callback([opt] {
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
    int counts[lmc::kNumHandOrientations][lmc::kNumHandMotions] = {};
    for (const auto& l : set.labels) ++counts[static_cast<int>(l.orientation)][static_cast<int>(l.motion)];
    std::cout << "wrote " << set.size() << " frames (" << set.description << ") to " << opt->output << "\n";
    for (int o = 0; o < lmc::kNumHandOrientations; ++o) {
      std::cout << "  " << lmc::orientation_name(static_cast<lmc::HandOrientation>(o)) << ":";
      for (int m = 0; m < lmc::kNumHandMotions; ++m) {
        std::cout << " " << lmc::motion_name(static_cast<lmc::HandMotion>(m)) << "=" << counts[o][m];
      }
      std::cout << "\n";
    }
  });
}

const lmc::cli::CommandRegistration poses_command{"poses", "Generate a seeded Monte Carlo hand pose set", 30,
                                                  setup_poses};

}  // namespace
