#pragma once
// A calibration's result as people read it: per controller samples, RMS residual
// before > after, how far it moved and turned (or that it could not be calibrated), the
// disagreement between controllers, every warning in red and how to read the numbers. The
// Devices tab's Calibrate step and the Record tab's block calibration draw the same view.
#include <string>
#include <vector>

#include "core/calibration/calibration_result.h"

namespace lmc::ui {

// `file_warnings`: what reading the trial found wrong; `notes`: what was done to line things up.
void draw_calibration_result(const std::string& trial, const CalibrationResult& result,
                             const std::vector<std::string>& file_warnings, const std::vector<std::string>& notes);

}  // namespace lmc::ui
