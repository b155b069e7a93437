// The backend's tests load the test double built beside them (LMC_FAKE_LEAPC_PATH, set by CMake),
// as a lab names its library with LMC_LEAPC_LIBRARY: set before any test runs.
#include <cstdlib>

#include "tests/support/env_var.h"

namespace {
const bool kLeapcLibraryNamed = [] {
  lmc::test::set_env("LMC_LEAPC_LIBRARY", LMC_FAKE_LEAPC_PATH);
  return true;
}();
}  // namespace
