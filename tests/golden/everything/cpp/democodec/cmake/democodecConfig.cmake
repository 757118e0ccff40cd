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
#   target_link_libraries(app PRIVATE democodec::cpp)        # C++17 library (static unless built shared)
#
# Components: c, c_json, c_posix and c_win32 (the C package: democodec-c-targets.cmake; c_posix when
# built with DEMOCODEC_POSIX, c_win32 with DEMOCODEC_WIN32), cpp (the C++ package: democodec-cpp-targets.cmake).
#
# The version file is ARCH_INDEPENDENT (one file for both packages); the packages' libraries are
# not, so democodec-c-abi.cmake and democodec-cpp-abi.cmake record their pointer size and a project
# of another one (a 32-bit or firmware build finding a 64-bit host install) does not get that
# package's targets: its components are reported missing with the reason.
set(_democodec_c_why "")
foreach(_democodec_part c cpp)
    if(EXISTS "${CMAKE_CURRENT_LIST_DIR}/democodec-${_democodec_part}-targets.cmake")
        if(EXISTS "${CMAKE_CURRENT_LIST_DIR}/democodec-${_democodec_part}-abi.cmake")
            include("${CMAKE_CURRENT_LIST_DIR}/democodec-${_democodec_part}-abi.cmake")
            set(_democodec_bits "${_democodec_${_democodec_part}_sizeof_void_p}")
            if(CMAKE_SIZEOF_VOID_P AND _democodec_bits AND NOT CMAKE_SIZEOF_VOID_P EQUAL _democodec_bits)
                set(_democodec_name "C")
                if(_democodec_part STREQUAL "cpp")
                    set(_democodec_name "C++")
                endif()
                string(APPEND _democodec_c_why "; the ${_democodec_name} package in ${CMAKE_CURRENT_LIST_DIR} was built for ${_democodec_bits}-byte pointers, this project has ${CMAKE_SIZEOF_VOID_P}")
                continue()
            endif()
        endif()
        include("${CMAKE_CURRENT_LIST_DIR}/democodec-${_democodec_part}-targets.cmake")
    endif()
endforeach()
unset(_democodec_part)
unset(_democodec_bits)
unset(_democodec_name)
unset(_democodec_c_sizeof_void_p)
unset(_democodec_cpp_sizeof_void_p)

# (With components asked for and a package refused for its pointer size, the components below say why.)
if(NOT TARGET democodec::c AND NOT TARGET democodec::cpp AND NOT (_democodec_c_why AND democodec_FIND_COMPONENTS))
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
