#include "devices/leapc/leapc_library.h"

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <utility>

#if defined(_WIN32)
#include <windows.h>
#else
#include <dlfcn.h>
#endif

namespace lmc::devices {
namespace {

std::mutex& path_mutex() {
  static std::mutex m;
  return m;
}
std::string& explicit_path() {
  static std::string path;
  return path;
}

std::string env(const char* name) {
  const char* v = std::getenv(name);
  return v == nullptr ? std::string() : std::string(v);
}

// An open library: its handle and a way to look names up in it. Never closed: LeapC starts threads
// of its own, and the process keeps the library it found for its lifetime.
struct Opened {
  void* handle = nullptr;
  std::string error;
};

#if defined(_WIN32)
Opened open_library(const std::string& path) {
  Opened o;
  const std::wstring wide = std::filesystem::path(path).wstring();
  o.handle = reinterpret_cast<void*>(LoadLibraryW(wide.c_str()));
  if (o.handle == nullptr) o.error = "LoadLibrary failed (error " + std::to_string(GetLastError()) + ")";
  return o;
}
void* symbol(void* handle, const char* name) {
  return reinterpret_cast<void*>(GetProcAddress(static_cast<HMODULE>(handle), name));
}
const char* const kBareNames[] = {"LeapC.dll"};
#else
Opened open_library(const std::string& path) {
  Opened o;
  o.handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (o.handle == nullptr) {
    const char* e = dlerror();
    o.error = e != nullptr ? e : "dlopen failed";
  }
  return o;
}
void* symbol(void* handle, const char* name) {
  return dlsym(handle, name);
}
const char* const kBareNames[] = {"libLeapC.so.6", "libLeapC.so.5", "libLeapC.so"};
#endif

template <typename Fn>
bool bind(void* handle, const char* name, Fn& out, std::vector<std::string>& missing) {
  out = reinterpret_cast<Fn>(symbol(handle, name));
  if (out == nullptr) missing.emplace_back(name);
  return out != nullptr;
}

// The required functions; the names of those missing. The optional ones are bound if present.
std::vector<std::string> bind_all(void* h, LeapcApi& a) {
  std::vector<std::string> missing;
  bind(h, "LeapCreateConnection", a.create_connection, missing);
  bind(h, "LeapOpenConnection", a.open_connection, missing);
  bind(h, "LeapPollConnection", a.poll_connection, missing);
  bind(h, "LeapCloseConnection", a.close_connection, missing);
  bind(h, "LeapDestroyConnection", a.destroy_connection, missing);
  bind(h, "LeapSetPolicyFlagsEx", a.set_policy_flags_ex, missing);
  bind(h, "LeapSetTrackingModeEx", a.set_tracking_mode_ex, missing);
  bind(h, "LeapOpenDevice", a.open_device, missing);
  bind(h, "LeapCloseDevice", a.close_device, missing);
  bind(h, "LeapGetDeviceInfo", a.get_device_info, missing);
  bind(h, "LeapSubscribeEvents", a.subscribe_events, missing);
  bind(h, "LeapUnsubscribeEvents", a.unsubscribe_events, missing);
  bind(h, "LeapGetNow", a.get_now, missing);
  std::vector<std::string> optional;
  bind(h, "LeapGetTrackingModeEx", a.get_tracking_mode_ex, optional);
  bind(h, "LeapGetConnectionInfo", a.get_connection_info, optional);
  bind(h, "LeapGetVersion", a.get_version, optional);
  return missing;
}

// The library's own version: asked of a connection that is created but never opened (the client
// library's version needs no service).
std::optional<leapc::Version> client_version(const LeapcApi& a) {
  if (a.get_version == nullptr) return std::nullopt;
  leapc::ConnectionConfig config{};
  config.size = sizeof config;
  leapc::Connection c = nullptr;
  if (a.create_connection(&config, &c) != leapc::kSuccess || c == nullptr) return std::nullopt;
  leapc::Version v{};
  const bool ok = a.get_version(c, leapc::kVersionClientLibrary, &v) == leapc::kSuccess;
  a.destroy_connection(c);
  if (!ok) return std::nullopt;
  return v;
}

// Tries one place: the library, or the reason it was not taken (in `outcome`).
std::shared_ptr<LeapcLibrary> try_place(const LeapcPlace& place, bool is_file, std::string& outcome) {
  if (is_file) {
    std::error_code ec;
    if (!std::filesystem::exists(place.path, ec)) {
      outcome = "not there";
      return nullptr;
    }
  }
  const Opened o = open_library(place.path);
  if (o.handle == nullptr) {
    outcome = is_file ? "cannot be loaded: " + o.error : "not found by the dynamic loader";
    return nullptr;
  }
  auto lib = std::make_shared<LeapcLibrary>();
  const std::vector<std::string> missing = bind_all(o.handle, lib->api);
  if (!missing.empty()) {
    outcome = "refused: it lacks " + missing.front() +
              (missing.size() > 1 ? " and " + std::to_string(missing.size() - 1) + " more" : std::string()) +
              " (multi-device tracking needs LeapC 5.4 or newer)";
    return nullptr;
  }
  lib->version = client_version(lib->api);
  if (lib->version && !leapc_major_supported(lib->version->major)) {
    outcome = "refused: it is LeapC " + leapc_version_text(*lib->version) +
              "; this program was written for LeapC 5 (Gemini), 6 and 7 (Hyperion), and another major version "
              "may lay out the structures it reads differently";
    return nullptr;
  }
  lib->path = place.path;
  lib->what = place.what;
  outcome = "loaded";
  return lib;
}

}  // namespace

std::string leapc_version_text(const leapc::Version& v) {
  return std::to_string(v.major) + "." + std::to_string(v.minor) + "." + std::to_string(v.patch);
}

std::string leapc_library_text(const LeapcLibrary& library) {
  const std::string version = library.version ? leapc_version_text(*library.version) : "(version not reported)";
  return "LeapC " + version + " from " + library.path + " (" + library.what + ")";
}

// 7: Hyperion's later client libraries; the structs and enum values the backend reads are those of
// 5.x (devices/leapc/README.md says how that was checked).
bool leapc_major_supported(int major) {
  return major >= 5 && major <= 7;
}

void set_leapc_library_path(const std::string& path) {
  std::lock_guard lock(path_mutex());
  explicit_path() = path;
}

std::string leapc_library_path() {
  std::lock_guard lock(path_mutex());
  return explicit_path();
}

std::vector<LeapcPlace> leapc_known_places() {
  const std::string root = env("LMC_LEAPC_SEARCH_ROOT");
  std::vector<LeapcPlace> places;
#if defined(_WIN32)
  // Where Windows keeps programs (%ProgramFiles%, on C: unless moved); under a search root (the
  // tests') the root stands in for the drive.
  std::string program_files = env("ProgramFiles");
  if (program_files.empty()) program_files = "C:/Program Files";
  if (!root.empty()) program_files = root + "/Program Files";
  auto add = [&](const std::string& path, const std::string& what) { places.push_back({program_files + path, what}); };
  add("/Ultraleap/LeapSDK/lib/x64/LeapC.dll", "Ultraleap SDK (Windows installer)");
  add("/Ultraleap/TrackingService/bin/LeapC.dll", "Ultraleap tracking service folder (Windows)");
#else
  auto add = [&](const std::string& path, const std::string& what) { places.push_back({root + path, what}); };
  // Hyperion (6) first: where both are installed, the current service is the one running.
  add("/usr/lib/x86_64-linux-gnu/libLeapC.so.6", "Hyperion 6 package");
  add("/usr/lib/ultraleap-hand-tracking-service/libLeapC.so.6", "Hyperion 6 package (service folder)");
  add("/usr/lib/x86_64-linux-gnu/libLeapC.so.5", "Gemini 5.17 package");
  add("/usr/lib/ultraleap-hand-tracking-service/libLeapC.so.5", "Gemini 5.6 package (service folder)");
  add("/usr/lib/ultraleap-hand-tracking-service/libLeapC.so", "Gemini 5.6 package (service folder)");
  add("/usr/share/doc/ultraleap-hand-tracking-service/lib/libLeapC.so.5", "Gemini 5.6 package (SDK folder)");
  add("/usr/share/doc/ultraleap-hand-tracking-service/lib/libLeapC.so", "Gemini 5.6 package (SDK folder)");
  add("/opt/ultraleap/LeapSDK/lib/libLeapC.so.6", "Ultraleap SDK tarball");
  add("/opt/ultraleap/LeapSDK/lib/libLeapC.so.5", "Ultraleap SDK tarball");
  add("/opt/ultraleap/LeapSDK/lib/libLeapC.so", "Ultraleap SDK tarball");
#endif
  return places;
}

LeapcSearchResult find_leapc() {
  LeapcSearchResult result;
  auto attempt = [&](const LeapcPlace& place, bool is_file) {
    std::string outcome;
    auto lib = try_place(place, is_file, outcome);
    result.tried.push_back({place.path, place.what, outcome});
    if (lib) {
      lib->tried = result.tried;
      result.library = std::move(lib);
    }
    return result.library != nullptr;
  };
  // Named by the user: the only place tried, so another library is never loaded in its stead.
  if (const std::string named = leapc_library_path(); !named.empty()) {
    attempt({named, "--leapc-library"}, true);
    return result;
  }
  if (const std::string named = env("LMC_LEAPC_LIBRARY"); !named.empty()) {
    attempt({named, "LMC_LEAPC_LIBRARY"}, true);
    return result;
  }
  for (const LeapcPlace& place : leapc_known_places())
    if (attempt(place, true)) return result;
  if (env("LMC_LEAPC_SEARCH_ROOT").empty())
    for (const char* name : kBareNames)
      if (attempt({name, "the dynamic loader's search path"}, false)) return result;
  return result;
}

std::string LeapcSearchResult::failure_text() const {
  if (library) return {};
  std::string text = "no usable LeapC library (Ultraleap's tracking software) was found. Places tried, in order:\n";
  for (const auto& t : tried) text += "  " + t.path + " [" + t.what + "]: " + t.outcome + "\n";
  text +=
      "Install Ultraleap's hand-tracking software (docs/guide/connect.md), or name the library with "
      "--leapc-library PATH or LMC_LEAPC_LIBRARY=PATH";
  return text;
}

}  // namespace lmc::devices
