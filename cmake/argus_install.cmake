# `cmake --install`: the `argus` executable, the headers a strategy plug-in compiles against
# (every folder a plain-C++ library builds from: the strategy interface includes config/,
# protocol/ and vision/ types, and a plug-in may reuse any of them), and the CMake package that
# makes find_package(Argus) work for a plug-in's own project (examples/strategies/).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# The strategy interface as a library target: headers and standard only; the runtime's code is
# the executable's.
find_package(Eigen3 REQUIRED NO_MODULE)
find_package(OpenCV REQUIRED COMPONENTS core)
add_library(argus_strategy_api INTERFACE)
add_library(Argus::strategy ALIAS argus_strategy_api)
set_target_properties(argus_strategy_api PROPERTIES EXPORT_NAME strategy)
target_compile_features(argus_strategy_api INTERFACE cxx_std_20)
target_include_directories(argus_strategy_api INTERFACE
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/argus>)
target_link_libraries(argus_strategy_api INTERFACE Eigen3::Eigen opencv_core)
include(ArgusStrategyPlugin)

install(TARGETS argus RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS argus_strategy_api EXPORT ArgusTargets)
foreach(dir config controller events protocol sensing vision world eval)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/argus/${dir}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/Argus)
install(EXPORT ArgusTargets NAMESPACE Argus:: DESTINATION ${config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ArgusConfig.cmake.in
  ${PROJECT_BINARY_DIR}/ArgusConfig.cmake INSTALL_DESTINATION ${config_dir}
  PATH_VARS CMAKE_INSTALL_BINDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ArgusConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ArgusConfig.cmake ${PROJECT_BINARY_DIR}/ArgusConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/ArgusStrategyPlugin.cmake
        DESTINATION ${config_dir})
