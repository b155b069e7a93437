#pragma once
// Shell-style wildcards for names (`--trials "Naiv_*"`): `*` any run of characters, `?` one,
// `[abc]`, `[a-z]` and `[!a-z]` (or `[^a-z]`) one of a set, `\` takes the next character as it
// is. The rules of POSIX fnmatch without flags, on every system (Windows has no fnmatch).
#include <string_view>

namespace lmc {

bool glob_matches(std::string_view pattern, std::string_view name);

}  // namespace lmc
