# install(): the core library, its headers, the programs, and the CMake package `gpsurf`
# (find_package(gpsurf 0.2) gives gpsurf::core). The Python module installs itself (python/).
include(CMakePackageConfigHelpers)
set(GPSURF_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/gpsurf)

install(TARGETS gps_core EXPORT gpsurfTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The public headers: each folder's entry points and what they include, and no other header of core
# (the plan builders, the reference's rules, the decimation's OpenMesh mesh stay inside).
set(GPSURF_PUBLIC_HEADERS
  core/mesh/covariance_mesh.h core/mesh/sharpness.h core/mesh/dual_map.h core/mesh/inference.h
  core/mesh/crease_by_angle.h
  core/io/mesh_io.h core/io/mesh_repair.h
  core/reference/reference_subdivision.h
  core/plans/planned_surface.h
  core/evaluation/patch_eval.h core/evaluation/tessellator.h
  core/edit/covariance_edit.h core/edit/gaussian_change.h
  core/modelling/operation_list.h core/modelling/primitives.h core/modelling/samples.h
  core/fitting/mesh_simplification.h core/fitting/limit_placement.h core/fitting/surface_distance.h
  core/fitting/limit_fit.h
  core/support/error.h core/support/progress.h core/support/freed_memory.h)
set(installed "")
set(pending ${GPSURF_PUBLIC_HEADERS})
while(pending)
  list(POP_FRONT pending header)
  if(header IN_LIST installed)
    continue()
  endif()
  list(APPEND installed ${header})
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${header})
  file(STRINGS ${PROJECT_SOURCE_DIR}/${header} includes REGEX "^#include \"core/")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"(core/[^\"]+)\".*" "\\1" included "${line}")
    if(EXISTS ${PROJECT_SOURCE_DIR}/${included})
      list(APPEND pending ${included})
    endif()
  endforeach()
endwhile()
foreach(header ${installed})
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/gpsurf/${folder})
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/core/generated/core/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/gpsurf/core)
install(EXPORT gpsurfTargets NAMESPACE gpsurf:: DESTINATION ${GPSURF_CMAKE_DIR})
install(TARGETS gpsurf RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(GPSURF_BUILD_GL)
  install(TARGETS gpsurf-editor RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # Not a command of its own: gpsurf runs it for render, bench and diff (app/gl_commands.h).
  install(TARGETS gpsurf-render RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/gpsurf)
  # OpenImageIO's formats, opened when first needed (render/image/image_file_module.h).
  install(TARGETS gpsurf_openimageio LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/gpsurf)
endif()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/gpsurfConfig.cmake.in
  ${PROJECT_BINARY_DIR}/gpsurfConfig.cmake INSTALL_DESTINATION ${GPSURF_CMAKE_DIR})
# 0.x: a minor version may change the interface, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/gpsurfConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/gpsurfConfig.cmake ${PROJECT_BINARY_DIR}/gpsurfConfigVersion.cmake
        DESTINATION ${GPSURF_CMAKE_DIR})
