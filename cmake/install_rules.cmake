# Install rules. In a catkin build (catkin_make_isolated --install, colcon build) the package
# installs as ROS packages do: the core library and headers for other packages (found with
# find_package(catkin COMPONENTS eaci_planner)), the nodes and tools in lib/eaci_planner
# (rosrun), and launch/, config/, maps/ in share/eaci_planner; the move_base plugin and
# plugins.xml are installed by src/ros when the plugin is built. Without catkin, a plain
# `cmake --install` puts the library, headers and tools under the prefix, with a CMake package
# (find_package(eaci_planner) -> eaci_planner::eaci_core).
if(EACI_ROS_FOUND)
  install(TARGETS eaci_core
          ARCHIVE DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
          LIBRARY DESTINATION ${CATKIN_PACKAGE_LIB_DESTINATION}
          RUNTIME DESTINATION ${CATKIN_GLOBAL_BIN_DESTINATION})
  install(DIRECTORY include/eaci DESTINATION ${CATKIN_GLOBAL_INCLUDE_DESTINATION})
  foreach(tool eaci_plan eaci_bench)
    if(TARGET ${tool})
      install(TARGETS ${tool} RUNTIME DESTINATION ${CATKIN_PACKAGE_BIN_DESTINATION})
    endif()
  endforeach()
  install(DIRECTORY launch config maps DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION})
  # The install-space check (scripts/install_check.sh) runs this rostest from share/.
  install(FILES test/ros/install/demo_arrives.test DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/test)
  install(PROGRAMS test/ros/install/arrival_check.py DESTINATION ${CATKIN_PACKAGE_SHARE_DESTINATION}/test)
else()
  include(GNUInstallDirs)
  include(CMakePackageConfigHelpers)
  install(TARGETS eaci_core EXPORT eaci_plannerTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY include/eaci DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  foreach(tool eaci_plan eaci_bench)
    if(TARGET ${tool})
      install(TARGETS ${tool} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
    endif()
  endforeach()
  set(EACI_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/eaci_planner)
  install(EXPORT eaci_plannerTargets NAMESPACE eaci_planner:: DESTINATION ${EACI_CMAKE_DIR})
  configure_package_config_file(cmake/eaci_plannerConfig.cmake.in
    ${CMAKE_CURRENT_BINARY_DIR}/eaci_plannerConfig.cmake INSTALL_DESTINATION ${EACI_CMAKE_DIR})
  write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/eaci_plannerConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
  install(FILES ${CMAKE_CURRENT_BINARY_DIR}/eaci_plannerConfig.cmake
                ${CMAKE_CURRENT_BINARY_DIR}/eaci_plannerConfigVersion.cmake
          DESTINATION ${EACI_CMAKE_DIR})
  install(DIRECTORY launch config maps DESTINATION ${CMAKE_INSTALL_DATADIR}/eaci_planner)
endif()
