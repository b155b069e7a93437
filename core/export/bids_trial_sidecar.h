#pragma once
// What a trial's recorder sidecar (core/io/recorder_sidecar.h) tells its BIDS files: each tracking
// system's motion.json fields (maker, model, serial, software), the trial's events and its
// acquisition time. A trial without a sidecar (a crash left none) still gets its motion.json, with
// what is known; it has no events then.
#include <cstdint>
#include <string>
#include <vector>

#include "core/export/bids_motion_files.h"
#include "core/export/bids_study.h"
#include "core/io/recorder_sidecar.h"
#include "core/processing/trial_pipeline.h"

namespace lmc {

BidsMotionInfo bids_motion_info(const BidsTrialPlan& trial, const BidsTrackingSystem& system,
                                const RecorderSidecar* sidecar, FusionMethod method);

// go (the first row the controllers wrote, when the sidecar says the trial reached go; lasting to
// the last row), stop (the last row) and vicon_capture_start (CaptureStart on the controllers'
// clock, or the simulated Vicon's time zero), in onset order, as seconds from `grid_start_us`
// (the device-clock time of the motion files' first row). Empty without a sidecar.
std::vector<BidsEvent> bids_trial_events(std::int64_t grid_start_us, const RecorderSidecar* sidecar);

// The go time (or the recorder's start) in BIDS's form; empty when unknown or `anonymise` (dates
// identify a subject as well as a name does).
std::string bids_trial_acq_time(const RecorderSidecar* sidecar, bool anonymise);

}  // namespace lmc
