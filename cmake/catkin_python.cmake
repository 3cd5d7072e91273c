# catkin runs Python (catkin_pkg, empy) while it configures, with PYTHON_EXECUTABLE. With a
# pyenv or conda python3 first on PATH that has no catkin_pkg, `find_package(catkin)` stops
# the configure with "No module named 'catkin_pkg'". eaci_find_catkin_python() picks a
# python3 that has it instead: the one given with -DPYTHON_EXECUTABLE, else python3 on PATH,
# else the distribution's /usr/bin/python3. It sets EACI_CATKIN_PYTHON (TRUE/FALSE) and, when
# found, the cache variable PYTHON_EXECUTABLE; without one it says in one line what to do.
function(eaci_python_has_catkin_pkg python result)
  execute_process(COMMAND "${python}" -c "import catkin_pkg"
                  RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
  if(status EQUAL 0)
    set(${result} TRUE PARENT_SCOPE)
  else()
    set(${result} FALSE PARENT_SCOPE)
  endif()
endfunction()

# Debian's pluginlib loads ament_cmake_core, which finds Python with FindPython3 (and imports
# ament_package): point it at the same interpreter unless the user chose one.
function(eaci_use_python_for_ros python)
  if(NOT Python3_EXECUTABLE)
    set(Python3_EXECUTABLE "${python}" CACHE FILEPATH "python3 for ROS's CMake helpers")
  endif()
endfunction()

function(eaci_find_catkin_python)
  set(EACI_CATKIN_PYTHON FALSE PARENT_SCOPE)
  # No catkin installed: nothing to look for, and nothing to say beyond the ROS summary.
  find_file(EACI_CATKIN_CONFIG catkinConfig.cmake PATH_SUFFIXES share/catkin/cmake)
  if(NOT EACI_CATKIN_CONFIG)
    return()
  endif()
  if(PYTHON_EXECUTABLE)
    eaci_python_has_catkin_pkg("${PYTHON_EXECUTABLE}" ok)
    if(NOT ok)
      message(WARNING "eaci_planner: PYTHON_EXECUTABLE=${PYTHON_EXECUTABLE} cannot import catkin_pkg; "
                      "building without ROS (install python3-catkin-pkg or pass -DPYTHON_EXECUTABLE=/usr/bin/python3)")
      return()
    endif()
    eaci_use_python_for_ros("${PYTHON_EXECUTABLE}")
    set(EACI_CATKIN_PYTHON TRUE PARENT_SCOPE)
    return()
  endif()
  find_program(EACI_PATH_PYTHON3 python3)
  set(path_python3 "${EACI_PATH_PYTHON3}")
  unset(EACI_PATH_PYTHON3 CACHE)   # look again on the next configure: PATH may have changed
  foreach(candidate ${path_python3} /usr/bin/python3)
    if(EXISTS "${candidate}")
      eaci_python_has_catkin_pkg("${candidate}" ok)
      if(ok)
        set(PYTHON_EXECUTABLE "${candidate}" CACHE FILEPATH "python3 with catkin_pkg, for catkin")
        eaci_use_python_for_ros("${candidate}")
        message(STATUS "eaci_planner: catkin's Python: ${candidate}")
        set(EACI_CATKIN_PYTHON TRUE PARENT_SCOPE)
        return()
      endif()
    endif()
  endforeach()
  message(WARNING "eaci_planner: catkin is installed but no python3 here can import catkin_pkg; "
                  "building without ROS (install python3-catkin-pkg or pass -DPYTHON_EXECUTABLE=...)")
endfunction()
