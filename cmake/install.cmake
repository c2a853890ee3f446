# Install rules and the exported package: `cmake --install build --prefix P` gives
#   P/include/projsurf/<folder>.hpp, each folder's public header, and the headers they include
#   P/lib/libprojsurf_<folder>.so* one per folder (libprojsurf_types.so, libprojsurf_io_yaml.so, ...)     P/bin/projsurf (the evaluation, eval/, is linked into it, not installed)
#   P/lib/cmake/projsurf/  find_package(projsurf [COMPONENTS core sim io frontend]) -> projsurf::<component>
#                          (projsurf::core links projsurf::types, projsurf::detection, ...)
#   P/lib/pkgconfig/       projsurf-core.pc (the core), projsurf.pc (all of them)
# Each component has its own export file, so find_package(projsurf COMPONENTS core) looks up
# only what the core's headers need (Eigen, OpenCV core): no nlohmann-json, PCL or CLI11.
# Every path in these files is relative to where they are installed (a tree can be moved).
include(CMakePackageConfigHelpers)
projsurf_install_public_headers()
set(PROJSURF_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/projsurf)

set(PROJSURF_COMPONENTS core sim)
if(TARGET projsurf_io)
  list(APPEND PROJSURF_COMPONENTS io)
endif()
if(TARGET projsurf_frontend)
  list(APPEND PROJSURF_COMPONENTS frontend)  # the CLI links it
endif()
# Each component is one or more folder libraries (projsurf_io_files, ...) behind an umbrella
# (projsurf::io); sim is its folder's library, which links sim/scenes.
set(PROJSURF_core_FOLDERS ${PROJSURF_CORE_TARGETS})
set(PROJSURF_sim_FOLDERS ${PROJSURF_SIM_TARGETS})
set(PROJSURF_io_FOLDERS ${PROJSURF_IO_TARGETS})
set(PROJSURF_frontend_FOLDERS ${PROJSURF_FRONTEND_TARGETS})
foreach(component ${PROJSURF_COMPONENTS})
  set(targets ${PROJSURF_${component}_FOLDERS})
  if(NOT component STREQUAL "sim")
    list(APPEND targets projsurf_${component})
  endif()
  install(TARGETS ${targets} EXPORT projsurf-${component}-targets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT runtime NAMELINK_COMPONENT devel
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT devel
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
  install(EXPORT projsurf-${component}-targets NAMESPACE projsurf:: DESTINATION ${PROJSURF_CMAKE_DIR}
    COMPONENT devel)
endforeach()

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/projsurf-config.cmake.in
  ${PROJECT_BINARY_DIR}/projsurf-config.cmake INSTALL_DESTINATION ${PROJSURF_CMAKE_DIR})
# 0.x: minor versions may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/projsurf-config-version.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/projsurf-config.cmake ${PROJECT_BINARY_DIR}/projsurf-config-version.cmake
  DESTINATION ${PROJSURF_CMAKE_DIR} COMPONENT devel)

# pkg-config: the prefix is found from the .pc file's own folder.
set(PROJSURF_PKGCONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
file(RELATIVE_PATH PROJSURF_PC_TO_PREFIX /prefix/${PROJSURF_PKGCONFIG_DIR} /prefix)
string(REGEX REPLACE "/$" "" PROJSURF_PC_TO_PREFIX "${PROJSURF_PC_TO_PREFIX}")
# Static libraries: a program links what projsurf_io uses inside too (pkg-config --static).
set(PROJSURF_PC_IO_PRIVATE "")
if(NOT PROJSURF_SHARED_LIBS)
  set(PROJSURF_PC_IO_PRIVATE yaml-cpp)
endif()
# projsurf-core links every folder's library, the ones that use others first.
set(PROJSURF_PC_CORE_LIBS "")
foreach(target ${PROJSURF_CORE_TARGETS})
  string(PREPEND PROJSURF_PC_CORE_LIBS "-l${target} ")
endforeach()
string(STRIP "${PROJSURF_PC_CORE_LIBS}" PROJSURF_PC_CORE_LIBS)
# projsurf.pc: the frontend's, io's and sim's folder libraries, users before what they use.
set(PROJSURF_PC_LIBS "")
foreach(target ${PROJSURF_SIM_TARGETS} ${PROJSURF_IO_TARGETS} ${PROJSURF_FRONTEND_TARGETS})
  string(PREPEND PROJSURF_PC_LIBS "-l${target} ")
endforeach()
string(STRIP "${PROJSURF_PC_LIBS}" PROJSURF_PC_LIBS)
set(PROJSURF_PC_FILES projsurf-core)
if(TARGET projsurf_io)
  list(APPEND PROJSURF_PC_FILES projsurf)
endif()
foreach(pc ${PROJSURF_PC_FILES})
  configure_file(${CMAKE_CURRENT_LIST_DIR}/${pc}.pc.in ${PROJECT_BINARY_DIR}/${pc}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/${pc}.pc DESTINATION ${PROJSURF_PKGCONFIG_DIR} COMPONENT devel)
endforeach()
