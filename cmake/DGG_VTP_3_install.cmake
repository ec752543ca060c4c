# Installs the headers and a CMake package, so that after `cmake --install`
#   find_package(DGG_VTP_3 CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE CGAL::DGG_VTP_3)
# works; DGG_VTP_3Config.cmake finds CGAL and Boost itself. Everything here is in the install
# component DGG_VTP_3 (`cmake --install build --component DGG_VTP_3`: the library alone, without
# building or installing the programs). The package is header only, hence share/, not lib/.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(_config_dir ${CMAKE_INSTALL_DATADIR}/cmake/DGG_VTP_3)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/CGAL DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT DGG_VTP_3)
install(TARGETS DGG_VTP_3 EXPORT DGG_VTP_3Targets COMPONENT DGG_VTP_3)
install(EXPORT DGG_VTP_3Targets NAMESPACE CGAL:: DESTINATION ${_config_dir} COMPONENT DGG_VTP_3)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/DGG_VTP_3Config.cmake.in
  ${PROJECT_BINARY_DIR}/DGG_VTP_3Config.cmake INSTALL_DESTINATION ${_config_dir})
# 0.x: a minor version may break the interface, so only the same minor version is compatible
write_basic_package_version_file(${PROJECT_BINARY_DIR}/DGG_VTP_3ConfigVersion.cmake
  COMPATIBILITY SameMinorVersion ARCH_INDEPENDENT)
install(FILES ${PROJECT_BINARY_DIR}/DGG_VTP_3Config.cmake ${PROJECT_BINARY_DIR}/DGG_VTP_3ConfigVersion.cmake
        DESTINATION ${_config_dir} COMPONENT DGG_VTP_3)
