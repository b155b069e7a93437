#include "ui/model/devices/calibration_job.h"

#include <utility>

#include "core/calibration/calibrated_layout.h"
#include "core/common/utc_time.h"

namespace lmc::ui {

void CalibrationJob::start(TrialCalibrationRequest request, Layout layout) {
  if (request.when_utc.empty()) request.when_utc = utc_now_iso8601();
  job_.start(
      [req = std::move(request), nominal = std::move(layout)](std::stop_token stop, JobChannel<NoReport>& channel) {
        // Reading, ray tracing and fitting take a fraction of a second: the stop is honoured before and
        // after, never inside.
        CalibrationOutcome out;
        if (stop.stop_requested()) return out;
        channel.set_stage("calibrating from " + req.trial.filename().string() + (req.vicon ? " against Vicon" : ""));
        TrialCalibration cal = calibrate_trial(req, nominal);
        if (stop.stop_requested()) return out;
        out.trial = std::move(cal.trial);
        out.table = residual_table(cal.result);
        out.result = std::move(cal.result);
        out.calibrated = std::move(cal.calibrated);
        out.file_warnings = std::move(cal.file_warnings);
        out.notes = std::move(cal.notes);
        return out;
      });
}

}  // namespace lmc::ui
