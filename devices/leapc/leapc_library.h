#pragma once
// Finding and loading Ultraleap's LeapC library at run time, so one binary works before and after
// the tracking software is installed (and a running workbench finds it on Reconnect: a failed
// search is never cached). The places are tried in this order (devices/leapc/README.md):
//   1. the library named with --leapc-library (set_leapc_library_path), else
//   2. the one in LMC_LEAPC_LIBRARY; either of these, when given, is the only one tried;
//   3. where Ultraleap's packages put it (leapc_known_places(): Hyperion 6 before Gemini 5, each
//      package's folders before the SDK tarball's), then the dynamic loader's own search.
// LMC_LEAPC_SEARCH_ROOT, when set, is put before every known place and the loader's own search
// is skipped, so tests can install the test double at each layout in a scratch folder.
// A library is taken when it has every function the backend calls and its major version is one
// the backend was written for (5, Gemini; 6, Hyperion); otherwise the next place is tried and the
// reason kept.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "devices/leapc/leapc_abi.h"

namespace lmc::devices {

// Every LeapC function the backend calls. The optional ones may be null (older services).
struct LeapcApi {
  leapc::CreateConnectionFn create_connection = nullptr;
  leapc::OpenConnectionFn open_connection = nullptr;
  leapc::PollConnectionFn poll_connection = nullptr;
  leapc::CloseConnectionFn close_connection = nullptr;
  leapc::DestroyConnectionFn destroy_connection = nullptr;
  leapc::SetPolicyFlagsExFn set_policy_flags_ex = nullptr;
  leapc::SetTrackingModeExFn set_tracking_mode_ex = nullptr;
  leapc::OpenDeviceFn open_device = nullptr;
  leapc::CloseDeviceFn close_device = nullptr;
  leapc::GetDeviceInfoFn get_device_info = nullptr;
  leapc::SubscribeEventsFn subscribe_events = nullptr;
  leapc::UnsubscribeEventsFn unsubscribe_events = nullptr;
  leapc::GetNowFn get_now = nullptr;
  // Optional.
  leapc::GetTrackingModeExFn get_tracking_mode_ex = nullptr;
  leapc::GetConnectionInfoFn get_connection_info = nullptr;
  leapc::GetVersionFn get_version = nullptr;
};

struct LeapcPlaceTried {
  std::string path;     // a file, or a bare name handed to the dynamic loader
  std::string what;     // "--leapc-library", "Gemini 5.6 package (service folder)", …
  std::string outcome;  // why it was not taken ("not there", "refused: LeapC 7.0.0 …"), or "loaded"
};

struct LeapcLibrary {
  LeapcApi api;
  std::string path;                       // as opened
  std::string what;                       // which of the places it is
  std::optional<leapc::Version> version;  // the library's own (LeapGetVersion), when it has the call
  std::vector<LeapcPlaceTried> tried;     // every place tried before it, and it
};

// "LeapC 5.6.1 from /usr/lib/… (Gemini 5.6 package (service folder))".
std::string leapc_library_text(const LeapcLibrary& library);
std::string leapc_version_text(const leapc::Version& v);

// The outcome of one search: the library, or every place tried and why each failed.
struct LeapcSearchResult {
  std::shared_ptr<const LeapcLibrary> library;
  std::vector<LeapcPlaceTried> tried;
  // Several lines: what was tried and what to do (empty when found).
  std::string failure_text() const;
};

// The process-wide --leapc-library (empty: search).
void set_leapc_library_path(const std::string& path);
std::string leapc_library_path();

// The places of step 3, in order, with LMC_LEAPC_SEARCH_ROOT applied.
struct LeapcPlace {
  std::string path;
  std::string what;
};
std::vector<LeapcPlace> leapc_known_places();

// Searches now (nothing is cached: a library installed since the last search is found).
LeapcSearchResult find_leapc();

// The major versions the backend was written for.
bool leapc_major_supported(int major);

}  // namespace lmc::devices
