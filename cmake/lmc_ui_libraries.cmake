# Dear ImGui (with its GLFW and OpenGL 3 back ends), libepoxy and stb's PNG writer, which lmc_ui
# links as PkgConfig::IMGUI and PkgConfig::EPOXY (ui/CMakeLists.txt).
#
# Debian (the Linux build) and scripts/build-windows's cache (the MinGW build) describe them with
# pkg-config files: imgui.pc brings stb's, whose library holds stb's implementations, and the
# sources include the back ends as <backends/imgui_impl_*.h>.
if(NOT VCPKG_TOOLCHAIN)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
  pkg_check_modules(EPOXY REQUIRED IMPORTED_TARGET epoxy)
  return()
endif()

# vcpkg (the msvc preset, vcpkg.json) has no pkg-config on Windows to read them with, and lays them
# out differently: ImGui is a CMake package (imgui::imgui) with the back ends' headers beside
# imgui.h; libepoxy is a DLL with an import library and headers only; stb is headers only, its
# implementations compiled by whoever uses them. The same two targets are made from those.
find_package(imgui CONFIG REQUIRED)
find_package(Stb REQUIRED)
find_path(LMC_EPOXY_INCLUDE_DIR epoxy/gl.h REQUIRED)
find_library(LMC_EPOXY_LIBRARY NAMES epoxy REQUIRED)

# <backends/imgui_impl_glfw.h> and <backends/imgui_impl_opengl3.h>, each forwarding to vcpkg's.
set(LMC_IMGUI_BACKENDS_DIR ${CMAKE_BINARY_DIR}/vcpkg-imgui-backends)
foreach(backend IN ITEMS imgui_impl_glfw imgui_impl_opengl3)
  file(CONFIGURE OUTPUT ${LMC_IMGUI_BACKENDS_DIR}/backends/${backend}.h
       CONTENT "#pragma once\n// Where Debian puts ImGui's back end; vcpkg puts it beside imgui.h.\n#include <${backend}.h>\n")
endforeach()

# The one stb implementation the workbench uses (its captures' PNG files).
set(LMC_STB_SOURCE ${CMAKE_BINARY_DIR}/vcpkg-stb/stb_image_write.cpp)
file(CONFIGURE OUTPUT ${LMC_STB_SOURCE}
     CONTENT "#define STB_IMAGE_WRITE_IMPLEMENTATION\n#include <stb_image_write.h>\n")
add_library(lmc_stb_image_write STATIC ${LMC_STB_SOURCE})
target_include_directories(lmc_stb_image_write SYSTEM PUBLIC ${Stb_INCLUDE_DIR})
target_compile_definitions(lmc_stb_image_write PRIVATE _CRT_SECURE_NO_WARNINGS)

add_library(PkgConfig::IMGUI INTERFACE IMPORTED)
target_include_directories(PkgConfig::IMGUI INTERFACE ${LMC_IMGUI_BACKENDS_DIR})
target_link_libraries(PkgConfig::IMGUI INTERFACE imgui::imgui lmc_stb_image_write)

add_library(PkgConfig::EPOXY INTERFACE IMPORTED)
target_include_directories(PkgConfig::EPOXY INTERFACE ${LMC_EPOXY_INCLUDE_DIR})
target_link_libraries(PkgConfig::EPOXY INTERFACE ${LMC_EPOXY_LIBRARY})
