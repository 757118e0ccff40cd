# CMake toolchain file for a Windows (x86-64) build of democodec (or of a project that uses it) from
# Linux with MinGW-w64: Debian's gcc-mingw-w64-x86-64 and g++-mingw-w64-x86-64. Shipped with the C
# and the C++ package (cmake/x86_64-w64-mingw32.cmake) and installed to
# <prefix>/share/democodec/x86_64-w64-mingw32.cmake. Generated: do not edit.
#
#   cmake -S . -B build-win -DCMAKE_TOOLCHAIN_FILE=third_party/democodec/cmake/x86_64-w64-mingw32.cmake
#
# On WIN32 the packages build the Win32 transports (Winsock TCP and COM serial ports) in place of
# the POSIX ones. Programs are linked statically (libgcc, libstdc++, winpthread), so that an .exe
# runs on Windows (or under Wine) without the MinGW DLLs beside it. DEMOCODEC_MINGW_PREFIX names
# another MinGW-w64 toolchain (i686-w64-mingw32 for 32-bit Windows).
set(CMAKE_SYSTEM_NAME Windows)
if(NOT DEFINED DEMOCODEC_MINGW_PREFIX)
    set(DEMOCODEC_MINGW_PREFIX x86_64-w64-mingw32)
endif()
set(DEMOCODEC_MINGW_PREFIX "${DEMOCODEC_MINGW_PREFIX}" CACHE STRING "Target triple of the MinGW-w64 toolchain")
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES DEMOCODEC_MINGW_PREFIX)
if(DEMOCODEC_MINGW_PREFIX MATCHES "^i.86")
    set(CMAKE_SYSTEM_PROCESSOR x86)
else()
    set(CMAKE_SYSTEM_PROCESSOR x86_64)
endif()

set(CMAKE_C_COMPILER ${DEMOCODEC_MINGW_PREFIX}-gcc)
set(CMAKE_CXX_COMPILER ${DEMOCODEC_MINGW_PREFIX}-g++)
set(CMAKE_RC_COMPILER ${DEMOCODEC_MINGW_PREFIX}-windres)
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static")

# Programs (code generators, ...) come from the host; libraries, headers and packages from the MinGW
# sysroot and the roots given with -DCMAKE_FIND_ROOT_PATH (a prefix the Windows build of a package
# was installed to).
list(APPEND CMAKE_FIND_ROOT_PATH /usr/${DEMOCODEC_MINGW_PREFIX})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
