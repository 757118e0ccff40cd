# CMake toolchain file for a Cortex-M firmware build of democodec (or of a project that vendors it)
# with the GNU Arm Embedded toolchain: Debian's gcc-arm-none-eabi and libnewlib-arm-none-eabi
# (newlib-nano, no OS). Shipped with the C package (cmake/arm-none-eabi.cmake) and installed to
# <prefix>/share/democodec/arm-none-eabi.cmake. Generated: do not edit.
#
#   cmake -S . -B build-m4 -DCMAKE_TOOLCHAIN_FILE=third_party/democodec/cmake/arm-none-eabi.cmake \
#         -DCMAKE_BUILD_TYPE=MinSizeRel
#
# The CPU defaults to a Cortex-M4F with hard float; another core through DEMOCODEC_ARM_FLAGS, e.g.
# -DDEMOCODEC_ARM_FLAGS="-mcpu=cortex-m0plus -mthumb" or "-mcpu=cortex-m7 -mthumb -mfloat-abi=hard
# -mfpu=fpv5-d16". Sections per function and data with --gc-sections keep only what the image uses;
# no start-up files are linked (the firmware brings its vector table and reset handler).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
# Compiler checks build a static library: nothing is linked without the firmware's start-up code.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

if(NOT DEFINED DEMOCODEC_ARM_FLAGS)
    set(DEMOCODEC_ARM_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16")
endif()
set(DEMOCODEC_ARM_FLAGS "${DEMOCODEC_ARM_FLAGS}" CACHE STRING "CPU flags of the Cortex-M target")
# The compiler checks (try_compile) see the same CPU flags.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES DEMOCODEC_ARM_FLAGS)

set(CMAKE_C_FLAGS_INIT "${DEMOCODEC_ARM_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_CXX_FLAGS_INIT "${DEMOCODEC_ARM_FLAGS} -ffunction-sections -fdata-sections")
set(CMAKE_ASM_FLAGS_INIT "${DEMOCODEC_ARM_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "--specs=nano.specs -nostartfiles -Wl,--gc-sections")

# Programs (code generators, ...) come from the host; libraries and headers from the target's sysroot.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
