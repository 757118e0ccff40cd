# mscipcodecConfigVersion.cmake, written and installed beside mscipcodecConfig.cmake by the C and the C++
# package of the Memsense MS-CIP protocol (the same bytes from both, so that both fit one install tree).
# Generated: do not edit.
#
# The compatibility is the rule of docs/versioning.md: while the major version is 0, a MINOR bump
# may break a consumer, so find_package(mscipcodec 0.Y) accepts 0.Y.z only (SameMinorVersion); from
# 1.0.0 on, find_package(mscipcodec X.Y) accepts X.y.z with y >= Y (SameMajorVersion).
# ARCH_INDEPENDENT, so that both packages write the same file: the pointer size of the packages'
# libraries is checked by mscipcodecConfig.cmake instead (mscipcodec-c-abi.cmake, mscipcodec-cpp-abi.cmake).
include(CMakePackageConfigHelpers)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/mscipcodecConfigVersion.cmake
    VERSION ${PROJECT_VERSION}
    COMPATIBILITY SameMinorVersion
    ARCH_INDEPENDENT)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/mscipcodecConfigVersion.cmake DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/mscipcodec)
