// lmc validate: how valid the fused hand is on given trials — for each fusion method,
// finger lengths and joint angles against Vicon and, needing no Vicon, against the controllers
// that see each finger (core/processing/validity.h). Real recordings are listed before simulated
// ones (the simulator is ours: a figure from it can flatter us). With --length-correction, ours with
// the subject's finger-length correction is a third method.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "app/lmc/command.h"
#include "core/common/error.h"
#include "core/io/recorder_sidecar.h"
#include "core/processing/batch.h"
#include "core/processing/length_correction_json.h"
#include "core/processing/validity.h"

namespace {

struct ValidateOptions {
  std::vector<std::string> inputs;
  std::string vicon;
  std::string layout;
  std::string length_correction;
};

void setup_validate(CLI::App& app) {
  auto opt = std::make_shared<ValidateOptions>();
  app.add_option("inputs", opt->inputs, "LMC recordings or folders of trials (as lmc process takes them)")->required();
  app.add_option("--vicon", opt->vicon, "Vicon file (.trc/.c3d) of the LMC files given (folders find theirs by name)");
  app.add_option("--layout", opt->layout, "Layout (name or file); default: the recorder sidecar's, else by trial name");
  app.add_option(
      "--length-correction", opt->length_correction,
      "Also validate the default fusion with this subject's finger-length correction (lmc length-correction fit)");
  app.callback([opt] {
    std::optional<lmc::LengthCorrection> correction;
    if (!opt->length_correction.empty()) correction = lmc::read_length_correction(opt->length_correction);
    struct Block {
      bool simulated = false;
      std::string text;
    };
    std::vector<Block> blocks;
    for (const auto& input : opt->inputs) {
      // --vicon names the Vicon file of a single LMC file; folders find theirs by trial name.
      const bool single_file = !std::filesystem::is_directory(input);
      const auto jobs = lmc::discover_trials(
          input, opt->vicon.empty() || !single_file ? std::nullopt : std::optional<std::filesystem::path>(opt->vicon));
      for (const auto& job : jobs) {
        bool simulated = false;
        if (job.sidecar) simulated = lmc::read_recorder_sidecar(*job.sidecar).backend == "sim";
        std::vector<lmc::MethodValidity> methods;
        std::string layout_used, frames;
        // The study's method, ours, and ours with the subject's length correction when one is given.
        const int passes = correction ? 3 : 2;
        for (int pass = 0; pass < passes; ++pass) {
          lmc::BatchOptions so;
          so.process.method = pass == 0 ? lmc::FusionMethod::kReference : lmc::FusionMethod::kDefault;
          if (pass == 2) so.process.length_correction = correction;
          if (!opt->layout.empty()) so.layout = opt->layout;
          std::optional<lmc::TrialAnalysis> kept;
          so.on_result = [&kept](const lmc::TrialAnalysis& r, const nlohmann::json&) { kept = r; };
          const lmc::ProcessedTrial out = lmc::process_batch({job}, so).front();
          if (!out.error.empty()) throw lmc::Error(job.trial + ": " + out.error);
          if (!kept) throw lmc::Error(job.trial + ": no result");
          layout_used = out.layout_used;
          frames = std::to_string(kept->fused.frame_count);
          methods.push_back(lmc::method_validity(*kept));
          if (pass == 2) methods.back().label = "corrected";
        }
        const bool with_vicon = std::isfinite(methods.front().vicon_finger_mean[0]);
        const std::string title =
            std::string(simulated ? "SIMULATOR" : "REAL DATA") + ": " + job.trial + " (" + frames + " frames, layout " +
            layout_used + (with_vicon ? ", with Vicon" : ", no Vicon") + ")" +
            (correction ? "\n  corrected = default fusion with the finger-length correction of subject " +
                              correction->subject + " (" + opt->length_correction + ")"
                        : std::string());
        blocks.push_back({simulated, lmc::format_validity(title, methods)});
      }
    }
    for (const bool simulated : {false, true}) {
      for (const auto& b : blocks)
        if (b.simulated == simulated) std::cout << b.text << "\n";
    }
  });
}

const lmc::cli::CommandRegistration validate_command{
    "validate", "Validity of the fused hand: against Vicon and against the controllers that see each finger", 62,
    setup_validate};

}  // namespace
