#include "core/common/number_format.h"

#include <cmath>
#include <cstdio>

namespace lmc {

std::string format_fixed(double v, int decimals) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
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
