# cmake --install: what a team needs to build and play its own C++ behaviour outside this tree
# (examples/behaviour_plugin): the programs in bin/ with their files in share/touchline/
# (config/, behaviour_py/, the viewer's page, VERSION: the programs and tools/touchline_paths.py
# look there, beside bin/); the robot API's headers (plugin.hpp among them) as the exported
# target touchline::robot_api; the LCM types (.lcm files and the C++ headers lcm-gen made of
# them); and TouchlineConfig.cmake, so find_package(Touchline).
# `pip install .` (pyproject.toml, scikit-build-core) installs the same components into the
# environment's prefix, and the Python packages (component python) into its site-packages.
# Components: programs, lcm_types, development, java (the lcm-spy jar), python (pip only).
# Included last by the top CMakeLists.txt: it names targets of every layer.
include(CMakePackageConfigHelpers)

set(TOUCHLINE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Touchline)
set(TOUCHLINE_LCM_TYPES_DIR ${CMAKE_INSTALL_DATADIR}/touchline/lcm_types)

# The installed programs keep the run path to the libraries they were linked with outside the
# system's (libpython of a pyenv, for example), as the built ones have it.
set_target_properties(sim_world robot_shim touchline_match PROPERTIES INSTALL_RPATH_USE_LINK_PATH ON)
install(TARGETS sim_world robot_shim touchline_match RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT programs)
# What the installed programs (bridge/apps/install_dirs.hpp) and Python tools read instead of the
# source tree's folders.
set(TOUCHLINE_SHARE_DIR ${CMAKE_INSTALL_DATADIR}/touchline)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/config ${PROJECT_SOURCE_DIR}/behaviour_py DESTINATION ${TOUCHLINE_SHARE_DIR}
  COMPONENT programs PATTERN __pycache__ EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/viewer/static DESTINATION ${TOUCHLINE_SHARE_DIR}/viewer COMPONENT programs)
install(FILES ${PROJECT_SOURCE_DIR}/VERSION DESTINATION ${TOUCHLINE_SHARE_DIR} COMPONENT programs)

install(TARGETS touchline_robot_api EXPORT TouchlineTargets COMPONENT development)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/robot_api/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  COMPONENT development)
# Our C++ skills and team (behaviour/registry.hpp: make_behaviour by name) for a team's own
# library to build on: touchline::behaviour_cpp, a static library (position-independent, so
# it links into a plugin). touchline_warnings goes along only as its link-time name.
set_target_properties(touchline_warnings PROPERTIES EXPORT_NAME warnings)
install(TARGETS touchline_behaviour_cpp touchline_warnings EXPORT TouchlineTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/behaviour_cpp/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  COMPONENT development)

# The message types, for a team's own tools on the bus: the definitions, and lcm-gen's C++
# (include/touchline/*_t.hpp, beside the robot API's folder) and Python.
file(GLOB TOUCHLINE_LCM_FILES ${PROJECT_SOURCE_DIR}/lcm_types/*.lcm)
install(FILES ${TOUCHLINE_LCM_FILES} DESTINATION ${TOUCHLINE_LCM_TYPES_DIR} COMPONENT lcm_types)
install(DIRECTORY ${PROJECT_BINARY_DIR}/lcm_types/gen/cpp/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT lcm_types)
install(DIRECTORY ${PROJECT_BINARY_DIR}/lcm_types/gen/python/ DESTINATION ${TOUCHLINE_LCM_TYPES_DIR}/python
  COMPONENT lcm_types)
if(TOUCHLINE_LCM_JAR)
  install(FILES ${TOUCHLINE_LCM_JAR} DESTINATION ${CMAKE_INSTALL_DATADIR}/java COMPONENT java)
endif()

install(EXPORT TouchlineTargets NAMESPACE touchline:: DESTINATION ${TOUCHLINE_CMAKE_DIR} COMPONENT development)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/TouchlineConfig.cmake.in
  ${PROJECT_BINARY_DIR}/TouchlineConfig.cmake INSTALL_DESTINATION ${TOUCHLINE_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_BINDIR CMAKE_INSTALL_INCLUDEDIR TOUCHLINE_LCM_TYPES_DIR)
# 0.x: a minor version may change the robot API, so only the same major.minor is compatible
# (plugin.hpp's ABI check refuses a stale library at run time as well).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/TouchlineConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/TouchlineConfig.cmake ${PROJECT_BINARY_DIR}/TouchlineConfigVersion.cmake
  DESTINATION ${TOUCHLINE_CMAKE_DIR} COMPONENT development)

# pip install . (scikit-build-core sets SKBUILD and the wheel's folders; its prefix is the wheel's
# data folder, so everything above lands in the environment's bin/, share/, include/ and lib/):
# the Python packages into site-packages. Excluded from a plain cmake --install, which leaves
# Python to the source tree (and its build folder may keep a pip build's SKBUILD values).
if(SKBUILD)
  set(py ${SKBUILD_PLATLIB_DIR})
  set(only_pip COMPONENT python EXCLUDE_FROM_ALL)
  install(DIRECTORY ${PROJECT_BINARY_DIR}/lcm_types/gen/python/touchline DESTINATION ${py} ${only_pip})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/viewer/touchline_viewer ${PROJECT_SOURCE_DIR}/learning/touchline_rl
    DESTINATION ${py} ${only_pip} PATTERN __pycache__ EXCLUDE)
  install(TARGETS robot_python_extension touchline_sim_extension LIBRARY DESTINATION ${py} ${only_pip})
  # tools/ as the package touchline_tools (console_scripts.py runs each tool as its script),
  # and the one resolver the tools, the viewer and learning share as a top-level module.
  file(GLOB tools_py CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/*.py)
  list(REMOVE_ITEM tools_py ${PROJECT_SOURCE_DIR}/tools/touchline_paths.py)
  install(FILES ${tools_py} DESTINATION ${py}/touchline_tools ${only_pip})
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/touchline_tools_init.py DESTINATION ${py}/touchline_tools
    RENAME __init__.py ${only_pip})
  install(PROGRAMS ${PROJECT_SOURCE_DIR}/tools/netns DESTINATION ${py}/touchline_tools ${only_pip})
  install(FILES ${PROJECT_SOURCE_DIR}/tools/touchline_paths.py DESTINATION ${py} ${only_pip})
endif()
