#pragma once
// Setting and removing an environment variable in a test, on both systems (POSIX setenv and
// unsetenv; Windows' _putenv_s, where an empty value removes the variable).
#include <cstdlib>

namespace lmc::test {

inline void set_env(const char* name, const char* value) {
#ifdef _WIN32
  _putenv_s(name, value);
#else
  setenv(name, value, 1);
#endif
}

inline void unset_env(const char* name) {
#ifdef _WIN32
  _putenv_s(name, "");
#else
  unsetenv(name);
#endif
}

}  // namespace lmc::test
