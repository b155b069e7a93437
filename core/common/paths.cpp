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

std::filesystem::path sessions_dir() {
  if (const char* env = std::getenv("LMC_SESSIONS_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  const std::filesystem::path in_project = std::filesystem::path(LMC_SOURCE_ASSETS_DIR).parent_path() / "sessions";
  std::error_code ec;
  if (std::filesystem::is_directory(in_project, ec)) return in_project;
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home != nullptr && *home != '\0' ? home : ".") / "lmc-sessions";
}

}  // namespace lmc
