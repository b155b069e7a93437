#pragma once
// Decimal digits of an unsigned integer written from the right, two at a time: shared by the
// number writers (shortest_double.cpp, number_format.cpp), whose outputs are millions of numbers.
#include <bit>
#include <cstdint>
#include <cstring>

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
