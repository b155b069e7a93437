#include "core/common/shortest_double.h"

#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

#include "core/common/decimal_digits.h"
#include "core/common/uint128.h"

namespace lmc {

namespace {

using u128 = Uint128;

// The fast path takes v = c · 2^q with q in [kMinExponent, 0]: every value from about 7.6e-6 to
// 2^53 that is not a power of two, which is nearly every coordinate in millimetres. Anything else
// goes to std::to_chars, which is right for every double; so is this path, by exact arithmetic.
constexpr int kMinExponent = -69;  // the largest p = -q for which 10^m, m = ceil(p·log10 2), is ≤ 10^21

// 10^0 … 10^21 as 128-bit integers (10^21 > 2^64).
constexpr std::array<u128, 22> kWidePow10 = [] {
  std::array<u128, 22> t{};
  t[0] = 1;
  for (size_t m = 1; m < t.size(); ++m) t[m] = t[m - 1] * 10;
  return t;
}();

char* fallback(char* first, double v) {
  return std::to_chars(first, first + kShortestDoubleMaxChars, v).ptr;
}

}  // namespace

// The shortest decimal in v's rounding interval, by the interval argument of Giulietti's
// Schubfach: scaled by 10^m so that the interval is at least one unit wide, the interval holds
// one or two integers and at most one multiple of ten. A multiple of ten inside is the (unique)
// shorter candidate; otherwise the nearer of the two integers around v. Every quantity is an
// exact integer here — v · 10^m · 4 is c · 10^m · 4 / 2^p with c · 10^m < 2^123 — so the
// comparisons with the interval's ends are exact and no table of rounded powers is needed.
char* write_shortest(char* first, double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  const bool negative = (bits >> 63) != 0;
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased == 0 && fraction == 0) {
    char* out = first;
    if (negative) *out++ = '-';
    *out++ = '0';
    return out;
  }
  if (biased == 0x7ff && fraction != 0) {
    // NaN, as std::to_chars writes it: a fused file has one for every point of a frame without a
    // hand, a twentieth of its numbers.
    char* out = first;
    if (negative) *out++ = '-';
    std::memcpy(out, "nan", 3);
    return out + 3;
  }
  const int q = biased - 1075;
  // Subnormals, the infinities, large and small values, and powers of two (whose interval is
  // lopsided) take the general route.
  if (biased == 0 || biased == 0x7ff || fraction == 0 || q > 0 || q < kMinExponent) return fallback(first, v);

  const std::uint64_t c = fraction | (std::uint64_t{1} << 52);
  const int p = -q;
  // k = floor(q · log10 2) (exact for |q| < 1650 with this constant), so 10^k ≤ 2^q: in units of
  // 10^k the interval, 2^q wide, is at least one unit wide and under ten.
  const int k = (q * 78913) >> 18;
  const int m = -k;
  const u128 pow_m = kWidePow10[static_cast<size_t>(m)];
  const u128 centre = (static_cast<u128>(c) * pow_m) << 2;  // 4 · v · 10^m · 2^p
  const u128 lower = centre - 2 * pow_m;                    // 4 · (c − ½) · 10^m
  const u128 upper = centre + 2 * pow_m;                    // 4 · (c + ½) · 10^m
  // Round-to-nearest-even reads the interval's ends back as v when c is even. (Written without
  // branches: the parity of c is a coin toss, and a mispredicted branch costs more than the test.)
  const unsigned ends_included = (c & 1) == 0 ? 1 : 0;
  const auto above_lower = [&](std::uint64_t quarters) {
    return lower < (static_cast<u128>(quarters) << p) + ends_included;
  };
  const auto below_upper = [&](std::uint64_t quarters) {
    return (static_cast<u128>(quarters) << p) < upper + ends_included;
  };

  const auto s = static_cast<std::uint64_t>(centre >> (p + 2));  // floor(v · 10^m), < 2^57
  std::uint64_t digits = 0;
  int exponent = k;  // of the last digit
  bool found = false;
  if (s >= 10) {
    const std::uint64_t sp = s / 10;
    const bool down_inside = above_lower(40 * sp);
    const bool up_inside = below_upper(40 * sp + 40);
    if (down_inside != up_inside) {
      digits = sp + (up_inside ? 1 : 0);
      exponent = k + 1;
      found = true;
    }
  }
  if (!found) {
    const bool down_inside = above_lower(4 * s);
    const bool up_inside = below_upper(4 * s + 4);
    if (down_inside && up_inside) {
      // The nearer of s and s + 1 to v, a tie to the even one.
      const u128 mid = static_cast<u128>(4 * s + 2) << p;
      digits = s + static_cast<std::uint64_t>((centre > mid) | ((centre == mid) & ((s & 1) != 0)));
    } else if (down_inside || up_inside) {
      digits = s + (up_inside ? 1 : 0);
    } else {
      return fallback(first, v);  // cannot happen for an interval a unit wide; stay right regardless
    }
  }
  while (digits % 10 == 0) {
    digits /= 10;
    ++exponent;
  }

  // Fixed or scientific, by length as std::to_chars chooses; the scientific form (rare in
  // millimetres) goes to the general route.
  const int n = decimal_digits::digit_count(digits);
  const int leading = exponent + n - 1;  // the decimal exponent of the first digit
  const int scientific_length = n + (n > 1 ? 1 : 0) + 2 + (leading >= 100 || leading <= -100 ? 3 : 2);
  int fixed_length = 0;
  if (exponent >= 0) {
    fixed_length = n + exponent;
  } else if (leading >= 0) {
    fixed_length = n + 1;
  } else {
    fixed_length = n + 1 - leading;
  }
  if (fixed_length > scientific_length) return fallback(first, v);

  char* out = first;
  if (negative) *out++ = '-';
  if (exponent >= 0) {
    decimal_digits::digits_ending_at(out + n, digits);
    std::memset(out + n, '0', static_cast<size_t>(exponent));
    return out + n + exponent;
  }
  if (leading >= 0 && leading < 8) {
    // The digits at a fixed place, then the whole part and the fraction copied out in blocks of
    // fixed length (whose bytes past the number's end the caller's room absorbs): no loop whose
    // length, the whole part's 1 to 3 digits, the CPU would have to guess.
    char digit_text[40] = {};
    char* const digit_end = digit_text + 24;
    decimal_digits::write_sixteen_digits(digit_end - 16, digits % 10000000000000000u);
    digit_end[-17] = static_cast<char>('0' + digits / 10000000000000000u);  // n ≤ 17
    const char* const digit_start = digit_end - n;
    std::memcpy(out, digit_start, 8);
    out[leading + 1] = '.';
    std::memcpy(out + leading + 2, digit_start + leading + 1, 16);
    return out + n + 1;
  }
  if (leading >= 0) {
    // A whole part of eight digits or more: the digits one place to the right, then the whole part
    // moved left over the point's place.
    decimal_digits::digits_ending_at(out + n + 1, digits);
    for (int i = 0; i <= leading; ++i) out[i] = out[i + 1];
    out[leading + 1] = '.';
    return out + n + 1;
  }
  *out++ = '0';
  *out++ = '.';
  std::memset(out, '0', static_cast<size_t>(-leading - 1));
  out += -leading - 1;
  decimal_digits::digits_ending_at(out + n, digits);
  return out + n;
}

}  // namespace lmc
