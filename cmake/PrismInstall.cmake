# What `cmake --install` puts under the prefix (GNU layout):
#   bin/prism                              the command line
#   lib/libprism.a                         the library (a static archive)
#   include/prism/...                      its headers (the viewer's are not installed)
#   lib/cmake/Prism/PrismConfig.cmake      find_package(Prism): the imported target
#   lib/cmake/Prism/PrismConfigVersion.cmake   Prism::prism and the library's dependencies
#   lib/cmake/Prism/PrismTargets*.cmake
# The library is static, so a program linking it links its private dependencies too
# (Embree, TBB, OpenEXR, libpng, zlib, OpenColorIO, libavif): PrismConfig.cmake finds
# them as this build did (cmake/PrismConfig.cmake.in).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(PRISM_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Prism)

install(TARGETS prism_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# prism_warnings is an interface target the library links privately: a static library's
# private links are part of what it exports (as link-only), so it is exported with it.
install(TARGETS prism prism_warnings EXPORT PrismTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/prism/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/prism
        FILES_MATCHING PATTERN "*.h" PATTERN "*.inc"
        PATTERN "viewer" EXCLUDE)
install(DIRECTORY ${PROJECT_BINARY_DIR}/src/prism/generated/prism/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/prism
        FILES_MATCHING PATTERN "*.h")
install(EXPORT PrismTargets NAMESPACE Prism:: DESTINATION ${PRISM_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/PrismConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/PrismConfig.cmake
                              INSTALL_DESTINATION ${PRISM_INSTALL_CMAKEDIR})
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/PrismConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/PrismConfig.cmake ${PROJECT_BINARY_DIR}/PrismConfigVersion.cmake
        DESTINATION ${PRISM_INSTALL_CMAKEDIR})
