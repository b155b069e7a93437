// The libFuzzer program, one for every target: `lmc_fuzz --target=NAME [libFuzzer flags] CORPUS…`.
// libFuzzer passes flags that start with "--" through untouched (also to the workers of -fork and
// -jobs), so the target's name travels with every process it starts. `lmc_fuzz --list` prints the
// names. Built only with clang (LMC_FUZZ, scripts/fuzz).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "tests/fuzz/fuzz_targets.h"

namespace {
const lmc::fuzz::Target* g_target = nullptr;
}

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  constexpr std::string_view kFlag = "--target=";
  for (int i = 1; i < *argc; ++i) {
    const std::string_view arg = (*argv)[i];
    if (arg == "--list") {
      for (const auto& t : lmc::fuzz::targets()) std::printf("%s\t%s\n", t.name, t.what);
      std::exit(0);
    }
    if (arg.substr(0, kFlag.size()) == kFlag) g_target = lmc::fuzz::find_target(arg.substr(kFlag.size()));
  }
  if (!g_target) {
    std::fprintf(stderr, "lmc_fuzz: give --target=NAME (one of the names `lmc_fuzz --list` prints)\n");
    std::exit(2);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  (void)lmc::fuzz::run_one(*g_target, {reinterpret_cast<const char*>(data), size});
  return 0;
}
