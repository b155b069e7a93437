# UBSan checks a build leaves out (LMC_SANITIZE). The check preset leaves out those of memory
# access (null, alignment, object-size, vptr, pointer-overflow): they were about four fifths of
# UBSan's compile time in an engine batch, and ASan, which stays, reports a wild or null access
# itself. The checks of arithmetic (signed overflow, shifts, division by zero, array bounds, bool
# and enum values, a missing return) stay; the fuzz build (scripts/fuzz) keeps every check.
set(LMC_UBSAN_SKIP "" CACHE STRING "UBSan checks left out under LMC_SANITIZE, as -fno-sanitize=... (the check preset: those of memory access)")
separate_arguments(LMC_UBSAN_SKIP_LIST UNIX_COMMAND "${LMC_UBSAN_SKIP}")

# The same intent for MSVC (the msvc preset, Windows only): level 4 warnings, standard
# conformance (/permissive-, the real __cplusplus that the libraries test), UTF-8 sources (the
# µ and ± in messages), C++ exceptions, and /bigobj for unity batches full of Eigen's templates.
# /fp:precise is MSVC's default and, since Visual Studio 2022, never contracts a*b+c into a
# multiply-add: the counterpart of -ffp-contract=off. MSVC calls standard C functions such as
# getenv and fopen deprecated in favour of its own *_s forms, which other systems lack: that
# warning is off. AddressSanitizer only: MSVC has no UBSan.
function(lmc_msvc_compile_flags target)
  target_compile_options(${target} PRIVATE /W4 /permissive- /utf-8 /EHsc /Zc:__cplusplus /bigobj /fp:precise
                                           /external:W0)
  target_compile_definitions(${target} PRIVATE _CRT_SECURE_NO_WARNINGS)
  if(LMC_WERROR)
    target_compile_options(${target} PRIVATE /WX)
  endif()
  if(LMC_SANITIZE)
    target_compile_options(${target} PRIVATE /fsanitize=address)
  endif()
endfunction()

# Strict warnings are applied per first-party target (never globally) so Debian's headers, included
# as SYSTEM by their imported targets, stay quiet.
function(lmc_compile_flags target)
  if(MSVC)
    lmc_msvc_compile_flags(${target})
  else()
    target_compile_options(${target} PRIVATE
      -Wall -Wextra -Wpedantic
      -Wshadow                # shadowed locals hide bugs in long numeric loops
      -Wcast-qual
      -Wimplicit-fallthrough
      -Wvla                   # no variable-length arrays: stack blow-ups on large pose sets
      -Wformat=2 -Wformat-security  # names from files must never become format strings
      -Wnon-virtual-dtor
      # Never fuse a*b+c into one multiply-add: the visibility kernel's AVX-512 build (which has FMA)
      # must round as its baseline and AVX2 builds do, bit for bit (visibility_kernel.cpp;
      # tests/check_no_fused_multiply_add.sh checks the program). Nothing else here is built for FMA.
      -ffp-contract=off
    )
    if(LMC_WERROR)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
    if(LMC_GCC_FEWER_COLLECTIONS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
      # GCC collects its own garbage every time its heap grows by a third (from 128 MB), a visible
      # share of a unity batch's compile time; collecting only when it quadruples from 1 GB trades
      # some peak memory for less CPU and gives the same objects (docs/results/build-time.md).
      target_compile_options(${target} PRIVATE --param=ggc-min-expand=400 --param=ggc-min-heapsize=1048576)
    endif()
    if(LMC_SANITIZE)
      target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-sanitize-recover=all
                                               -fno-omit-frame-pointer ${LMC_UBSAN_SKIP_LIST})
      target_link_options(${target} PRIVATE -fsanitize=address,undefined)
    endif()
  endif()
  if(LMC_SANITIZE)
    # Eigen picks its allocator by whether the file is compiled with ASan: files with and without
    # (LMC_TEST_FLAGS) would then free each other's matrices with the wrong one. One choice for all.
    target_compile_definitions(${target} PRIVATE EIGEN_MALLOC_ALREADY_ALIGNED=0)
  endif()
  # No absolute paths here (they would tie every object to the checkout's folder): the assets
  # path is compiled into core/common/paths.cpp alone.
  target_compile_definitions(${target} PRIVATE LMC_VERSION="${PROJECT_VERSION}")
