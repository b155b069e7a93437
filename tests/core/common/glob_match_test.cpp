// glob_matches keeps fnmatch's rules (flags 0) on every system; on Linux each case is also checked
// against the C library's fnmatch itself.
#include "core/common/glob_match.h"

#include <gtest/gtest.h>

#ifndef _WIN32
#include <fnmatch.h>
#endif

#include <string>

namespace {

struct Case {
  const char* pattern;
  const char* name;
  bool matches;
};

const Case kCases[] = {
    {"Naiv_*", "Naiv_Static101", true},
    {"Naiv_*", "naiv_Static101", false},
    {"*101", "Naiv_Static101", true},
    {"*", "", true},
    {"", "", true},
    {"", "a", false},
    {"?", "a", true},
    {"?", "", false},
    {"a?c", "abc", true},
    {"*Static1[0-9]1", "Naiv_Static121", true},
    {"*[!0-9]", "x1", false},
    {"*[^0-9]", "1x", true},
    {"[abc]", "b", true},
    {"[abc]", "d", false},
    {"[]a]", "]", true},
    {"[!]a]", "b", true},
    {"\\*", "*", true},
    {"\\*", "a", false},
    {"a[", "a[", true},
    {"a*b*c", "aXbYbZc", true},
    {"a*b*c", "aXbYbZ", false},
    {"*/*", "dir/file", true},
    {"**x", "abx", true},
    {"[a-c-e]", "-", true},
    {"Trial 1", "Trial 1", true},
    {"Trial ?", "Trial 10", false},
};

}  // namespace

TEST(GlobMatch, FollowsFnmatchRules) {
  for (const Case& c : kCases) {
    EXPECT_EQ(lmc::glob_matches(c.pattern, c.name), c.matches) << c.pattern << " vs " << c.name;
#ifndef _WIN32
    EXPECT_EQ(fnmatch(c.pattern, c.name, 0) == 0, c.matches) << "fnmatch: " << c.pattern << " vs " << c.name;
#endif
  }
}
