#pragma once
// A calibration written back into a layout, and the residual table people read.
//
// How a fitted transform p ↦ R_f·p + t_f maps onto the layout's pose and offset
// (p = R·p_d + t + offset, docs/algorithms/frames.md): the rotation goes into the pose's angles
// (the offset is a pure translation and cannot hold one); the pose's x, y, z stay the nominal
// position a person measured, and the whole translation correction goes into the offset,
// offset = t_f − (x, y, z), the field the study used for exactly this kind of correction. Then
// to_world reproduces the fitted transform exactly, and the offset says how far the controller
// really stood from where the layout put it.
#include <string>

#include "core/calibration/calibration_result.h"
#include "core/layout/layout.h"

namespace lmc {

struct CalibrationSource {
  std::string trial;     // the calibration trial's name or file
  std::string vicon;     // the Vicon file, empty without
  std::string when_utc;  // ISO 8601
};

// `nominal` with every fitted controller's pose angles and offset replaced; name and
// description say it is calibrated, from what and when.
Layout calibrated_layout(const Layout& nominal, const CalibrationResult& result, const CalibrationSource& source);

// A fixed-width table: per controller samples, RMS before → after (all points and per group),
// the correction (mm, degrees), then the disagreement between controllers and every warning.
std::string residual_table(const CalibrationResult& result);

}  // namespace lmc
