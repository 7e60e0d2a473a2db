# cmake --install: what a team needs to build and play its own C++ behaviour outside this tree
# (examples/behaviour_plugin): the programs in bin/; the robot API's headers (plugin.hpp
# among them) as the exported target touchline::robot_api; the LCM types (.lcm files and the
# C++ headers lcm-gen made of them); and TouchlineConfig.cmake, so find_package(Touchline).
# Included last by the top CMakeLists.txt: it names targets of every layer.
include(CMakePackageConfigHelpers)

set(TOUCHLINE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Touchline)
set(TOUCHLINE_LCM_TYPES_DIR ${CMAKE_INSTALL_DATADIR}/touchline/lcm_types)

# The installed programs keep the run path to the libraries they were linked with outside the
# system's (libpython of a pyenv, for example), as the built ones have it.
set_target_properties(sim_world robot_shim touchline_match PROPERTIES INSTALL_RPATH_USE_LINK_PATH ON)
install(TARGETS sim_world robot_shim touchline_match RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(TARGETS touchline_robot_api EXPORT TouchlineTargets)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/robot_api/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

# The message types, for a team's own tools on the bus: the definitions, and lcm-gen's C++
# (include/touchline/*_t.hpp, beside the robot API's folder) and Python.
file(GLOB TOUCHLINE_LCM_FILES ${PROJECT_SOURCE_DIR}/lcm_types/*.lcm)
install(FILES ${TOUCHLINE_LCM_FILES} DESTINATION ${TOUCHLINE_LCM_TYPES_DIR})
install(DIRECTORY ${PROJECT_BINARY_DIR}/lcm_types/gen/cpp/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_BINARY_DIR}/lcm_types/gen/python/ DESTINATION ${TOUCHLINE_LCM_TYPES_DIR}/python)
if(TOUCHLINE_LCM_JAR)
  install(FILES ${TOUCHLINE_LCM_JAR} DESTINATION ${CMAKE_INSTALL_DATADIR}/java)
endif()

install(EXPORT TouchlineTargets NAMESPACE touchline:: DESTINATION ${TOUCHLINE_CMAKE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/TouchlineConfig.cmake.in
  ${PROJECT_BINARY_DIR}/TouchlineConfig.cmake INSTALL_DESTINATION ${TOUCHLINE_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_BINDIR CMAKE_INSTALL_INCLUDEDIR TOUCHLINE_LCM_TYPES_DIR)
# 0.x: a minor version may change the robot API, so only the same major.minor is compatible
# (plugin.hpp's ABI check refuses a stale library at run time as well).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/TouchlineConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/TouchlineConfig.cmake ${PROJECT_BINARY_DIR}/TouchlineConfigVersion.cmake
  DESTINATION ${TOUCHLINE_CMAKE_DIR})
