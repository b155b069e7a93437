#pragma once
// While a trial records: frames written, the Vicon trigger's state (packets sent, or in listen
// mode whether CaptureStart / CaptureStop came) and a strip per controller (rate, hand present,
// frame age), from the trial engine's latest snapshot. Draws only.
#include "devices/record/trial_engine.h"

namespace lmc::ui {

void draw_record_device_strips(const devices::TrialSnapshot& live);

}  // namespace lmc::ui
