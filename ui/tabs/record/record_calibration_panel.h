#pragma once
// The Record tab's block calibration, for protocols with a calibration step: before a
// block's first trial, the cues for a still open hand and a button to record it; while it
// records, the time left; then the residual table (the Devices tab's, calibration_result_view.h)
// and the operator's choice: Apply, calibrate again, or keep the nominal layout with a reason.
#include "ui/model/record/record_session_model.h"
#include "ui/tabs/record/record_trial_panel.h"

namespace lmc::ui {

TrialPanelAction draw_block_calibration(const RecordSessionModel& model, TrialPanelInput& input);

}  // namespace lmc::ui
