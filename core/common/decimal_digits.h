#pragma once
// Decimal digits of an unsigned integer written from the right, two at a time: shared by the
// number writers (shortest_double.cpp, number_format.cpp), whose outputs are millions of numbers.
#include <bit>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace lmc::decimal_digits {

// 10^0 … 10^19: every power of ten a uint64_t holds.
inline constexpr std::uint64_t kPow10[] = {1ull,
                                           10ull,
                                           100ull,
                                           1000ull,
                                           10000ull,
                                           100000ull,
                                           1000000ull,
                                           10000000ull,
                                           100000000ull,
                                           1000000000ull,
                                           10000000000ull,
                                           100000000000ull,
                                           1000000000000ull,
                                           10000000000000ull,
                                           100000000000000ull,
                                           1000000000000000ull,
                                           10000000000000000ull,
                                           100000000000000000ull,
                                           1000000000000000000ull,
                                           10000000000000000000ull};

// How many decimal digits d (> 0) has: an estimate from its bit length, corrected by one compare.
inline int digit_count(std::uint64_t d) {
  const int estimate = (std::bit_width(d) * 1233) >> 12;  // floor(log10 2^bits): at most one short
  return estimate + (d >= kPow10[estimate] ? 1 : 0);
}

inline constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// The eight decimal digits of d (< 10^8, with leading zeros) at `out`: four independent pairs, not
// one chain of divisions by ten.
inline void write_eight_digits(char* out, std::uint32_t d) {
  const std::uint32_t high = d / 10000;
  const std::uint32_t low = d % 10000;
  std::memcpy(out, kDigitPairs + 2 * (high / 100), 2);
  std::memcpy(out + 2, kDigitPairs + 2 * (high % 100), 2);
  std::memcpy(out + 4, kDigitPairs + 2 * (low / 100), 2);
  std::memcpy(out + 6, kDigitPairs + 2 * (low % 100), 2);
}

// The sixteen decimal digits of d (< 10^16, with leading zeros) at `out`. With SSE2 (every x86-64
// CPU) the four-digit groups are split into pairs and the pairs into digits in eight lanes at once:
// a quotient by 100 or 10 of such small numbers is exactly a multiply-high by 5243 (then >> 3) or
// by 6554, so the digits are the same as by division.
inline void write_sixteen_digits(char* out, std::uint64_t d) {
  const auto high = static_cast<std::uint32_t>(d / 100000000);
  const auto low = static_cast<std::uint32_t>(d % 100000000);
#if defined(__SSE2__)
  const auto g0 = static_cast<short>(high / 10000), g1 = static_cast<short>(high % 10000);
  const auto g2 = static_cast<short>(low / 10000), g3 = static_cast<short>(low % 10000);
  const __m128i groups = _mm_setr_epi16(g0, g0, g1, g1, g2, g2, g3, g3);
  const __m128i hundreds = _mm_srli_epi16(_mm_mulhi_epu16(groups, _mm_set1_epi16(5243)), 3);
  const __m128i below_hundred = _mm_sub_epi16(groups, _mm_mullo_epi16(hundreds, _mm_set1_epi16(100)));
  const __m128i odd_lanes = _mm_setr_epi16(0, -1, 0, -1, 0, -1, 0, -1);
  // Lane 2i: group i's first two digits; lane 2i + 1: its last two.
  const __m128i pairs = _mm_or_si128(_mm_andnot_si128(odd_lanes, hundreds), _mm_and_si128(odd_lanes, below_hundred));
  const __m128i tens = _mm_mulhi_epu16(pairs, _mm_set1_epi16(6554));
  const __m128i ones = _mm_sub_epi16(pairs, _mm_mullo_epi16(tens, _mm_set1_epi16(10)));
  // Each lane's two bytes in memory order: the tens digit, then the ones digit.
  const __m128i digits = _mm_add_epi8(_mm_or_si128(tens, _mm_slli_epi16(ones, 8)), _mm_set1_epi8('0'));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), digits);
#else
  write_eight_digits(out, high);
  write_eight_digits(out + 8, low);
#endif
}

// The decimal digits of d (0 is written "0") written so they end at `end`; returns where they
// start.
inline char* digits_ending_at(char* end, std::uint64_t d) {
  while (d >= 100000000) {
    end -= 8;
    write_eight_digits(end, static_cast<std::uint32_t>(d % 100000000));
    d /= 100000000;
  }
  auto rest = static_cast<std::uint32_t>(d);
  while (rest >= 100) {
    end -= 2;
    std::memcpy(end, kDigitPairs + 2 * (rest % 100), 2);
    rest /= 100;
  }
  if (rest >= 10) {
    end -= 2;
    std::memcpy(end, kDigitPairs + 2 * rest, 2);
  } else {
    *--end = static_cast<char>('0' + rest);
  }
  return end;
}

}  // namespace lmc::decimal_digits
