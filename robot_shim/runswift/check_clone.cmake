# The rUNSWift profile's first step (issue #19), run straight after project() so that a wrong
# path fails the configure at once, before anything else is looked for: one line naming the
# path and what is missing. Sets TOUCHLINE_RUNSWIFT_SOURCES (their files the profile builds,
# absolute) and TOUCHLINE_RUNSWIFT_ROBOT_DIR (their include root).

# Their files the walk profile compiles, by path inside their clone.
set(_rs_sources
  robot/motion/generator/Walk2014Generator.cpp
  robot/motion/generator/BodyModel.cpp
  robot/motion/MotionOdometry.cpp
  robot/perception/kinematics/Kinematics.cpp
  robot/perception/kinematics/Parameters.cpp
  robot/perception/kinematics/Pose.cpp)
# And what our adapter and compatibility library include of theirs, with their bundled Eigen.
set(_rs_needed ${_rs_sources}
  robot/motion/generator/Walk2014Generator.hpp
  robot/motion/generator/BodyModel.hpp
  robot/motion/MotionDefs.hpp
  robot/perception/kinematics/Kinematics.hpp
  robot/types/ActionCommand.hpp
  robot/types/SensorValues.hpp
  robot/utils/body.hpp
  robot/utils/Logger.hpp
  robot/Eigen/Core)

# A leading space keeps CMake from wrapping the message: it stays one line.
set(_rs_dir "${TOUCHLINE_RUNSWIFT_DIR}")
if(NOT EXISTS "${_rs_dir}")
  message(FATAL_ERROR " TOUCHLINE_RUNSWIFT_DIR=${_rs_dir}: no such directory")
elseif(NOT IS_DIRECTORY "${_rs_dir}")
  message(FATAL_ERROR " TOUCHLINE_RUNSWIFT_DIR=${_rs_dir}: not a directory (give the top folder of a rUNSWift clone)")
elseif(EXISTS "${_rs_dir}/motion/generator/Walk2014Generator.cpp")
  get_filename_component(_rs_parent "${_rs_dir}" DIRECTORY)
  message(FATAL_ERROR " TOUCHLINE_RUNSWIFT_DIR=${_rs_dir}: this is their robot/ folder; give the clone's top folder (${_rs_parent})")
endif()
set(_rs_missing "")
foreach(_rs_file IN LISTS _rs_needed)
  if(NOT EXISTS "${_rs_dir}/${_rs_file}")
    list(APPEND _rs_missing "${_rs_file}")
  endif()
endforeach()
list(LENGTH _rs_missing _rs_count)
list(LENGTH _rs_needed _rs_total)
if(_rs_count EQUAL _rs_total)
  message(FATAL_ERROR " TOUCHLINE_RUNSWIFT_DIR=${_rs_dir}: not a rUNSWift clone (no robot/motion/generator/Walk2014Generator.cpp)")
elseif(_rs_count GREATER 0)
  list(GET _rs_missing 0 _rs_first)
  math(EXPR _rs_more "${_rs_count} - 1")
  set(_rs_tail "")
  if(_rs_more GREATER 0)
    set(_rs_tail " (and ${_rs_more} more of the files the walk needs)")
  endif()
  message(FATAL_ERROR " TOUCHLINE_RUNSWIFT_DIR=${_rs_dir}: ${_rs_first} is missing${_rs_tail}")
endif()

set(TOUCHLINE_RUNSWIFT_ROBOT_DIR "${_rs_dir}/robot")
list(TRANSFORM _rs_sources PREPEND "${_rs_dir}/" OUTPUT_VARIABLE TOUCHLINE_RUNSWIFT_SOURCES)
message(STATUS "rUNSWift walk profile: building their walk from ${_rs_dir}")
