// The backend's tests load the test double built beside them (LMC_FAKE_LEAPC_PATH, set by CMake),
// as a lab names its library with LMC_LEAPC_LIBRARY: set before any test runs.
#include <cstdlib>

namespace {
const bool kLeapcLibraryNamed = [] {
  setenv("LMC_LEAPC_LIBRARY", LMC_FAKE_LEAPC_PATH, 1);
  return true;
}();
}  // namespace
