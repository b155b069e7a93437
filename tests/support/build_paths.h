#pragma once
// Where the tests find the source tree, the assets, the reference data and the built programs.
// The absolute paths are compiled into build_paths.cpp alone: as -D flags on every test file they
// would tie each object to the checkout's folder.
#include <filesystem>

namespace lmc::test {

std::filesystem::path source_dir();             // the repository root
std::filesystem::path test_assets_dir();        // <source>/assets
std::filesystem::path default_reference_dir();  // LMC_REFERENCE_DATA_DIR (CMakeLists.txt)
std::filesystem::path cli_path();               // the built `lmc`
std::filesystem::path workbench_path();         // the built `lmc-workbench`

}  // namespace lmc::test
