#include "ui/model/devices/calibration_job.h"

#include <utility>

#include "core/calibration/calibrated_layout.h"
#include "core/common/utc_time.h"
#include "core/io/lmc_recording.h"

namespace lmc::ui {

void CalibrationJob::start(std::filesystem::path recording, Layout layout, std::string trial_name) {
  job_.start([file = std::move(recording), nominal = std::move(layout), trial = std::move(trial_name)](
                 std::stop_token, JobChannel<NoReport>& channel) {
    // Each stage takes a fraction of a second: no cancellation points inside them.
    channel.set_stage("reading " + file.filename().string());
    const LmcRecording rec = read_lmc_recording(file);
    channel.set_stage("resampling and ray tracing");
    const auto input = calibration::prepare_calibration_input(rec, nullptr, {});
    channel.set_stage("calibrating");
    CalibrationOutcome out;
    out.result = calibration::calibrate(input, nominal);
    out.calibrated = calibration::calibrated_layout(nominal, out.result, {trial, "", utc_now_iso8601()});
    out.table = calibration::residual_table(out.result);
    return out;
  });
}

}  // namespace lmc::ui
