#include "core/common/glob_match.h"

#include <cstddef>

namespace lmc {
namespace {

// Whether the set starting at pattern[p] (just after '[') holds c; *end gets the index after ']'.
// A set without its ']' is no set: the '[' is then an ordinary character (*end stays 0).
bool set_holds(std::string_view pattern, std::size_t p, char c, std::size_t* end) {
  *end = 0;
  bool negate = false;
  if (p < pattern.size() && (pattern[p] == '!' || pattern[p] == '^')) {
    negate = true;
    ++p;
  }
  bool found = false;
  bool first = true;
  while (p < pattern.size() && (first || pattern[p] != ']')) {
    first = false;
    char lo = pattern[p];
    if (lo == '\\' && p + 1 < pattern.size()) lo = pattern[++p];
    char hi = lo;
    if (p + 2 < pattern.size() && pattern[p + 1] == '-' && pattern[p + 2] != ']') {
      hi = pattern[p + 2];
      if (hi == '\\' && p + 3 < pattern.size()) hi = pattern[++p + 2];
      p += 2;
    }
    if (static_cast<unsigned char>(lo) <= static_cast<unsigned char>(c) &&
        static_cast<unsigned char>(c) <= static_cast<unsigned char>(hi))
      found = true;
    ++p;
  }
  if (p >= pattern.size()) return false;
  *end = p + 1;
  return found != negate;
}

}  // namespace

bool glob_matches(std::string_view pattern, std::string_view name) {
  std::size_t p = 0, n = 0;
  // Where the last '*' was and how much of the name it has taken: on a mismatch it takes one more.
  std::size_t star = std::string_view::npos, star_n = 0;
  while (n < name.size()) {
    if (p < pattern.size()) {
      const char pc = pattern[p];
      if (pc == '*') {
        star = p++;
        star_n = n;
        continue;
      }
      if (pc == '?') {
        ++p;
        ++n;
        continue;
      }
      if (pc == '[') {
        std::size_t end = 0;
        const bool holds = set_holds(pattern, p + 1, name[n], &end);
        if (end != 0) {
          if (holds) {
            p = end;
            ++n;
            continue;
          }
        } else if (name[n] == '[') {
          ++p;
          ++n;
          continue;
        }
      } else {
        char literal = pc;
        std::size_t step = 1;
        if (pc == '\\' && p + 1 < pattern.size()) {
          literal = pattern[p + 1];
          step = 2;
        }
        if (literal == name[n]) {
          p += step;
          ++n;
          continue;
        }
      }
    }
    if (star == std::string_view::npos) return false;
    p = star + 1;
    n = ++star_n;
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

}  // namespace lmc
