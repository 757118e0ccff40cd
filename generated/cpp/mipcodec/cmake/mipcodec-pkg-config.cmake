# Variables of the pkg-config files of mipcodec (cmake/*.pc.in), relocatable: the prefix is found
# relative to the .pc file. Generated: do not edit.
file(RELATIVE_PATH MIPCODEC_PC_TO_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
foreach(_mipcodec_dir LIBDIR INCLUDEDIR)
    if(IS_ABSOLUTE "${CMAKE_INSTALL_${_mipcodec_dir}}")
        set(MIPCODEC_PC_${_mipcodec_dir} "${CMAKE_INSTALL_${_mipcodec_dir}}")
    else()
        set(MIPCODEC_PC_${_mipcodec_dir} "\${prefix}/${CMAKE_INSTALL_${_mipcodec_dir}}")
    endif()
endforeach()
unset(_mipcodec_dir)
# The package version, once the project declares one.
if(PROJECT_VERSION)
    set(MIPCODEC_PC_VERSION "${PROJECT_VERSION}")
else()
    set(MIPCODEC_PC_VERSION "0")
endif()
