#pragma once
// How numbers are written in the study's text outputs and in messages: one formatter for every
// folder of core (results, processing, calibration) so none needs another's header for it.
#include <string>

namespace lmc {

// Python-style "%f"/"%.2f": NaN → "nan", ±inf → "inf"/"-inf".
std::string format_fixed(double v, int decimals);

}  // namespace lmc
