#pragma once
// robot_shim's LCM adapter: joins the match as one robot, then answers every sense_t
// frame with the act_t that the Robot computes. The robot code sees simulated time only.
#include <cstdint>
#include <spdlog/fwd.h>
#include <memory>
#include <string>

#include "touchline/lcm/bus.hpp"
#include "touchline/lcm/codec.hpp"
#include "touchline/lcm/match_key.hpp"
#include "touchline/robot/robot.hpp"

namespace touchline::transport {

struct RobotNodeDef {
  std::string lcm_url = kDefaultUrl;
  MatchKey key;                ///< the match secret every message is authenticated with
  double join_timeout_s = 60;  ///< wall seconds to wait for sim_world to accept the join
  double world_timeout_s = 30; ///< wall seconds of silence from sim_world before giving up
  int64_t instance = 0;        ///< random id of this process (0: pick one)
  int snapshot_every = 30;     ///< publish a Blackboard snapshot every N frames the behaviour runs (0: never)
};

/// Why run_robot returned.
enum class RobotExit {
  kMatchOver,   ///< the world said FINISHED
  kRejected,    ///< the world refused the join (reason in the log)
  kNoWorld,     ///< no sim_world answered, or it fell silent
  kInterrupted, ///< SIGINT/SIGTERM
};

/// One robot on a match bus: asks to join, then answers every sense the bus delivers with
/// the act the Robot computes. run() is the shim's loop; on a bus driven by someone else
/// (the world's loop on a shared memq:// bus, in tests) the handlers alone play the robot.
class RobotNode {
 public:
  RobotNode(robot::Robot& robot, const RobotNodeDef& def, Bus& bus, spdlog::logger& log);
  ~RobotNode();
  /// Joins (asking again every 250 ms) and plays until the match is over.
  RobotExit run();
  /// Sends one request to play.
  void request_join();
  bool joined() const;
  /// The world said FINISHED.
  bool match_over() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

/// Opens the bus at def.lcm_url and runs a RobotNode on it. Messages for the user go to `log`:
/// why it gave up at error, malformed messages at warn.
RobotExit run_robot(robot::Robot& robot, const RobotNodeDef& def, spdlog::logger& log);

/// Asks a running run_robot to return (signal-safe).
void request_robot_stop();

} // namespace touchline::transport
