# The rUNSWift profile's first step (issue #19): a wrong -DTOUCHLINE_RUNSWIFT_DIR fails the
# configure at once with one line naming the path and what is wrong, before anything of
# theirs is compiled. Needs TOUCHLINE_RUNSWIFT_SOURCES (their files the profile builds,
# relative to their robot/ folder: runswift/CMakeLists.txt).

# Their files the profile compiles, and what our adapter and compatibility library include
# of theirs, with their bundled Eigen.
list(TRANSFORM TOUCHLINE_RUNSWIFT_SOURCES PREPEND "robot/" OUTPUT_VARIABLE _rs_needed)
list(APPEND _rs_needed
  robot/motion/generator/Walk2014Generator.hpp
  robot/motion/generator/BodyModel.hpp
  robot/motion/MotionDefs.hpp
  robot/perception/kinematics/Kinematics.hpp
  robot/types/ActionCommand.hpp
  robot/types/MotionDebugInfo.hpp
  robot/types/Odometry.hpp
  robot/types/SensorValues.hpp
  robot/utils/Logger.hpp
  robot/utils/options.hpp
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
message(STATUS "rUNSWift walk profile: building their walk from ${_rs_dir}")
