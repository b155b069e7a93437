#pragma once
// How numbers are written in the study's text outputs and in messages: one formatter for every
// folder of core (results, processing, calibration) so none needs another's header for it.
#include <string>

namespace lmc {

// Python-style "%f"/"%.2f": NaN → "nan", ±inf → "inf"/"-inf".
std::string format_fixed(double v, int decimals);
// The same characters appended to `out` (no string of its own: tables of millions of numbers).
void append_fixed(std::string& out, double v, int decimals);

// Room write_fixed may use.
inline constexpr int kFixedQuickRoom = 64;
// The same characters written at `first` (kFixedQuickRoom bytes of room, which it may use past the
// end it returns), for tables built a row at a time; nullptr, with nothing promised about the room,
// for what only append_fixed writes: over 9 decimals, or a value of 2^63 units of the last decimal
// or more (1e15 with 4 decimals).
char* write_fixed(char* first, double v, int decimals);

// A number for a person to read (tables, plot labels, the workbench): fixed-point like
// format_fixed, with a leading "+" on positive values when `plus_sign` (a difference), and never
// a negative zero — -0.004 with 2 decimals reads "0.00", not "-0.00" (a reader takes the sign for
// a direction the value does not have). A value that rounds to zero has no sign at all.
std::string format_readable(double v, int decimals, bool plus_sign = false);

}  // namespace lmc
