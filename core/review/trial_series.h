#pragma once
// One processed trial as time series for the Review tab's stacked plots and their CSV export
//: the six joint angles and five finger lengths of the fused hand, of Vicon and of each
// controller after realignment, and per controller and finger the ray-traced label, so every gap
// in a curve has a visible cause. Missing values stay NaN (never 0); series share one time axis in
// seconds from the grid's first frame (Vicon frame f is grid frame f: processing aligns them).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/processing/measures.h"
#include "core/processing/trial_pipeline.h"

namespace lmc {

struct MeasureSeries {
  std::array<std::vector<double>, kNumAngles> angle_deg;   // [angle][frame]
  std::array<std::vector<double>, kNumFingers> finger_mm;  // [finger][frame]
};

struct DeviceSeries {
  int device_id = 0;                                       // LMC1 = 1
  MeasureSeries measures;                                  // this controller alone, realigned
  std::array<std::vector<std::int8_t>, kNumDigits> label;  // [finger][frame]: 1 seen, 0 model, −1 no hand
};

struct TrialSeries {
  std::string trial;
  std::vector<double> time_s;  // one per frame
  MeasureSeries fused;
  bool has_vicon = false;
  MeasureSeries vicon;  // empty vectors without Vicon; else as long as time_s (NaN past its end)
  std::vector<DeviceSeries> devices;
  int frames() const { return static_cast<int>(time_s.size()); }
};

TrialSeries trial_series(const TrialAnalysis& result);

// Label words for a legend or tooltip: "seen", "internal model", "no hand".
const char* label_word(std::int8_t label);

// The exact numbers behind the plots: one row per frame, columns time_s, then fused, Vicon and each
// controller's angles and finger lengths, then each controller's labels. NaN is an empty cell.
std::string trial_series_csv(const TrialSeries& series);

}  // namespace lmc
