#include "core/common/uint128.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

// The two 64-bit halves that MSVC builds use for the decimal arithmetic, held to GCC's and
// Clang's built-in unsigned __int128 (where this test is compiled) operation by operation.
#if defined(__SIZEOF_INT128__)

namespace lmc::uint128_test {

__extension__ typedef unsigned __int128 Builtin;  // -Wpedantic needs the marker

PortableUint128 portable(Builtin v) {
  return (PortableUint128{static_cast<std::uint64_t>(v >> 64)} << 64) | PortableUint128{static_cast<std::uint64_t>(v)};
}

// Equal when both halves are: the high half through a shift, the low half through the conversion.
void expect_same(PortableUint128 got, Builtin want, const char* what, Builtin a, Builtin b) {
  const auto low = [](Builtin v) { return static_cast<std::uint64_t>(v); };
  EXPECT_EQ(static_cast<std::uint64_t>(got >> 64), low(want >> 64))
      << what << " of " << low(a >> 64) << ":" << low(a) << " and " << low(b >> 64) << ":" << low(b);
  EXPECT_EQ(static_cast<std::uint64_t>(got), low(want))
      << what << " of " << low(a >> 64) << ":" << low(a) << " and " << low(b >> 64) << ":" << low(b);
}

// Values at the halves' edges and the carries between them, then random ones of every width.
std::vector<Builtin> operands() {
  const Builtin one = 1;
  std::vector<Builtin> v = {0,
                            1,
                            2,
                            3,
                            10,
                            0xffffffffu,
                            one << 32,
                            (one << 64) - 1,
                            one << 64,
                            (one << 64) + 1,
                            (one << 127) - 1,
                            one << 127,
                            ~Builtin{0},
                            ~Builtin{0} - 1};
  std::mt19937_64 rng(12345);
  for (int i = 0; i < 200; ++i) {
    const Builtin wide = (Builtin{rng()} << 64) | rng();
    v.push_back(wide >> (rng() % 128));
  }
  return v;
}

TEST(PortableUint128, AddsSubtractsAndMultipliesAsTheBuiltInTypeModulo2To128) {
  const std::vector<Builtin> values = operands();
  for (const Builtin a : values) {
    for (const Builtin b : values) {
      expect_same(portable(a) + portable(b), a + b, "sum", a, b);
      expect_same(portable(a) - portable(b), a - b, "difference", a, b);
      expect_same(portable(a) * portable(b), a * b, "product", a, b);
      expect_same(portable(a) & portable(b), a & b, "and", a, b);
      expect_same(portable(a) | portable(b), a | b, "or", a, b);
    }
  }
}

TEST(PortableUint128, DividesAsTheBuiltInType) {
  const std::vector<Builtin> values = operands();
  for (const Builtin a : values) {
    for (const Builtin b : values) {
      if (b != 0) expect_same(portable(a) / portable(b), a / b, "quotient", a, b);
    }
  }
  // The last entry of the decimal reader's table: 2^(63+e) / 5^f for f = 19, e = 45.
  EXPECT_EQ(static_cast<std::uint64_t>((PortableUint128{1} << 108) / 19073486328125u),
            static_cast<std::uint64_t>((Builtin{1} << 108) / 19073486328125u));
}

TEST(PortableUint128, ShiftsByEveryWidthAsTheBuiltInType) {
  for (const Builtin a : operands()) {
    for (int shift = 0; shift < 128; ++shift) {
      expect_same(portable(a) << shift, a << shift, "left shift", a, static_cast<Builtin>(shift));
      expect_same(portable(a) >> shift, a >> shift, "right shift", a, static_cast<Builtin>(shift));
    }
  }
}

TEST(PortableUint128, ComparesAndIncrementsAsTheBuiltInType) {
  const std::vector<Builtin> values = operands();
  for (const Builtin a : values) {
    for (const Builtin b : values) {
      EXPECT_EQ(portable(a) < portable(b), a < b);
      EXPECT_EQ(portable(a) == portable(b), a == b);
      EXPECT_EQ(portable(a) > portable(b), a > b);
    }
    PortableUint128 next = portable(a);
    ++next;
    expect_same(next, a + 1, "increment", a, 1);
  }
  // Mixed with 64-bit and int operands, as the callers write it.
  EXPECT_EQ(static_cast<std::uint64_t>(2 * PortableUint128{21}), 42u);
  EXPECT_TRUE((PortableUint128{5} & 1) != 0);
  EXPECT_EQ(static_cast<std::uint64_t>(PortableUint128{40} + 2u), 42u);
}

// The constant tables of the decimal code are computed at compile time.
static_assert(static_cast<std::uint64_t>((PortableUint128{1} << 70) / 1024u >> 60) == 1);
static_assert(PortableUint128{3} * PortableUint128{1} < PortableUint128{4});

}  // namespace lmc::uint128_test

#endif
