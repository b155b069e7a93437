#include "core/common/number_format.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "core/common/decimal_digits.h"
#include "core/common/uint128.h"

namespace lmc {

namespace {

// "%.*f" by integer arithmetic for up to 9 decimals and values below ~9e18 / 10^decimals: v is
// m · 2^e exactly, so v · 10^d is m · 10^d · 2^e, a 128-bit integer shifted, and the discarded bits
// say exactly whether the value lies below, on or above the halfway point — printf's rule (round
// the binary value, ties to even) with no floating-point step to blur it, and cheaper than the
// general formatter (docs/results/processing.md); nullptr hands a value it does not cover on.
// Writes up to 32 bytes at `first`.
char* write_fixed_by_integers(char* first, double v, int decimals) {
  using decimal_digits::kPow10;
  if (decimals < 0 || decimals > 9) return nullptr;
  const auto bits = std::bit_cast<std::uint64_t>(v);
  const bool negative = (bits >> 63) != 0;
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased == 0x7ff) return nullptr;
  const std::uint64_t m = biased == 0 ? fraction : (fraction | (std::uint64_t{1} << 52));
  const int e = biased == 0 ? -1074 : biased - 1075;
  using u128 = Uint128;
  const u128 scaled = static_cast<u128>(m) * kPow10[decimals];  // < 2^83
  u128 n = 0;
  if (e >= 0) {
    if (e > 40) return nullptr;
    n = scaled << e;
  } else if (-e < 128) {
    const int shift = -e;
    n = scaled >> shift;
    const u128 rest = scaled & ((u128{1} << shift) - 1);
    const u128 half = u128{1} << (shift - 1);
    if (rest > half || (rest == half && (n & 1) != 0)) ++n;
  }  // else: below half a unit of the last decimal, n stays 0
  if ((n >> 63) != 0) return nullptr;
  const auto whole = static_cast<std::uint64_t>(n);
  // The digits of `whole` (at least decimals + 1 of them) with the point put in, built in one
  // buffer leftwards from buf + 40 and copied out once. The decimals, a fixed count, move right to
  // make room for the point; the whole part, whose length varies, stays where it is. The final
  // fixed-size copy reads 32 bytes from the first character: for a short number, past buf + 64.
  char buf[80];
  char* end = buf + 40;
  char* start = nullptr;
  if (whole < 10000000000000000u) {
    decimal_digits::write_sixteen_digits(end - 16, whole);  // with leading zeros, as needed below
    start = end - std::max(whole == 0 ? 1 : decimal_digits::digit_count(whole), decimals + 1);
  } else {
    start = decimal_digits::digits_ending_at(end, whole);
    while (end - start < decimals + 1) *--start = '0';
  }
  if (decimals > 0) {
    // Sixteen bytes from the first decimal (≤ 9 of them, the rest spare room) one place right.
    char moved[16];
    std::memcpy(moved, end - decimals, sizeof moved);
    std::memcpy(end - decimals + 1, moved, sizeof moved);
    end[-decimals] = '.';
    ++end;
  }
  if (negative) *--start = '-';
  // At most 30 characters (a sign, 19 digits, a point, 9 decimals): one fixed-size copy.
  std::memcpy(first, start, 32);
  return first + (end - start);
}

}  // namespace

char* write_fixed(char* first, double v, int decimals) {
  if (std::isnan(v)) {
    std::memcpy(first, "nan", 3);
    return first + 3;
  }
  if (std::isinf(v)) {
    if (v > 0) {
      std::memcpy(first, "inf", 3);
      return first + 3;
    }
    std::memcpy(first, "-inf", 4);
    return first + 4;
  }
  return write_fixed_by_integers(first, v, decimals);
}

void append_fixed(std::string& out, double v, int decimals) {
  char quick[kFixedQuickRoom];
  if (char* end = write_fixed(quick, v, decimals)) {
    out.append(quick, end);
    return;
  }
  // std::to_chars with a precision writes exactly what printf's "%.*f" writes (both round the
  // exact binary value), several times faster than printf. A value or precision too long for the
  // buffer (1e300 with 4 decimals) goes the slow way whole.
  char buf[128];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (ec == std::errc()) {
    out.append(buf, end);
    return;
  }
  const int n = std::snprintf(nullptr, 0, "%.*f", decimals, v);
  const size_t at = out.size();
  out.resize(at + static_cast<size_t>(n) + 1);
  std::snprintf(out.data() + at, static_cast<size_t>(n) + 1, "%.*f", decimals, v);
  out.resize(at + static_cast<size_t>(n));
}

std::string format_fixed(double v, int decimals) {
  std::string out;
  append_fixed(out, v, decimals);
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
