# Variables of the pkg-config files of democodec (cmake/*.pc.in), relocatable: the prefix is found
# relative to the .pc file. Generated: do not edit.
file(RELATIVE_PATH DEMOCODEC_PC_TO_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
foreach(_democodec_dir LIBDIR INCLUDEDIR)
    if(IS_ABSOLUTE "${CMAKE_INSTALL_${_democodec_dir}}")
        set(DEMOCODEC_PC_${_democodec_dir} "${CMAKE_INSTALL_${_democodec_dir}}")
    else()
        set(DEMOCODEC_PC_${_democodec_dir} "\${prefix}/${CMAKE_INSTALL_${_democodec_dir}}")
    endif()
endforeach()
unset(_democodec_dir)
# The package version, once the project declares one.
if(PROJECT_VERSION)
    set(DEMOCODEC_PC_VERSION "${PROJECT_VERSION}")
else()
    set(DEMOCODEC_PC_VERSION "0")
endif()
