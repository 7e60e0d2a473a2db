#pragma once
// The rUNSWift walk engine (robot_shim --walk-engine runswift): their Walk2014Generator,
// built from the user's clone (cmake -DTOUCHLINE_RUNSWIFT_DIR=...), behind our seam. This
// header is ours and includes nothing of theirs: only runswift_walk.cpp does.
#include <memory>
#include <string>

#include "touchline/robot/walk_engine.hpp"

namespace touchline::robot {

struct RunswiftWalkDef {
  /// One of their option files (e.g. <clone>/image/home/nao/data/runswift.cfg): the walk's
  /// keys it sets override the defaults; "" for the defaults alone.
  std::string config_file;
};

/// Throws touchline::ConfigError naming the file for an option file that does not parse.
std::unique_ptr<WalkEngine> make_runswift_walk(const RunswiftWalkDef& def);

} // namespace touchline::robot
