# mscipcodecConfig.cmake: the CMake package mscipcodec, installed byte-identical by the C and the C++
# package of the Memsense MS-CIP protocol, so that both fit one install tree. Generated: do not edit.
#
#   find_package(mscipcodec CONFIG REQUIRED)                  # whatever is installed
#   find_package(mscipcodec 0.1 CONFIG REQUIRED)              # a compatible version (mscipcodecConfigVersion.cmake)
#   find_package(mscipcodec CONFIG REQUIRED COMPONENTS c)     # fail unless the C package is
#   target_link_libraries(app PRIVATE mscipcodec::c)          # C core (no stdio, no heap)
#   target_link_libraries(app PRIVATE mscipcodec::c_json)     # C canonical JSON (links mscipcodec::c)
#   target_link_libraries(app PRIVATE mscipcodec::c_posix)    # C POSIX transports of the session API
#   target_link_libraries(app PRIVATE mscipcodec::c_win32)    # C Win32 transports (Windows; links ws2_32)
#   target_link_libraries(app PRIVATE mscipcodec::cpp)        # C++17 library (static unless built shared)
#
# Components: c, c_json, c_posix and c_win32 (the C package: mscipcodec-c-targets.cmake; c_posix when
# built with MSCIPCODEC_POSIX, c_win32 with MSCIPCODEC_WIN32), cpp (the C++ package: mscipcodec-cpp-targets.cmake).
#
# The version file is ARCH_INDEPENDENT (one file for both packages); the packages' libraries are
# not, so mscipcodec-c-abi.cmake and mscipcodec-cpp-abi.cmake record their pointer size and a project
# of another one (a 32-bit or firmware build finding a 64-bit host install) does not get that
# package's targets: its components are reported missing with the reason.
set(_mscipcodec_c_why "")
foreach(_mscipcodec_part c cpp)
    if(EXISTS "${CMAKE_CURRENT_LIST_DIR}/mscipcodec-${_mscipcodec_part}-targets.cmake")
        if(EXISTS "${CMAKE_CURRENT_LIST_DIR}/mscipcodec-${_mscipcodec_part}-abi.cmake")
            include("${CMAKE_CURRENT_LIST_DIR}/mscipcodec-${_mscipcodec_part}-abi.cmake")
            set(_mscipcodec_bits "${_mscipcodec_${_mscipcodec_part}_sizeof_void_p}")
            if(CMAKE_SIZEOF_VOID_P AND _mscipcodec_bits AND NOT CMAKE_SIZEOF_VOID_P EQUAL _mscipcodec_bits)
                set(_mscipcodec_name "C")
                if(_mscipcodec_part STREQUAL "cpp")
                    set(_mscipcodec_name "C++")
                endif()
                string(APPEND _mscipcodec_c_why "; the ${_mscipcodec_name} package in ${CMAKE_CURRENT_LIST_DIR} was built for ${_mscipcodec_bits}-byte pointers, this project has ${CMAKE_SIZEOF_VOID_P}")
                continue()
            endif()
        endif()
        include("${CMAKE_CURRENT_LIST_DIR}/mscipcodec-${_mscipcodec_part}-targets.cmake")
    endif()
endforeach()
unset(_mscipcodec_part)
unset(_mscipcodec_bits)
unset(_mscipcodec_name)
unset(_mscipcodec_c_sizeof_void_p)
unset(_mscipcodec_cpp_sizeof_void_p)

# (With components asked for and a package refused for its pointer size, the components below say why.)
if(NOT TARGET mscipcodec::c AND NOT TARGET mscipcodec::cpp AND NOT (_mscipcodec_c_why AND mscipcodec_FIND_COMPONENTS))
    set(mscipcodec_FOUND FALSE)
    set(mscipcodec_NOT_FOUND_MESSAGE "neither the C nor the C++ package of mscipcodec is installed in ${CMAKE_CURRENT_LIST_DIR}${_mscipcodec_c_why}")
    unset(_mscipcodec_c_why)
    return()
endif()

foreach(_mscipcodec_comp ${mscipcodec_FIND_COMPONENTS})
    if(TARGET mscipcodec::${_mscipcodec_comp})
        set(mscipcodec_${_mscipcodec_comp}_FOUND TRUE)
    else()
        set(mscipcodec_${_mscipcodec_comp}_FOUND FALSE)
        if(mscipcodec_FIND_REQUIRED_${_mscipcodec_comp})
            set(mscipcodec_FOUND FALSE)
            set(mscipcodec_NOT_FOUND_MESSAGE
                "component ${_mscipcodec_comp} is not installed (c, c_json, c_posix, c_win32: the C package; cpp: the C++ package)${_mscipcodec_c_why}")
        endif()
    endif()
endforeach()
unset(_mscipcodec_comp)
unset(_mscipcodec_c_why)
