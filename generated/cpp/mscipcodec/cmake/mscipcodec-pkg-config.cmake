# Variables of the pkg-config files of mscipcodec (cmake/*.pc.in), relocatable: the prefix is found
# relative to the .pc file. Generated: do not edit.
file(RELATIVE_PATH MSCIPCODEC_PC_TO_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
foreach(_mscipcodec_dir LIBDIR INCLUDEDIR)
    if(IS_ABSOLUTE "${CMAKE_INSTALL_${_mscipcodec_dir}}")
        set(MSCIPCODEC_PC_${_mscipcodec_dir} "${CMAKE_INSTALL_${_mscipcodec_dir}}")
    else()
        set(MSCIPCODEC_PC_${_mscipcodec_dir} "\${prefix}/${CMAKE_INSTALL_${_mscipcodec_dir}}")
    endif()
endforeach()
unset(_mscipcodec_dir)
# The package version, once the project declares one.
if(PROJECT_VERSION)
    set(MSCIPCODEC_PC_VERSION "${PROJECT_VERSION}")
else()
    set(MSCIPCODEC_PC_VERSION "0")
endif()
