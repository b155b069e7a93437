#include "core/common/plain_decimal.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include <bit>

#include "core/common/decimal_digits.h"

namespace lmc::plain_decimal_detail {

namespace {

// Shuffle masks that move the first L bytes of a 16-byte load to its end and zero the rest:
// byte i of the result is byte i − (16 − L) of the input, or 0 (index 0x80) before that.
struct RightAlignMasks {
  alignas(16) unsigned char mask[17][16];
};
constexpr RightAlignMasks make_right_align_masks() {
  RightAlignMasks t{};
  for (int length = 0; length <= 16; ++length) {
    for (int i = 0; i < 16; ++i) {
      const int from = i - (16 - length);
      t.mask[length][i] = from >= 0 ? static_cast<unsigned char>(from) : 0x80;
    }
  }
  return t;
}
constexpr RightAlignMasks kRightAlign = make_right_align_masks();

// The integer the `length` (1…16) digits at `at` spell. Right-aligned in 16 lanes, they are joined
// pairwise three times: 16 digits → 8 two-digit → 4 four-digit → 2 eight-digit numbers. Every step
// is exact (each lane stays below 2^15 or 2^31), so this is the same integer the digit loop builds.
[[gnu::target("avx2")]] std::uint64_t digits_value(const char* at, int length) {
  __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(at));
  v = _mm_sub_epi8(v, _mm_set1_epi8('0'));
  v = _mm_shuffle_epi8(v, _mm_load_si128(reinterpret_cast<const __m128i*>(kRightAlign.mask[length])));
  const __m128i pairs = _mm_maddubs_epi16(v, _mm_setr_epi8(10, 1, 10, 1, 10, 1, 10, 1, 10, 1, 10, 1, 10, 1, 10, 1));
  const __m128i fours = _mm_madd_epi16(pairs, _mm_setr_epi16(100, 1, 100, 1, 100, 1, 100, 1));
  const __m128i packed = _mm_packus_epi32(fours, fours);
  const __m128i eights = _mm_madd_epi16(packed, _mm_setr_epi16(10000, 1, 10000, 1, 10000, 1, 10000, 1));
  const auto high = static_cast<std::uint32_t>(_mm_cvtsi128_si32(eights));
  const auto low = static_cast<std::uint32_t>(_mm_extract_epi32(eights, 1));
  return std::uint64_t{high} * 100000000u + low;
}

}  // namespace

// Where the digits stop is read off a 32-byte window's mask of non-digits, so there is no loop
// whose exit the CPU must guess. Anything this does not settle (no digits, over 16 digits in a part
// or 19 in all, a number running past `last` or the window) is left to the digit loop, so the result
// is always read_plain_decimal's.
[[gnu::target("avx2")]] const char* read_plain_decimal_avx2(const char* first, const char* last, double& out) {
  const bool negative = *first == '-';
  const char* const at = first + (negative ? 1 : 0);
  const __m256i window = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(at));
  const __m256i values = _mm256_sub_epi8(window, _mm256_set1_epi8('0'));
  const __m256i digit = _mm256_cmpeq_epi8(_mm256_min_epu8(values, _mm256_set1_epi8(9)), values);
  const auto non_digits = ~static_cast<std::uint32_t>(_mm256_movemask_epi8(digit));
  const int whole = std::countr_zero(non_digits);  // 32 when the window is all digits
  if (whole == 0 || whole > 16) return read_plain_decimal(first, last, out);
  int fraction = 0;
  int end = whole;
  if (at[whole] == '.') {
    fraction = std::countr_zero(non_digits >> (whole + 1));
    if (fraction == 0 || fraction > 16 || whole + fraction > kMaxDigits) return read_plain_decimal(first, last, out);
    end = whole + 1 + fraction;
  }
  if (at + end > last) return read_plain_decimal(first, last, out);
  if (at + end != last && (at[end] == 'e' || at[end] == 'E' || at[end] == '.')) return nullptr;
  std::uint64_t w = digits_value(at, whole);
  if (fraction > 0) {
    w = w * decimal_digits::kPow10[fraction] + digits_value(at + whole + 1, fraction);
  }
  return to_double(w, fraction, negative, out) ? at + end : nullptr;
}

}  // namespace lmc::plain_decimal_detail
#endif
