# Install rules. In a catkin build (catkin_make_isolated --install, colcon build) the package
# installs as ROS packages do: the core library and headers for other packages (found with
# find_package(catkin COMPONENTS eaci_planner)), the nodes and tools in lib/eaci_planner
# (rosrun), and launch/, config/, maps/ in share/eaci_planner; the move_base plugin and
# plugins.xml are installed by src/ros when the plugin is built. Without catkin, a plain
# `cmake --install` puts the library, headers and tools under the prefix, with a CMake package
# (find_package(eaci_planner) -> eaci_planner::eaci_core).
if(EACI_ROS_FOUND)
  set(EACI_LIB_DEST ${CATKIN_PACKAGE_LIB_DESTINATION})
  set(EACI_DLL_DEST ${CATKIN_GLOBAL_BIN_DESTINATION})
  set(EACI_INCLUDE_DEST ${CATKIN_GLOBAL_INCLUDE_DESTINATION})
  set(EACI_TOOL_DEST ${CATKIN_PACKAGE_BIN_DESTINATION})
  set(EACI_SHARE_DEST ${CATKIN_PACKAGE_SHARE_DESTINATION})
  set(EACI_EXPORT)   # catkin_package() exports the library
else()
  include(GNUInstallDirs)
  set(EACI_LIB_DEST ${CMAKE_INSTALL_LIBDIR})
  set(EACI_DLL_DEST ${CMAKE_INSTALL_BINDIR})
  set(EACI_INCLUDE_DEST ${CMAKE_INSTALL_INCLUDEDIR})
  set(EACI_TOOL_DEST ${CMAKE_INSTALL_BINDIR})
  set(EACI_SHARE_DEST ${CMAKE_INSTALL_DATADIR}/eaci_planner)
  set(EACI_EXPORT EXPORT eaci_plannerTargets)
endif()

install(TARGETS eaci_core ${EACI_EXPORT}
        ARCHIVE DESTINATION ${EACI_LIB_DEST}
        LIBRARY DESTINATION ${EACI_LIB_DEST}
        RUNTIME DESTINATION ${EACI_DLL_DEST})
install(DIRECTORY include/eaci DESTINATION ${EACI_INCLUDE_DEST})
foreach(tool eaci_plan eaci_bench)
  if(TARGET ${tool})
    install(TARGETS ${tool} RUNTIME DESTINATION ${EACI_TOOL_DEST})
  endif()
endforeach()
install(DIRECTORY launch config maps DESTINATION ${EACI_SHARE_DEST})

if(EACI_ROS_FOUND)
  # The install-space check (scripts/install_check.sh) runs this rostest from share/.
  install(FILES test/ros/install/demo_arrives.test DESTINATION ${EACI_SHARE_DEST}/test)
  install(PROGRAMS test/ros/install/arrival_check.py DESTINATION ${EACI_SHARE_DEST}/test)
else()
  include(CMakePackageConfigHelpers)
  set(EACI_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/eaci_planner)
  install(EXPORT eaci_plannerTargets NAMESPACE eaci_planner:: DESTINATION ${EACI_CMAKE_DIR})
  configure_package_config_file(cmake/eaci_plannerConfig.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/eaci_plannerConfig.cmake INSTALL_DESTINATION ${EACI_CMAKE_DIR})
  write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/eaci_plannerConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/eaci_plannerConfig.cmake
                ${CMAKE_CURRENT_BINARY_DIR}/eaci_plannerConfigVersion.cmake
          DESTINATION ${EACI_CMAKE_DIR})
endif()
