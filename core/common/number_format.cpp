#include "core/common/number_format.h"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace lmc {

std::string format_fixed(double v, int decimals) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  // std::to_chars with a precision writes exactly what printf's "%.*f" writes (both round the
  // exact binary value), several times faster: the processing outputs write millions of numbers.
  // A value or precision too long for the buffer (1e300 with 4 decimals) goes the slow way whole.
  char buf[128];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (ec == std::errc()) return std::string(buf, end);
  const int n = std::snprintf(nullptr, 0, "%.*f", decimals, v);
  std::string out(static_cast<size_t>(n) + 1, '\0');
  std::snprintf(out.data(), out.size(), "%.*f", decimals, v);
  out.resize(static_cast<size_t>(n));
  return out;
}

std::string format_readable(double v, int decimals, bool plus_sign) {
  std::string text = format_fixed(v, decimals);
  if (!std::isfinite(v)) return text;
  // Whether the written digits are all zero decides, not v itself: -0.004 rounds to zero too.
  const bool zero = text.find_first_of("123456789") == std::string::npos;
  if (zero && !text.empty() && text[0] == '-') text.erase(0, 1);
  if (plus_sign && !zero && v > 0) text.insert(0, 1, '+');
  return text;
}

}  // namespace lmc
