#pragma once
// An unsigned 128-bit integer for the exact arithmetic of reading and writing decimal numbers
// (plain_decimal.h, shortest_double.cpp, number_format.cpp). GCC and Clang have one built in,
// `unsigned __int128`, a GNU extension that MSVC lacks; there the same operations run on two
// 64-bit halves (PortableUint128). Both wrap modulo 2^128 and give the same bits; only the speed
// differs. LMC_PORTABLE_UINT128 chooses the halves on GCC and Clang too, to check them there.
#include <compare>
#include <cstdint>

namespace lmc {

class PortableUint128 {
 public:
  constexpr PortableUint128() = default;
  constexpr PortableUint128(std::uint64_t low) : low_(low) {}  // implicit, as the built-in type converts

  constexpr explicit operator std::uint64_t() const { return low_; }

  friend constexpr auto operator<=>(const PortableUint128&, const PortableUint128&) = default;

  friend constexpr PortableUint128 operator+(PortableUint128 a, PortableUint128 b) {
    const std::uint64_t low = a.low_ + b.low_;
    return from_halves(a.high_ + b.high_ + (low < a.low_ ? 1 : 0), low);
  }
  friend constexpr PortableUint128 operator-(PortableUint128 a, PortableUint128 b) {
    return from_halves(a.high_ - b.high_ - (a.low_ < b.low_ ? 1 : 0), a.low_ - b.low_);
  }
  friend constexpr PortableUint128 operator*(PortableUint128 a, PortableUint128 b) {
    PortableUint128 product = multiply(a.low_, b.low_);
    product.high_ += a.low_ * b.high_ + a.high_ * b.low_;  // the parts at or above 2^64; the rest wraps
    return product;
  }
  // n / d for d ≠ 0, one quotient bit at a time (only tables computed at compile time divide).
  friend constexpr PortableUint128 operator/(PortableUint128 n, PortableUint128 d) {
    PortableUint128 quotient;
    PortableUint128 rest;
    for (int bit = 127; bit >= 0; --bit) {
      rest = (rest << 1) | ((n >> bit) & PortableUint128{1});
      if (rest >= d) {
        rest = rest - d;
        quotient = quotient | (PortableUint128{1} << bit);
      }
    }
    return quotient;
  }
  friend constexpr PortableUint128 operator&(PortableUint128 a, PortableUint128 b) {
    return from_halves(a.high_ & b.high_, a.low_ & b.low_);
  }
  friend constexpr PortableUint128 operator|(PortableUint128 a, PortableUint128 b) {
    return from_halves(a.high_ | b.high_, a.low_ | b.low_);
  }
  // Shifts by 0 to 127 bits, as for the built-in type.
  friend constexpr PortableUint128 operator<<(PortableUint128 a, int shift) {
    if (shift == 0) return a;
    if (shift >= 64) return from_halves(a.low_ << (shift - 64), 0);
    return from_halves((a.high_ << shift) | (a.low_ >> (64 - shift)), a.low_ << shift);
  }
  friend constexpr PortableUint128 operator>>(PortableUint128 a, int shift) {
    if (shift == 0) return a;
    if (shift >= 64) return from_halves(0, a.high_ >> (shift - 64));
    return from_halves(a.high_ >> shift, (a.low_ >> shift) | (a.high_ << (64 - shift)));
  }
  constexpr PortableUint128& operator++() {
    *this = *this + PortableUint128{1};
    return *this;
  }

 private:
  static constexpr PortableUint128 from_halves(std::uint64_t high, std::uint64_t low) {
    PortableUint128 v;
    v.high_ = high;
    v.low_ = low;
    return v;
  }
  // a · b in full, from four 32-bit by 32-bit products.
  static constexpr PortableUint128 multiply(std::uint64_t a, std::uint64_t b) {
    constexpr std::uint64_t kLow32 = 0xffffffffu;
    const std::uint64_t low_low = (a & kLow32) * (b & kLow32);
    const std::uint64_t low_high = (a & kLow32) * (b >> 32);
    const std::uint64_t high_low = (a >> 32) * (b & kLow32);
    const std::uint64_t high_high = (a >> 32) * (b >> 32);
    const std::uint64_t middle = (low_low >> 32) + (low_high & kLow32) + (high_low & kLow32);
    return from_halves(high_high + (low_high >> 32) + (high_low >> 32) + (middle >> 32),
                       (middle << 32) | (low_low & kLow32));
  }

  // High half first: the defaulted comparison compares members in this order.
  std::uint64_t high_ = 0;
  std::uint64_t low_ = 0;
};

#if defined(__SIZEOF_INT128__) && !defined(LMC_PORTABLE_UINT128)
__extension__ typedef unsigned __int128 Uint128;  // -Wpedantic needs the marker
#else
using Uint128 = PortableUint128;
#endif

}  // namespace lmc
