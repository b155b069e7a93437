#pragma once
// The plot widgets' round ticks, fitted y range and cursor value text are core's
// (core/figures/axis_ticks.h), so the screen and the exported figures pick the same ticks: one
// implementation, named here for ui code.
#include "core/figures/axis_ticks.h"

namespace lmc::ui {}  // namespace lmc::ui
