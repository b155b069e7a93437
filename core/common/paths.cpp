#include "core/common/paths.h"

#include <cstdlib>

#include "core/common/error.h"

#ifndef LMC_SOURCE_ASSETS_DIR
#define LMC_SOURCE_ASSETS_DIR "assets"
#endif

namespace lmc {

std::filesystem::path assets_dir() {
  if (const char* env = std::getenv("LMC_ASSETS_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  return LMC_SOURCE_ASSETS_DIR;
}

std::filesystem::path asset_path(const std::filesystem::path& relative) {
  auto p = assets_dir() / relative;
  if (!std::filesystem::exists(p)) {
    throw Error(ErrorLocation{p.string()}, "asset not found (set LMC_ASSETS_DIR to the assets folder)");
  }
  return p;
}

}  // namespace lmc
