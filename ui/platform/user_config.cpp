#include "ui/platform/user_config.h"

#include <cstdlib>
#include <system_error>

namespace lmc::ui {

std::filesystem::path user_config_dir() {
  std::filesystem::path base;
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) {
    base = xdg;
  } else if (const char* home = std::getenv("HOME"); home && *home) {
    base = std::filesystem::path(home) / ".config";
  } else {
    return {};
  }
  std::error_code ec;
  std::filesystem::create_directories(base / "lmc-workbench", ec);
  if (ec) return {};
  return base / "lmc-workbench";
}

}  // namespace lmc::ui
