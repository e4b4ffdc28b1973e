# Installation and the package configuration (find_package(pg)):
#   cmake --install <build> --prefix <prefix>
# puts libpg.so, the headers, pg_solve and pg_study (if built) and
# lib/cmake/pg/pgConfig.cmake into <prefix>; a user's project then calls
# find_package(pg) with -Dpg_DIR=<prefix>/lib/cmake/pg (or
# CMAKE_PREFIX_PATH=<prefix>) and links pg::pg. The build tree exports the
# same files, so -Dpg_DIR=<build> works without installing.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(_pg_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/pg)

install(TARGETS pg EXPORT pgTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/pg
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/include/pg/version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/pg)
if(PG_BUILD_APPLICATIONS)
  # the applications find libpg.so next to them in <prefix>/lib
  set_target_properties(pg_solve pg_study PROPERTIES
    INSTALL_RPATH "$ORIGIN/../${CMAKE_INSTALL_LIBDIR}")
  install(TARGETS pg_solve pg_study
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(EXPORT pgTargets NAMESPACE pg:: DESTINATION ${_pg_config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/pgConfig.cmake.in
  ${PROJECT_BINARY_DIR}/cmake/pgConfig.cmake
  INSTALL_DESTINATION ${_pg_config_dir})
write_basic_package_version_file(
  ${PROJECT_BINARY_DIR}/cmake/pgConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/cmake/pgConfig.cmake
  ${PROJECT_BINARY_DIR}/cmake/pgConfigVersion.cmake
  DESTINATION ${_pg_config_dir})

# the build tree as a package too: -Dpg_DIR=<build>
export(EXPORT pgTargets NAMESPACE pg::
  FILE ${PROJECT_BINARY_DIR}/pgTargets.cmake)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/pgConfig.cmake.in
  ${PROJECT_BINARY_DIR}/pgConfig.cmake
  INSTALL_DESTINATION ${PROJECT_BINARY_DIR})
configure_file(${PROJECT_BINARY_DIR}/cmake/pgConfigVersion.cmake
  ${PROJECT_BINARY_DIR}/pgConfigVersion.cmake COPYONLY)
