# mscipcodecConfig.cmake: the CMake package mscipcodec, installed byte-identical by the C and the C++
# package of the Memsense MS-CIP protocol, so that both fit one install tree. Generated: do not edit.
#
#   find_package(mscipcodec CONFIG REQUIRED)                  # whatever is installed
#   find_package(mscipcodec 0.1 CONFIG REQUIRED)              # a compatible version (mscipcodecConfigVersion.cmake)
#   find_package(mscipcodec CONFIG REQUIRED COMPONENTS c)     # fail unless the C package is
#   target_link_libraries(app PRIVATE mscipcodec::c)          # C core (no stdio, no heap)
#   target_link_libraries(app PRIVATE mscipcodec::c_json)     # C canonical JSON (links mscipcodec::c)
#   target_link_libraries(app PRIVATE mscipcodec::c_posix)    # C POSIX transports of the session API
#   target_link_libraries(app PRIVATE mscipcodec::cpp)        # C++17 header-only library
#
# Components: c, c_json and c_posix (the C package: mscipcodec-c-targets.cmake; c_posix when built
# with MSCIPCODEC_POSIX), cpp (the C++ package: mscipcodec-cpp-targets.cmake).
foreach(_mscipcodec_part c cpp)
    if(EXISTS "${CMAKE_CURRENT_LIST_DIR}/mscipcodec-${_mscipcodec_part}-targets.cmake")
        include("${CMAKE_CURRENT_LIST_DIR}/mscipcodec-${_mscipcodec_part}-targets.cmake")
    endif()
endforeach()
unset(_mscipcodec_part)

if(NOT TARGET mscipcodec::c AND NOT TARGET mscipcodec::cpp)
    set(mscipcodec_FOUND FALSE)
    set(mscipcodec_NOT_FOUND_MESSAGE "neither the C nor the C++ package of mscipcodec is installed in ${CMAKE_CURRENT_LIST_DIR}")
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
                "component ${_mscipcodec_comp} is not installed (c, c_json, c_posix: the C package; cpp: the C++ package)")
        endif()
    endif()
endforeach()
unset(_mscipcodec_comp)
