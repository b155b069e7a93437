#pragma once
// The shortest form of a double that reads back as the same double, character for character what
// std::to_chars(first, last, v) writes (fixed or scientific, whichever is shorter, fixed on a tie;
// among the shortest, the one nearest to v), at a fraction of its cost for the values the study's
// files hold. The fused output of a subject is millions of such numbers, so writing them is a large
// part of processing (docs/results/processing.md).

namespace lmc {

// Room write_shortest may use: a sign, 17 digits, a point, and "e-308" with margin.
inline constexpr int kShortestDoubleMaxChars = 32;

// Writes v at `first` (at least kShortestDoubleMaxChars bytes) and returns the end. It may also
// write past that end within the room (fixed-size copies). NaN and the infinities are written as
// std::to_chars writes them ("nan", "-nan", "inf", "-inf").
char* write_shortest(char* first, double v);

}  // namespace lmc
