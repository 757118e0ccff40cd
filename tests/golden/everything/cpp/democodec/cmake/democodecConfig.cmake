# democodecConfig.cmake: the CMake package democodec, installed byte-identical by the C and the C++
# package of the Demo protocol with every spec feature protocol, so that both fit one install tree. Generated: do not edit.
#
#   find_package(democodec CONFIG REQUIRED)                  # whatever is installed
#   find_package(democodec 2.10 CONFIG REQUIRED)              # a compatible version (democodecConfigVersion.cmake)
#   find_package(democodec CONFIG REQUIRED COMPONENTS c)     # fail unless the C package is
#   target_link_libraries(app PRIVATE democodec::c)          # C core (no stdio, no heap)
#   target_link_libraries(app PRIVATE democodec::c_json)     # C canonical JSON (links democodec::c)
#   target_link_libraries(app PRIVATE democodec::c_posix)    # C POSIX transports of the session API
#   target_link_libraries(app PRIVATE democodec::c_win32)    # C Win32 transports (Windows; links ws2_32)
#   target_link_libraries(app PRIVATE democodec::cpp)        # C++17 header-only library
#
# Components: c, c_json, c_posix and c_win32 (the C package: democodec-c-targets.cmake; c_posix when
# built with DEMOCODEC_POSIX, c_win32 with DEMOCODEC_WIN32), cpp (the C++ package: democodec-cpp-targets.cmake).
#
# The version file is ARCH_INDEPENDENT (one file for both packages); the C package's libraries are
# not, so democodec-c-abi.cmake records their pointer size and a project of another one (a 32-bit
# or firmware build finding a 64-bit host install) does not get the C targets: its c components
# are reported missing with the reason.
set(_democodec_c_why "")
foreach(_democodec_part c cpp)
    if(EXISTS "${CMAKE_CURRENT_LIST_DIR}/democodec-${_democodec_part}-targets.cmake")
        if(_democodec_part STREQUAL "c" AND EXISTS "${CMAKE_CURRENT_LIST_DIR}/democodec-c-abi.cmake")
            include("${CMAKE_CURRENT_LIST_DIR}/democodec-c-abi.cmake")
            if(CMAKE_SIZEOF_VOID_P AND _democodec_c_sizeof_void_p
               AND NOT CMAKE_SIZEOF_VOID_P EQUAL _democodec_c_sizeof_void_p)
                set(_democodec_c_why "; the C package in ${CMAKE_CURRENT_LIST_DIR} was built for ${_democodec_c_sizeof_void_p}-byte pointers, this project has ${CMAKE_SIZEOF_VOID_P}")
                continue()
            endif()
        endif()
        include("${CMAKE_CURRENT_LIST_DIR}/democodec-${_democodec_part}-targets.cmake")
    endif()
endforeach()
unset(_democodec_part)
unset(_democodec_c_sizeof_void_p)

if(NOT TARGET democodec::c AND NOT TARGET democodec::cpp)
    set(democodec_FOUND FALSE)
    set(democodec_NOT_FOUND_MESSAGE "neither the C nor the C++ package of democodec is installed in ${CMAKE_CURRENT_LIST_DIR}${_democodec_c_why}")
    unset(_democodec_c_why)
    return()
endif()

foreach(_democodec_comp ${democodec_FIND_COMPONENTS})
    if(TARGET democodec::${_democodec_comp})
        set(democodec_${_democodec_comp}_FOUND TRUE)
    else()
        set(democodec_${_democodec_comp}_FOUND FALSE)
        if(democodec_FIND_REQUIRED_${_democodec_comp})
            set(democodec_FOUND FALSE)
            set(democodec_NOT_FOUND_MESSAGE
                "component ${_democodec_comp} is not installed (c, c_json, c_posix, c_win32: the C package; cpp: the C++ package)${_democodec_c_why}")
        endif()
    endif()
endforeach()
unset(_democodec_comp)
unset(_democodec_c_why)
