#pragma once
// A quick exact reader for the numbers the recordings and TRC files are made of: an optional '-',
// digits, and an optional '.' followed by digits, at most 19 digits in all. It gives exactly the
// double std::from_chars gives, or declines and leaves the number to it; a subject's files hold
// ten million such numbers, so reading them is a large part of processing (the measurements are in
// docs/results/processing.md).
//
// Why it is exact: the digits make an integer w < 10^19, and the value is w / 10^f = w / 5^f · 2^−f.
// With R = floor(2^(63+e) / 5^f) (64 bits) and w shifted left to 64 bits, the product P = w·R is
// at most w below the exact w·2^(63+e)/5^f (R is at most 1 below the exact reciprocal). Its top 53
// bits, rounded by the bits below, are the double, unless a halfway point between two doubles lies
// within that margin of P: only then could the exact value round differently, and those (about one
// number in a thousand) are declined. The same argument as Lemire's fast decimal conversion, on the
// one range we need. It holds for every w ≥ 1. For w ≤ 2^53 one IEEE division w / 10^f would do
// too (the classic fast path), but a field of the study's files has 16 or 17 digits, w falls on
// either side of 2^53 at random, and that branch the CPU keeps mispredicting costs more than the
// division saves.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

#include "core/common/cpu_features.h"
#include "core/common/uint128.h"

namespace lmc {

namespace plain_decimal_detail {

inline constexpr int kMaxDigits = 19;  // 10^19 − 1 < 2^64

using u128 = Uint128;

// 1/5^f as R / 2^(63+e), R = floor(2^(63+e) / 5^f) in [2^63, 2^64).
struct Reciprocal {
  std::uint64_t r = 0;
  int e = 0;
};
inline constexpr std::array<Reciprocal, kMaxDigits + 1> kReciprocals = [] {
  std::array<Reciprocal, kMaxDigits + 1> t{};
  std::uint64_t pow5 = 1;
  for (std::size_t f = 0; f < t.size(); ++f) {
    t[f].e = f == 0 ? 0 : static_cast<int>(std::bit_width(pow5));
    t[f].r = static_cast<std::uint64_t>((u128{1} << (63 + t[f].e)) / pow5);
    pow5 *= 5;
  }
  return t;
}();

// w (≥ 1, < 2^64) / 10^f as a double, or false when w is too near a halfway point to tell.
inline bool wide_quotient(std::uint64_t w, int f, double& out) {
  const int shift = std::countl_zero(w);
  const Reciprocal& rec = kReciprocals[static_cast<std::size_t>(f)];
  const u128 product = static_cast<u128>(w << shift) * rec.r;  // in [2^126, 2^128)
  const auto high = static_cast<std::uint64_t>(product >> 64);
  const auto low = static_cast<std::uint64_t>(product);
  // When the margin (< 2^64) may carry the product past 2^127 (high = 2^63 − 1, the value is a power
  // of two such as "0.5"), both sides round to 2^127: below it, the 10 dropped bits are all ones
  // and round up; above it, the excess is far below half. The general rule below gives 2^127.
  const int top = static_cast<int>(high >> 63);
  const int dropped = 10 + top;  // bits of `high` below the double's 53 (plus all of `low`)
  const std::uint64_t half = std::uint64_t{1} << (dropped - 1);
  const std::uint64_t rest = high & ((std::uint64_t{1} << dropped) - 1);
  // A halfway point within the margin above the product: the exact value may be on either side.
  if (rest == half - 1 || (rest == half && low == 0)) return false;
  const std::uint64_t significand = (high >> dropped) + (rest >= half ? 1 : 0);  // ≤ 2^53
  const int exponent = 64 + dropped - 63 - rec.e - shift - f;
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(1023 + exponent) << 52);
  out = static_cast<double>(static_cast<std::int64_t>(significand)) * scale;  // exact: a power of two
  return true;
}

// w / 10^f, negated when asked, as a double; false (out untouched) when w is too near a halfway
// point to tell (wide_quotient).
inline bool to_double(std::uint64_t w, int f, bool negative, double& out) {
  double v = 0.0;
  if (w != 0 && !wide_quotient(w, f, v)) return false;
  out = negative ? -v : v;
  return true;
}

#if defined(__x86_64__) && defined(__GNUC__)
// Bytes read_plain_decimal_avx2 may load from `first` on: a sign, a 32-byte window, and 16 bytes
// from where the fraction starts inside it.
inline constexpr std::ptrdiff_t kWideLookahead = 64;
// read_plain_decimal for a CPU with AVX2 and kWideLookahead bytes loadable from `first`.
const char* read_plain_decimal_avx2(const char* first, const char* last, double& out);
#endif

inline bool is_digit(char c) {
  return static_cast<unsigned char>(c - '0') < 10;
}

}  // namespace plain_decimal_detail

// Reads a plain decimal starting at `first` and stopping at the first character that cannot
// continue it (or at `last`). Returns where it stopped, or nullptr (`out` untouched) when the text
// there is not a plain decimal of at most 19 digits, or when the quick conversion declines: the
// caller then reads the field with std::from_chars and its own checks.
inline const char* read_plain_decimal(const char* first, const char* last, double& out) {
  namespace d = plain_decimal_detail;
  const char* p = first;
  const bool negative = p != last && *p == '-';
  if (negative) ++p;
  std::uint64_t w = 0;
  // Digits up to `stop` (at most kMaxDigits in all); one more digit after it declines.
  const auto digits_until = [&w, &p](const char* stop) {
    while (p != stop) {
      const auto digit = static_cast<unsigned char>(*p - '0');
      if (digit > 9) break;
      w = w * 10 + digit;
      ++p;
    }
  };
  const char* const whole = p;
  digits_until(last - p > d::kMaxDigits ? p + d::kMaxDigits : last);
  const auto whole_digits = static_cast<int>(p - whole);
  if (whole_digits == 0 || (p != last && d::is_digit(*p))) return nullptr;
  int fraction_digits = 0;
  if (p != last && *p == '.') {
    const char* const fraction = ++p;
    const int room = d::kMaxDigits - whole_digits;
    digits_until(last - p > room ? p + room : last);
    fraction_digits = static_cast<int>(p - fraction);
    if (fraction_digits == 0 || (p != last && d::is_digit(*p))) return nullptr;
  }
  // An exponent or a second point: from_chars's business.
  if (p != last && (*p == 'e' || *p == 'E' || *p == '.')) return nullptr;
  return d::to_double(w, fraction_digits, negative, out) ? p : nullptr;
}

// The same reading, with the same result, for text inside a buffer that ends at `buffer_end`
// (≥ last): where the buffer leaves room after `first`, the digits are found and read 16 at a time
// (plain_decimal.cpp), with no branch per digit. A field of the study's files is 17 to 19
// characters, and the per-digit loop's exits were most of its cost.
inline const char* read_plain_decimal(const char* first, const char* last, const char* buffer_end, double& out) {
#if defined(__x86_64__) && defined(__GNUC__)
  if (buffer_end - first >= plain_decimal_detail::kWideLookahead && cpu_has_avx2()) {
    return plain_decimal_detail::read_plain_decimal_avx2(first, last, out);
  }
#endif
  (void)buffer_end;
  return read_plain_decimal(first, last, out);
}

}  // namespace lmc
