#include "tests/support/build_paths.h"

namespace lmc::test {

std::filesystem::path source_dir() {
  return LMC_SOURCE_DIR;
}
std::filesystem::path test_assets_dir() {
  return LMC_TEST_ASSETS_DIR;
}
std::filesystem::path default_reference_dir() {
  return LMC_REFERENCE_DATA_DIR;
}
std::filesystem::path cli_path() {
  return LMC_CLI_PATH;
}
std::filesystem::path workbench_path() {
  return LMC_WORKBENCH_PATH;
}

}  // namespace lmc::test
