#include "core/common/paths.h"

#include <cstdlib>
#include <system_error>

#include "core/common/error.h"

#ifdef _WIN32
#include <windows.h>
#endif

#ifndef LMC_SOURCE_ASSETS_DIR
#define LMC_SOURCE_ASSETS_DIR "assets"
#endif

namespace lmc {
namespace {

// The folder holding the running program: an unpacked Windows zip keeps its assets beside it.
std::filesystem::path program_dir() {
  std::error_code ec;
#ifdef _WIN32
  std::wstring buffer(32768, L'\0');
  const DWORD n = GetModuleFileNameW(nullptr, buffer.data(), static_cast<DWORD>(buffer.size()));
  if (n == 0 || n >= buffer.size()) return {};
  buffer.resize(n);
  return std::filesystem::path(buffer).parent_path();
#else
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe.parent_path();
#endif
}

}  // namespace

std::filesystem::path assets_dir() {
  if (const char* env = std::getenv("LMC_ASSETS_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  std::error_code ec;
  // A packed build (the Windows zip) carries its assets beside the programs; a build tree uses the
  // checkout's.
  if (const auto dir = program_dir(); !dir.empty() && !std::filesystem::is_directory(LMC_SOURCE_ASSETS_DIR, ec) &&
                                      std::filesystem::is_directory(dir / "assets", ec))
    return dir / "assets";
  return LMC_SOURCE_ASSETS_DIR;
}

std::filesystem::path asset_path(const std::filesystem::path& relative) {
  auto p = assets_dir() / relative;
  if (!std::filesystem::exists(p)) {
    throw Error(ErrorLocation{p.string()}, "asset not found (set LMC_ASSETS_DIR to the assets folder)");
  }
  return p;
}

std::filesystem::path user_data_dir() {
#ifdef _WIN32
  if (const char* profile = std::getenv("USERPROFILE"); profile != nullptr && *profile != '\0')
    return std::filesystem::path(profile) / "Documents" / "lmc-workbench";
  return {};
#else
  if (const char* xdg = std::getenv("XDG_DATA_HOME"); xdg != nullptr && *xdg != '\0')
    return std::filesystem::path(xdg) / "lmc-workbench";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0')
    return std::filesystem::path(home) / ".local" / "share" / "lmc-workbench";
  return {};
#endif
}

namespace {

std::filesystem::path project_sessions_dir() {
  return std::filesystem::path(LMC_SOURCE_ASSETS_DIR).parent_path() / "sessions";
}

}  // namespace

std::filesystem::path sessions_dir() {
  if (const char* env = std::getenv("LMC_SESSIONS_DIR"); env != nullptr && *env != '\0') {
    return env;
  }
  if (std::filesystem::path data = user_data_dir(); !data.empty()) return data;
  return project_sessions_dir();
}

std::filesystem::path demo_sessions_dir() {
  if (const char* env = std::getenv("LMC_SESSIONS_DIR"); env != nullptr && *env != '\0') {
    return std::filesystem::path(env) / "demo";
  }
  std::error_code ec;
  if (const auto in_project = project_sessions_dir() / "demo"; std::filesystem::is_directory(in_project, ec))
    return in_project;
  return sessions_dir() / "demo";
}

std::filesystem::path user_cache_dir() {
  if (const char* env = std::getenv("LMC_CACHE_DIR"); env != nullptr && *env != '\0') return env;
#ifdef _WIN32
  if (const char* local = std::getenv("LOCALAPPDATA"); local != nullptr && *local != '\0')
    return std::filesystem::path(local) / "lmc-workbench" / "cache";
#endif
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg != '\0') {
    return std::filesystem::path(xdg) / "lmc-workbench";
  }
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') {
    return std::filesystem::path(home) / ".cache" / "lmc-workbench";
  }
  return {};
}

std::filesystem::path study_sample_dir() {
  std::error_code ec;
  if (const char* env = std::getenv("LMC_REFERENCE_DATA_DIR"); env != nullptr && *env != '\0') {
    const auto dir = std::filesystem::path(env) / "validation";
    return std::filesystem::is_directory(dir, ec) ? dir : std::filesystem::path();
  }
  // assets/ → the checkout → the folder holding it, where the study's data may sit.
  const auto dir = std::filesystem::path(LMC_SOURCE_ASSETS_DIR).parent_path().parent_path() / "shared" /
                   "reference-data" / "validation";
  return std::filesystem::is_directory(dir, ec) ? dir : std::filesystem::path();
}

}  // namespace lmc
