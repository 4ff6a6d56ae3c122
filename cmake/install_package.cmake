# install(): the core library, its headers, the programs, and the CMake package `gpsurf`
# (find_package(gpsurf 0.2) gives gpsurf::core). The Python module installs itself (python/).
include(CMakePackageConfigHelpers)
set(GPSURF_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/gpsurf)

install(TARGETS gps_core EXPORT gpsurfTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/gpsurf/core
        FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/core/generated/core/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/gpsurf/core)
install(EXPORT gpsurfTargets NAMESPACE gpsurf:: DESTINATION ${GPSURF_CMAKE_DIR})
install(TARGETS gpsurf RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(GPSURF_BUILD_GL)
  install(TARGETS gpsurf-editor RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # Not a command of its own: gpsurf runs it for render, bench and diff (app/gl_commands.h).
  install(TARGETS gpsurf-render RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/gpsurf)
endif()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/gpsurfConfig.cmake.in
  ${PROJECT_BINARY_DIR}/gpsurfConfig.cmake INSTALL_DESTINATION ${GPSURF_CMAKE_DIR})
# 0.x: a minor version may change the interface, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/gpsurfConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/gpsurfConfig.cmake ${PROJECT_BINARY_DIR}/gpsurfConfigVersion.cmake
        DESTINATION ${GPSURF_CMAKE_DIR})
