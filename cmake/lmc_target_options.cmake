# Strict warnings are applied per first-party target (never globally) so Debian's headers, included
# as SYSTEM by their imported targets, stay quiet.
function(lmc_compile_flags target)
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
endfunction()

# Parsing Eigen and nlohmann-json is about 40 % of compiling a typical file here, so they are
# precompiled. Not once per target (each precompiled header costs as much as several ordinary
# files under ASan): one small holder target builds it and every first-party target reuses it
# (REUSE_FROM). Reuse is only valid while all of them compile with the same flags, which is why
# every target gets its flags from lmc_compile_flags above; per-target definitions such as lmc_ui's
# GLFW_INCLUDE_NONE are fine because the precompiled headers never look at them.
set(LMC_PCH_HEADERS
    <Eigen/Dense> <nlohmann/json.hpp>
    <algorithm> <array> <cmath> <filesystem> <functional> <memory> <string> <vector>)

# lmc_add_pch_target(name HEADERS <h>... [LIBS lib...]): a precompiled-header holder. LIBS give the
# holder the include paths (and usage definitions) the headers need.
function(lmc_add_pch_target name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "HEADERS;LIBS")
  set(anchor ${CMAKE_CURRENT_BINARY_DIR}/${name}_anchor.cpp)
  file(CONFIGURE OUTPUT ${anchor} CONTENT "// Compiled only so that ${name} has a precompiled header to share.\n")
  add_library(${name} OBJECT ${anchor})
  target_link_libraries(${name} PRIVATE ${arg_LIBS})
  lmc_compile_flags(${name})
  target_precompile_headers(${name} PRIVATE ${arg_HEADERS})
endfunction()

if(LMC_PRECOMPILE_HEADERS)
  lmc_add_pch_target(lmc_pch HEADERS ${LMC_PCH_HEADERS}
                     LIBS Eigen3::Eigen nlohmann_json::nlohmann_json)
endif()

# lmc_target_options(target [PCH holder]): the flags above plus the shared precompiled header
# (lmc_pch unless another holder, e.g. the tests' one with GoogleTest added, is named).
function(lmc_target_options target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "PCH" "")
  lmc_compile_flags(${target})
  # Batches of files compiled as one (unity build): Eigen's and the JSON library's templates are
  # then instantiated once per batch instead of once per file, which is most of the compile time
  # under ASan/UBSan. Names in anonymous namespaces must therefore be unique within a target.
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${LMC_UNITY} UNITY_BUILD_BATCH_SIZE 8)
  if(LMC_PRECOMPILE_HEADERS)
    if(NOT arg_PCH)
      set(arg_PCH lmc_pch)
    endif()
    target_precompile_headers(${target} REUSE_FROM ${arg_PCH})
  endif()
endfunction()

# Executables and test binaries need the sanitizer runtime at link time even when only their
# libraries were instrumented.
function(lmc_executable_options target)
  lmc_target_options(${ARGV})
endfunction()
