#pragma once
// The Blackboard: sub-blackboards that modules share. Only adapters write it; behaviour
// code receives it as const. Units: mm, rad; times in simulated microseconds.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "touchline/robot_api/action_command.hpp"
#include "touchline/robot_api/geometry.hpp"

namespace touchline::api {

/// Written by the MotionAdapter (every 10 ms motion tick).
struct MotionBlackboard {
  AbsCoord odometry;                 ///< dead-reckoned body pose since the robot started
  ActionCommand::Body active;        ///< the body command being executed
  float headYaw = 0, headPitch = 0;  ///< rad, measured
  bool standing = true;              ///< the walk is not stepping
  bool fallen = false;               ///< lying on the ground (it gets up by itself)
  int kickPhase = 0;                 ///< the kick or dribble running: 0 none, 1 prepare, 2 swing, 3 recover
  int64_t ticks = 0;                 ///< motion ticks run
  float sonarLeft = 1, sonarRight = 1; ///< nearest obstacle, fraction of sonarRange_mm (1: none within it)
  float sonarRange_mm = 1000;        ///< the sonars' range, mm (the world's [sonar] range_mm)
  /// Where another robot touches this one, by its bearing from the heading (+ left): the foot
  /// bumpers ahead (0 to 45 deg left, 0 to 45 deg right), the arms beside (45 to 135 deg) and
  /// behind (beyond 135 deg).
  bool touchFrontLeft = false, touchFrontRight = false, touchLeft = false, touchRight = false, touchBack = false;
};

/// Written by the localisation adapter (every perception frame).
struct LocalisationBlackboard {
  AbsCoord robotPos;        ///< where the robot believes it is (field frame)
  AbsCoord ballPos;         ///< absolute ball estimate, theta unused
  RRCoord ballPosRR;        ///< ball relative to the robot
  int ballLostCount = 1 << 20; ///< frames since the ball was last seen (huge: never seen)
  AbsCoord teamBallPos;     ///< the team's shared ball estimate
  AbsCoord ballVel;         ///< ball velocity estimate, field frame, mm/s (theta unused)
  /// Row-major covariance of robotPos (x mm, y mm, theta rad): mm^2, mm rad, rad^2. Zero
  /// when the pose is the truth (perfect localisation).
  std::array<float, 9> robotPosCovariance{};
  /// Row-major covariance of ballPos (x, y), mm^2.
  std::array<float, 4> ballPosCovariance{};
};

/// Written by the vision adapter (every perception frame): what the camera saw.
/// A goal post or a robot the camera saw this frame.
struct SeenObject {
  RRCoord rr;
  int id = 0;               ///< posts: 0, 1 our goal's left and right seen from the field centre, 2, 3
                            ///< the opponent goal's; robots: the player number
  bool teammate = false;    ///< robots: one of ours
};

struct VisionBlackboard {
  bool ballSeen = false;
  RRCoord ball;
  int64_t frame = 0;        ///< camera frame index
  std::vector<SeenObject> posts;  ///< goal posts seen this frame
  std::vector<SeenObject> robots; ///< robots seen this frame
};

/// The GameController's states (STANDBY: SPL 2023 on, between INITIAL and READY; robots stand).
enum class GameState : int8_t { INITIAL = 0, READY = 1, SET = 2, PLAYING = 3, FINISHED = 4, STANDBY = 5 };

/// The GameController's set plays (SPL 2020 on), during PLAYING.
enum class SetPlay : int8_t {
  NONE = 0,
  GOAL_KICK = 1,
  PUSHING_FREE_KICK = 2,
  CORNER_KICK = 3,
  KICK_IN = 4,
  PENALTY_KICK = 5,
};

/// Written by the game-controller adapter.
struct GameControllerBlackboard {
  GameState state = GameState::INITIAL;
  int team = 0;             ///< our team index, 0 or 1
  int playerNumber = 1;     ///< 1..7
  bool penalised = false;
  std::array<int, 2> score{{0, 0}};
  int secsRemaining = 0;
  bool firstHalf = true;
  int kickOffTeam = 0;      ///< team index (0 or 1) that kicks off
  SetPlay setPlay = SetPlay::NONE; ///< the set play under way
  int setPlayTeam = -1;            ///< the team index taking it (0 or 1; ours is `team`), -1: none
  /// The last ball put back after it left the field, as the SPL 2011 GameController tells it
  /// (rules without set plays): the team index whose touch put it out (ours is `team`; -1:
  /// not known), and whole seconds since it was put back (-1: none yet).
  int dropInTeam = -1;
  int dropInTime = -1;
};

/// A teammate's last message, written by the receiver adapter.
struct TeamMessage {
  int playerNumber = 0;
  int64_t utime = 0;          ///< simulated time it was sent, microseconds
  std::vector<uint8_t> data;
};

/// The latest message from each teammate that got through, by player number.
struct ReceiverBlackboard {
  std::vector<TeamMessage> messages;
};

/// Written by the behaviour adapter: the request the behaviour returned this frame.
struct BehaviourBlackboard {
  ActionCommand::All request;
  std::string skill;       ///< name of the running behaviour
};

struct Blackboard {
  int64_t utime = 0;       ///< simulated time of this perception frame, microseconds
  MotionBlackboard motion;
  LocalisationBlackboard localisation;
  VisionBlackboard vision;
  GameControllerBlackboard gameController;
  ReceiverBlackboard receiver;
  BehaviourBlackboard behaviour;
};

} // namespace touchline::api
