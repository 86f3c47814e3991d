# Installs a CMake package so that users' projects can `find_package(wash)`.
include(CMakePackageConfigHelpers)
set(WASH_CMAKE_INSTALL_DIR lib/cmake/wash)
install(EXPORT washTargets NAMESPACE wash:: DESTINATION ${WASH_CMAKE_INSTALL_DIR})
configure_package_config_file(cmake/washConfig.cmake.in
  "${PROJECT_BINARY_DIR}/washConfig.cmake" INSTALL_DESTINATION ${WASH_CMAKE_INSTALL_DIR})
write_basic_package_version_file("${PROJECT_BINARY_DIR}/washConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/washConfig.cmake"
  "${PROJECT_BINARY_DIR}/washConfigVersion.cmake" cmake/WashSimulation.cmake
  DESTINATION ${WASH_CMAKE_INSTALL_DIR})
