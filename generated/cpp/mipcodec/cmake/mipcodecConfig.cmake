# mipcodecConfig.cmake: the CMake package mipcodec, installed byte-identical by the C and the C++
# package of the MicroStrain MIP protocol, so that both fit one install tree. Generated: do not edit.
#
#   find_package(mipcodec CONFIG REQUIRED)                  # whatever is installed
#   find_package(mipcodec 0.1 CONFIG REQUIRED)              # a compatible version (mipcodecConfigVersion.cmake)
#   find_package(mipcodec CONFIG REQUIRED COMPONENTS c)     # fail unless the C package is
#   target_link_libraries(app PRIVATE mipcodec::c)          # C core (no stdio, no heap)
#   target_link_libraries(app PRIVATE mipcodec::c_json)     # C canonical JSON (links mipcodec::c)
#   target_link_libraries(app PRIVATE mipcodec::c_posix)    # C POSIX transports of the session API
#   target_link_libraries(app PRIVATE mipcodec::c_win32)    # C Win32 transports (Windows; links ws2_32)
#   target_link_libraries(app PRIVATE mipcodec::cpp)        # C++17 library (static unless built shared)
#
# Components: c, c_json, c_posix and c_win32 (the C package: mipcodec-c-targets.cmake; c_posix when
# built with MIPCODEC_POSIX, c_win32 with MIPCODEC_WIN32), cpp (the C++ package: mipcodec-cpp-targets.cmake).
#
# The version file is ARCH_INDEPENDENT (one file for both packages); the packages' libraries are
# not, so mipcodec-c-abi.cmake and mipcodec-cpp-abi.cmake record their pointer size and a project
# of another one (a 32-bit or firmware build finding a 64-bit host install) does not get that
# package's targets: its components are reported missing with the reason.
set(_mipcodec_c_why "")
foreach(_mipcodec_part c cpp)
    if(EXISTS "${CMAKE_CURRENT_LIST_DIR}/mipcodec-${_mipcodec_part}-targets.cmake")
        if(EXISTS "${CMAKE_CURRENT_LIST_DIR}/mipcodec-${_mipcodec_part}-abi.cmake")
            include("${CMAKE_CURRENT_LIST_DIR}/mipcodec-${_mipcodec_part}-abi.cmake")
            set(_mipcodec_bits "${_mipcodec_${_mipcodec_part}_sizeof_void_p}")
            if(CMAKE_SIZEOF_VOID_P AND _mipcodec_bits AND NOT CMAKE_SIZEOF_VOID_P EQUAL _mipcodec_bits)
                set(_mipcodec_name "C")
                if(_mipcodec_part STREQUAL "cpp")
                    set(_mipcodec_name "C++")
                endif()
                string(APPEND _mipcodec_c_why "; the ${_mipcodec_name} package in ${CMAKE_CURRENT_LIST_DIR} was built for ${_mipcodec_bits}-byte pointers, this project has ${CMAKE_SIZEOF_VOID_P}")
                continue()
            endif()
        endif()
        include("${CMAKE_CURRENT_LIST_DIR}/mipcodec-${_mipcodec_part}-targets.cmake")
    endif()
endforeach()
unset(_mipcodec_part)
unset(_mipcodec_bits)
unset(_mipcodec_name)
unset(_mipcodec_c_sizeof_void_p)
unset(_mipcodec_cpp_sizeof_void_p)

# (With components asked for and a package refused for its pointer size, the components below say why.)
if(NOT TARGET mipcodec::c AND NOT TARGET mipcodec::cpp AND NOT (_mipcodec_c_why AND mipcodec_FIND_COMPONENTS))
    set(mipcodec_FOUND FALSE)
    set(mipcodec_NOT_FOUND_MESSAGE "neither the C nor the C++ package of mipcodec is installed in ${CMAKE_CURRENT_LIST_DIR}${_mipcodec_c_why}")
    unset(_mipcodec_c_why)
    return()
endif()

foreach(_mipcodec_comp ${mipcodec_FIND_COMPONENTS})
    if(TARGET mipcodec::${_mipcodec_comp})
        set(mipcodec_${_mipcodec_comp}_FOUND TRUE)
    else()
        set(mipcodec_${_mipcodec_comp}_FOUND FALSE)
        if(mipcodec_FIND_REQUIRED_${_mipcodec_comp})
            set(mipcodec_FOUND FALSE)
            set(mipcodec_NOT_FOUND_MESSAGE
                "component ${_mipcodec_comp} is not installed (c, c_json, c_posix, c_win32: the C package; cpp: the C++ package)${_mipcodec_c_why}")
        endif()
    endif()
endforeach()
unset(_mipcodec_comp)
unset(_mipcodec_c_why)
