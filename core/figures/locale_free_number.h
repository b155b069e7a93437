#pragma once
// Numbers in exported files are written in the C locale whatever the program's global locale:
// a German locale must not turn 1.5 into "1,5" inside an SVG coordinate or a CSV cell.
// std::to_chars never consults the locale (printf does), so both functions build on it.
#include <string>

namespace lmc {

// Fixed-point with `decimals` digits after the point; "-0.00" is written "0.00" so output does not
// depend on the sign of a rounded zero. Non-finite values give "nan", "inf", "-inf".
std::string fixed_c(double v, int decimals);

// The shortest text that reads back as exactly `v` (the CSV's exact data); "" for NaN or ±inf.
std::string exact_c(double v);

}  // namespace lmc
