# Cross-compiling for 64-bit Windows with Debian's MinGW-w64 (package g++-mingw-w64-x86-64-posix:
# the posix thread model, which std::thread and oneTBB need). scripts/build-windows passes
# LMC_WINDOWS_DEPS_PREFIX, where it installed the cross-built libraries (by default its cache
# folder); nothing is searched on the
# build machine's own /usr (its headers and libraries are Linux ones).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(LMC_MINGW_TRIPLET x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${LMC_MINGW_TRIPLET}-gcc-posix)
set(CMAKE_CXX_COMPILER ${LMC_MINGW_TRIPLET}-g++-posix)
set(CMAKE_RC_COMPILER ${LMC_MINGW_TRIPLET}-windres)

if(NOT LMC_WINDOWS_DEPS_PREFIX)
  # scripts/build-windows's cache: $LMC_WINDOWS_DEPS_DIR, else the user's cache folder.
  if(DEFINED ENV{LMC_WINDOWS_DEPS_DIR})
    set(LMC_WINDOWS_DEPS_PREFIX $ENV{LMC_WINDOWS_DEPS_DIR}/prefix)
  elseif(DEFINED ENV{XDG_CACHE_HOME})
    set(LMC_WINDOWS_DEPS_PREFIX $ENV{XDG_CACHE_HOME}/lmc-workbench/windows-deps/prefix)
  else()
    set(LMC_WINDOWS_DEPS_PREFIX $ENV{HOME}/.cache/lmc-workbench/windows-deps/prefix)
  endif()
endif()
# Try-compiles run in their own project: hand the prefix on to them.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES LMC_WINDOWS_DEPS_PREFIX)
set(CMAKE_FIND_ROOT_PATH /usr/${LMC_MINGW_TRIPLET} ${LMC_WINDOWS_DEPS_PREFIX})
set(CMAKE_PREFIX_PATH ${LMC_WINDOWS_DEPS_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# pkg-config (ImGui, libepoxy) looks in the cross prefix only.
set(ENV{PKG_CONFIG_LIBDIR} "${LMC_WINDOWS_DEPS_PREFIX}/lib/pkgconfig:${LMC_WINDOWS_DEPS_PREFIX}/share/pkgconfig")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "")

# Programs the build runs (tests, GoogleTest discovery) run under Wine.
find_program(LMC_WINE NAMES wine64 wine PATHS /usr/lib/wine NO_CMAKE_FIND_ROOT_PATH)
if(LMC_WINE)
  set(CMAKE_CROSSCOMPILING_EMULATOR ${LMC_WINE})
endif()
