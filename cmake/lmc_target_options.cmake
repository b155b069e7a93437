# Strict warnings are applied per first-party target (never globally) so Debian's headers, included
# as SYSTEM by their imported targets, stay quiet.
function(lmc_target_options target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic
    -Wshadow                # shadowed locals hide bugs in long numeric loops
    -Wcast-qual
    -Wimplicit-fallthrough
    -Wvla                   # no variable-length arrays: stack blow-ups on large pose sets
    -Wformat=2 -Wformat-security  # names from files must never become format strings
    -Wnon-virtual-dtor
  )
  if(LMC_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  if(LMC_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-sanitize-recover=all
                                             -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
  # No absolute paths here (they would tie every object to the checkout's folder): the assets
  # path is compiled into core/common/paths.cpp alone.
  target_compile_definitions(${target} PRIVATE LMC_VERSION="${PROJECT_VERSION}")
  # Parsing Eigen and nlohmann-json is about 40 % of compiling a typical file here: precompile them
  # once per target (CI builds from scratch on two cores and must stay well under 15 minutes).
  if(LMC_PRECOMPILE_HEADERS)
    target_precompile_headers(${target} PRIVATE
      <Eigen/Dense> <nlohmann/json.hpp>
      <algorithm> <array> <cmath> <filesystem> <functional> <memory> <string> <vector>)
  endif()
endfunction()

# Executables and test binaries need the sanitizer runtime at link time even when only their
# libraries were instrumented.
function(lmc_executable_options target)
  lmc_target_options(${target})
endfunction()
