// Building a pose set from a whole subject: the study's 80 trials of 10 s, processed (one fused
// hand file per trial, 100 Hz), read in parallel (oneTBB) into one recorded set. Target: under 2 s
// on 2 cores. Run: build/<release>/tests/lmc_benchmarks --benchmark_filter=RecordedPoses
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/hand/hand_model.h"
#include "core/hand/pose_set_generator.h"
#include "core/io/lmc_recording.h"
#include "core/poses/recorded_poses.h"

namespace {

namespace fs = std::filesystem;

// 80 fused files of 1,000 frames each (the Monte Carlo generator's hands stand in for a subject's),
// written once into a temporary folder.
const fs::path& subject_folder() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("lmc_bench_recorded_poses_" + std::to_string(::getpid()));
    fs::create_directories(d);
    const char* motions[4] = {"Static", "Index", "Thumb", "Wrist"};
    int trial = 0;
    for (const char* layout : {"Naiv", "Opti"}) {
      for (int pose = 1; pose <= 2; ++pose) {
        for (const char* motion : motions) {
          for (int rep = 1; rep <= 5; ++rep) {
            lmc::PoseSetSettings s;
            s.frames = 1000;
            s.seed = static_cast<std::uint64_t>(++trial);
            const lmc::PoseSet set = lmc::generate_pose_set(lmc::HandModel(), s);
            lmc::LmcRecording rec;
            rec.kind = lmc::RecordingKind::kResampled;
            for (size_t j = 0; j < set.frames.size(); ++j) {
              lmc::HandFrame f = set.frames[j];
              f.device_id = 1;
              f.frame_rate_hz = 100;
              f.timestamp_us = static_cast<std::int64_t>(j) * 10000;
              rec.rows.push_back(f);
            }
            const std::string name =
                std::string(layout) + "_" + motion + std::to_string(pose) + "0" + std::to_string(rep) + ".fused.txt";
            lmc::save_lmc_recording(d / name, rec);
          }
        }
      }
    }
    return d;
  }();
  return dir;
}

void BM_RecordedPosesFromEightyFusedTrials(benchmark::State& state) {
  const fs::path& dir = subject_folder();
  std::int64_t frames = 0;
  for (auto _ : state) {
    const lmc::RecordedPoseSet set = lmc::pose_set_from_recordings({dir}, lmc::RecordedPoseOptions{});
    frames = set.set.size();
    benchmark::DoNotOptimize(set.set.frames.data());
  }
  state.counters["frames"] = static_cast<double>(frames);
  state.SetItemsProcessed(state.iterations() * frames);
}
BENCHMARK(BM_RecordedPosesFromEightyFusedTrials)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