endfunction()

# Files per unity batch. Larger batches instantiate the shared templates fewer times (so the check
# preset that CI builds uses 32; docs/results/build-time.md); smaller ones rebuild less after an
# edit and give ninja more to run in parallel. Names in
# anonymous namespaces must be unique across a library's files.
set(LMC_UNITY_BATCH_SIZE 8 CACHE STRING "Source files per unity batch (0: one batch per target)")

# Parsing Eigen and nlohmann-json is a large part of compiling a typical file here, so they are
# precompiled (docs/results/build-time.md). Not once per target (each precompiled header costs as
# much as several ordinary files under ASan): one small holder target builds it and every
# first-party target reuses it (REUSE_FROM). Reuse is only valid while all of them compile with
# the same flags, which is why every target gets its flags from lmc_compile_flags above;
# per-target definitions such as lmc_ui's GLFW_INCLUDE_NONE are fine because the precompiled
# headers never look at them.
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

# Code that only drives the engine (the test binaries, the command-line commands and the window's
# entry point) gains little from optimisation but pays for it in compile time under the
# sanitizers (CLI11's header above all; docs/results/build-time.md). The check preset sets these
# flags to -O0 and leaves UBSan out (a sixth of their compile time, for checks of code that only
# drives the engine); the engine's libraries keep CMAKE_CXX_FLAGS_<CONFIG> and both sanitizers, so
# what the tests exercise runs as optimised and as checked as before.
set(LMC_DRIVER_FLAGS "" CACHE STRING "Extra compile flags for test binaries and program entry points (the check preset: -O0)")
separate_arguments(LMC_DRIVER_FLAG_LIST UNIX_COMMAND "${LMC_DRIVER_FLAGS}")

# lmc_append_flags(target flag...): flags after every other flag of the target (the last -O wins);
# none: nothing.
function(lmc_append_flags target)
  if(ARGN)
    target_compile_options(${target} PRIVATE ${ARGN})
  endif()
endfunction()

# lmc_driver_flags(target): LMC_DRIVER_FLAGS after every other flag.
function(lmc_driver_flags target)
  lmc_append_flags(${target} ${LMC_DRIVER_FLAG_LIST})
endfunction()

# The test binaries' own files: what they exercise is the engine, whose libraries keep the
# sanitizers, while instrumenting the tests themselves roughly doubled their compile time (and
# with the sanitizers on, their precompiled header saved nothing). The check preset sets
# -fno-sanitize=all here; a test's own memory errors are then found only where they reach the
# engine's code. Applied after LMC_DRIVER_FLAGS.
set(LMC_TEST_FLAGS "" CACHE STRING "Extra compile flags for the test binaries' own files (the check preset: no sanitizers)")
separate_arguments(LMC_TEST_FLAG_LIST UNIX_COMMAND "${LMC_TEST_FLAGS}")

# lmc_test_flags(target): LMC_TEST_FLAGS after every other flag.
function(lmc_test_flags target)
  lmc_append_flags(${target} ${LMC_TEST_FLAG_LIST})
endfunction()

# The engine's files the test suite spends its time in, at the flags that keep them quick to run.
# The check preset compiles the engine at -Og, which compiles much faster than -O1 under
# ASan/UBSan, but Eigen's small functions stay calls at -Og, so the code that does the tests'
# arithmetic (found with perf over the whole ctest run: calibration, frame preparation and the
# palm hull, the hand model, trial quality, the simulated rig) runs several times slower
# (docs/results/build-time.md).
# Those files take LMC_HOT_FLAGS (the check preset: -O1) instead. Empty: no split (Release, dev).
set(LMC_HOT_FLAGS "" CACHE STRING "Compile flags for the engine's hot files (lmc_hot_sources), after the build type's")
separate_arguments(LMC_HOT_FLAG_LIST UNIX_COMMAND "${LMC_HOT_FLAGS}")

