// lmc visibility: label every row of an LMC recording with the per-finger visibility of
// docs/algorithms/visibility.md, the device at its own origin (recorded points are in device
// coordinates): 1 visible, 0 hidden (the controller's internal model), −1 no hand.
#include <iostream>
#include <string>

#include "app/lmc/command.h"
#include "core/io/lmc_recording.h"
#include "core/visibility/device_view.h"
#include "core/visibility/frame_prep.h"
#include "core/visibility/visibility_explain.h"
#include "core/visibility/visibility_kernel.h"

namespace {

struct VisibilityOptions {
  std::string input;
  std::string output;
  double range_mm = 400.0;
  double fov_long_deg = 150.0;
  double fov_short_deg = 120.0;
  double radius_mm = 10.0;
  bool explain = false;
};

void setup_visibility(CLI::App& app) {
  auto opt = std::make_shared<VisibilityOptions>();
  app.add_option("file", opt->input, "LMC recording (raw, resampled or raytraced)")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("-o,--output", opt->output, "Output: the input columns plus visibility_thumb … visibility_pinky")
      ->required();
  app.add_option("--range-mm", opt->range_mm, "Sensor range (mm)")->check(CLI::PositiveNumber);
  app.add_option("--fov-long-deg", opt->fov_long_deg, "Full field-of-view angle along the long axis x (degrees)")
      ->check(CLI::Range(0.001, 179.999));
  app.add_option("--fov-short-deg", opt->fov_short_deg, "Full field-of-view angle along the short axis z (degrees)")
      ->check(CLI::Range(0.001, 179.999));
  app.add_option("--radius-mm", opt->radius_mm, "Phalanx radius (mm)")->check(CLI::NonNegativeNumber);
  app.add_flag("--explain", opt->explain, "Print why hidden fingers are hidden (one line per hidden finger) on stdout");
  app.callback([opt] {
    lmc::LmcRecording rec = lmc::read_lmc_recording(opt->input);
    for (const auto& w : rec.warnings) std::cerr << "lmc: warning: " << opt->input << ": " << w << "\n";
    const lmc::VisibilityLimits limits =
        lmc::make_limits({opt->range_mm, opt->fov_long_deg, opt->fov_short_deg, opt->radius_mm});
    const lmc::DeviceView device = lmc::DeviceView::identity();
    const std::vector<lmc::PreparedFrame> prepared = lmc::prepare_frames(rec.rows);
    rec.visibility.assign(rec.rows.size(), {});
    long counts[3] = {0, 0, 0};  // −1, 0, 1
    for (size_t i = 0; i < rec.rows.size(); ++i) {
      auto& labels = rec.visibility[i];
      if (!rec.rows[i].hand_present || !prepared[i].valid) {
        labels.fill(-1);
        counts[0] += lmc::kNumDigits;
        continue;
      }
      const lmc::FingerBits bits = lmc::visible_fingers(prepared[i], device, limits);
      for (int k = 0; k < lmc::kNumDigits; ++k) {
        labels[static_cast<size_t>(k)] = static_cast<std::int8_t>((bits >> k) & 1);
        ++counts[1 + ((bits >> k) & 1)];
      }
      if (opt->explain && bits != lmc::kAllFingersVisible) {
        const auto ex = lmc::explain_visibility(prepared[i], device, limits);
        for (int k = 0; k < lmc::kNumDigits; ++k) {
          const auto& v = ex.fingers[static_cast<size_t>(k)];
          if (!v.visible()) {
            std::cout << "row " << (i + 1) << " device " << rec.rows[i].device_id << " " << lmc::digit_name(k) << ": "
                      << lmc::describe(v) << "\n";
          }
        }
      }
    }
    rec.kind = lmc::RecordingKind::kRaytraced;
    lmc::save_lmc_recording(opt->output, rec);
    std::cerr << "labelled " << rec.rows.size() << " rows: " << counts[2] << " visible, " << counts[1] << " hidden, "
              << counts[0] << " no hand (finger labels)\n";
  });
}

const lmc::cli::CommandRegistration visibility_command{
    "visibility", "Label a recording's rows with ray-traced finger visibility", 40, setup_visibility};

}  // namespace
