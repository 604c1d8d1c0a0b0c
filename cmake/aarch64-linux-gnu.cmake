# Cross-compiling fieldlines for 64-bit ARM Linux (Jetson, Raspberry Pi 4/5, arm64 humanoids)
# with Debian's g++-aarch64-linux-gnu against an arm64 sysroot holding Debian's arm64 OpenCV,
# GoogleTest, nlohmann-json and Eigen. scripts/arm64.sh builds the sysroot (build/arm64/sysroot,
# from Debian's arm64 packages, nothing installed on the host) and uses this file through the
# `arm64` preset:
#   cmake --preset arm64 && cmake --build --preset arm64 -j2
# Another sysroot (say, a Jetson's root file system copied over): -DFIELDLINES_ARM64_SYSROOT=DIR.
# Built programs run on the host under qemu-user (CMAKE_CROSSCOMPILING_EMULATOR), which is how
# gtest_discover_tests lists the tests and how ctest would run them.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

if(NOT FIELDLINES_ARM64_SYSROOT)
  if(DEFINED ENV{FIELDLINES_ARM64_SYSROOT})
    set(FIELDLINES_ARM64_SYSROOT "$ENV{FIELDLINES_ARM64_SYSROOT}")
  else()
    get_filename_component(FIELDLINES_ARM64_SYSROOT "${CMAKE_CURRENT_LIST_DIR}/../build/arm64/sysroot" ABSOLUTE)
  endif()
endif()
if(NOT EXISTS "${FIELDLINES_ARM64_SYSROOT}/usr/lib/aarch64-linux-gnu")
  message(FATAL_ERROR "no arm64 sysroot at ${FIELDLINES_ARM64_SYSROOT}: run scripts/arm64.sh, "
                      "or pass -DFIELDLINES_ARM64_SYSROOT=DIR")
endif()
set(FIELDLINES_ARM64_SYSROOT "${FIELDLINES_ARM64_SYSROOT}" CACHE PATH "arm64 sysroot (scripts/arm64.sh builds one)")
# try_compile projects read this file again and need the same sysroot.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES FIELDLINES_ARM64_SYSROOT)

set(CMAKE_SYSROOT "${FIELDLINES_ARM64_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH "${FIELDLINES_ARM64_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)   # host tools (qemu, dpkg, git) come from the host
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# OpenCV's libraries need libraries of their own (gdal, ffmpeg, ...) that only the sysroot has;
# a sysroot unpacked from .debs has no ld.so.cache, so name its library folders to the linker.
set(_fieldlines_rpath_link
    "-Wl,-rpath-link,${FIELDLINES_ARM64_SYSROOT}/usr/lib/aarch64-linux-gnu -Wl,-rpath-link,${FIELDLINES_ARM64_SYSROOT}/lib/aarch64-linux-gnu")
# GCC's note that pair<double, double> is passed differently since GCC 9.1 concerns mixing
# objects built by GCC < 9 and >= 9; everything here is built by one compiler.
set(CMAKE_CXX_FLAGS_INIT "-Wno-psabi")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${_fieldlines_rpath_link}")
set(CMAKE_SHARED_LINKER_FLAGS_INIT "${_fieldlines_rpath_link}")
set(CMAKE_MODULE_LINKER_FLAGS_INIT "${_fieldlines_rpath_link}")

find_program(FIELDLINES_QEMU_AARCH64 NAMES qemu-aarch64-static qemu-aarch64)
if(FIELDLINES_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR "${FIELDLINES_QEMU_AARCH64};-L;${FIELDLINES_ARM64_SYSROOT}")
endif()

# cpack -G DEB in this build folder labels the packages arm64 (CPack would ask the host's dpkg).
set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE arm64)