if(LMC_PRECOMPILE_HEADERS)
  lmc_add_pch_target(lmc_pch HEADERS ${LMC_PCH_HEADERS}
                     LIBS Eigen3::Eigen nlohmann_json::nlohmann_json)
  # A precompiled header is only used with the flags it was made with: drivers get their own.
  set(LMC_DRIVER_PCH lmc_pch)
  if(LMC_DRIVER_FLAG_LIST)
    lmc_add_pch_target(lmc_driver_pch HEADERS ${LMC_PCH_HEADERS}
                       LIBS Eigen3::Eigen nlohmann_json::nlohmann_json)
    lmc_driver_flags(lmc_driver_pch)
    set(LMC_DRIVER_PCH lmc_driver_pch)
  endif()
endif()

# lmc_target_options(target [PCH holder]): the flags above plus the shared precompiled header
# (lmc_pch unless another holder, e.g. the tests' one with GoogleTest added, is named).
function(lmc_target_options target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "PCH" "")
  lmc_compile_flags(${target})
  # Batches of files compiled as one (unity build): Eigen's and the JSON library's templates are
  # then instantiated once per batch instead of once per file, which is most of the compile time
  # under ASan/UBSan. Names in anonymous namespaces must therefore be unique within a target.
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${LMC_UNITY} UNITY_BUILD_BATCH_SIZE ${LMC_UNITY_BATCH_SIZE})
  if(LMC_PRECOMPILE_HEADERS)
    if(NOT arg_PCH)
      set(arg_PCH lmc_pch)
    endif()
    target_precompile_headers(${target} REUSE_FROM ${arg_PCH})
  endif()
endfunction()

# lmc_hot_sources(target SOURCES_VAR LIBS lib... GLOBS pattern...): with LMC_HOT_FLAGS set, the
# files of ${SOURCES_VAR} that match a pattern (relative to this folder) are taken out of it and
# compiled in an object library of their own, with those flags, and their objects are added to
# `target`. LIBS: what the files include. No precompiled header: GCC takes a precompiled header's
# optimisation level over the file's own, and one made for these few files would cost more than
# it saves.
function(lmc_hot_sources target sources_var)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "LIBS;GLOBS")
  if(NOT LMC_HOT_FLAG_LIST)
    return()
  endif()
  set(hot "")
  foreach(pattern IN LISTS arg_GLOBS)
    file(GLOB matched CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${pattern})
    if(NOT matched)
      # A hot file renamed or moved would otherwise drop back to the slow flags in silence.
      message(FATAL_ERROR "lmc_hot_sources(${target}): ${pattern} matches no file in ${CMAKE_CURRENT_SOURCE_DIR}")
    endif()
    list(APPEND hot ${matched})
  endforeach()
  list(REMOVE_DUPLICATES hot)
  set(rest ${${sources_var}})
  list(REMOVE_ITEM rest ${hot})
  set(${sources_var} ${rest} PARENT_SCOPE)
  add_library(${target}_hot OBJECT ${hot})
  target_include_directories(${target}_hot PRIVATE ${CMAKE_SOURCE_DIR})
  target_link_libraries(${target}_hot PRIVATE ${arg_LIBS})
  lmc_compile_flags(${target}_hot)
  set_target_properties(${target}_hot PROPERTIES UNITY_BUILD ${LMC_UNITY} UNITY_BUILD_BATCH_SIZE ${LMC_UNITY_BATCH_SIZE})
  target_compile_options(${target}_hot PRIVATE ${LMC_HOT_FLAG_LIST})
  set(LMC_HOT_OBJECTS_${target} $<TARGET_OBJECTS:${target}_hot> PARENT_SCOPE)
endfunction()

# Executables and test binaries need the sanitizer runtime at link time even when only their
# libraries were instrumented.
function(lmc_executable_options target)
  lmc_target_options(${ARGV})
endfunction()

# lmc_driver_options(target [PCH holder]): a test binary or program entry point (see
# LMC_DRIVER_FLAGS): the usual options, the drivers' precompiled header unless another holder is
# named, then the driver flags.
function(lmc_driver_options target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "PCH" "")
  if(NOT arg_PCH)
    set(arg_PCH ${LMC_DRIVER_PCH})
  endif()
  lmc_target_options(${target} PCH ${arg_PCH})
  lmc_driver_flags(${target})
endfunction()
