#pragma once
// The contract between the world and the robots, free of any transport: what a robot
// senses at the start of a 30 Hz camera frame and what it answers for that frame.
// sim/ produces SenseFrame and consumes RobotAct; robot_shim/ does the reverse; the LCM
// adapters and the in-process runner only carry these values.
#include <array>
#include <cstdint>
#include <vector>

namespace touchline {

/// A pose on the field (field frame: origin at the centre, +x towards the goal team 0
/// attacks, +y left) or in a robot's odometry frame.
struct Pose2D {
  float x_mm = 0;      ///< millimetres
  float y_mm = 0;      ///< millimetres
  float theta_rad = 0; ///< radians, counter-clockwise from +x
};

/// How one foot moves during one motion tick, in the body frame at the start of the
/// tick (body = midpoint of the feet, heading mean_heading of the feet's (angles.hpp),
/// +x forward, +y left).
struct FootMotion {
  float dx_mm = 0;      ///< forward, millimetres
  float dy_mm = 0;      ///< left, millimetres
  float dtheta_rad = 0; ///< counter-clockwise, radians
};

/// How both feet of one robot move during one 10 ms motion tick: what the robot's motion
/// thread makes, RobotAct carries and the world steps, unchanged all the way.
struct TickMotion {
  FootMotion left;
  FootMotion right;
};

struct RobotId {
  int team = 0;   ///< 0 or 1
  int player = 1; ///< 1..kMaxTeamSize
  friend bool operator==(RobotId a, RobotId b) { return a.team == b.team && a.player == b.player; }
  friend bool operator!=(RobotId a, RobotId b) { return !(a == b); }
  friend bool operator<(RobotId a, RobotId b) {
    return a.team != b.team ? a.team < b.team : a.player < b.player;
  }
};

constexpr int kMaxTeamSize = 7;
/// Longest field length or width a world config may give (the robots' maps agree): twice
/// the largest RoboCup field (AdultSize, 14 x 9 m), and short enough that the world's
/// longest wall stays within what Box2D handles (sim/src/config.cpp).
constexpr float kMaxFieldSide_mm = 30000.f;
constexpr int kMaxTicksPerFrame = 4;
constexpr int64_t kMotionTickUs = 10000; ///< 100 Hz motion
constexpr int kFramesPerCycle = 3;       ///< 3 camera frames (30 Hz) ...
constexpr int kTicksPerCycle = 10;       ///< ... span exactly 10 motion ticks (100 ms)

/// One motion tick in seconds, for rates (mm/s x tick = mm): 0.01f, the same float however
/// it is derived (kMotionTickUs / 1e6f and kMotionTickUs * 1e-6f agree).
constexpr float kMotionTick_s = static_cast<float>(kMotionTickUs) / 1e6f;
/// Camera frames per simulated second: kFramesPerCycle frames span kTicksPerCycle ticks.
constexpr int kFramesPerSecond = static_cast<int>(kFramesPerCycle * 1000000 / (kTicksPerCycle * kMotionTickUs));
static_assert(kFramesPerSecond * kTicksPerCycle * kMotionTickUs == kFramesPerCycle * 1000000,
              "a whole number of camera frames a second");

/// Index of the first motion tick of camera frame `frame`.
constexpr int64_t first_tick_of_frame(int64_t frame) {
  return frame * kTicksPerCycle / kFramesPerCycle;
}
/// Motion ticks in camera frame `frame`: 3, 3, 4, 3, 3, 4, ...
constexpr int ticks_in_frame(int64_t frame) {
  return static_cast<int>(first_tick_of_frame(frame + 1) - first_tick_of_frame(frame));
}
/// Simulated time at the start of camera frame `frame`, microseconds.
constexpr int64_t frame_start_utime(int64_t frame) {
  return first_tick_of_frame(frame) * kMotionTickUs;
}

/// Game states, as the GameController sends them (STANDBY: SPL 2022 and later, between
/// INITIAL and READY, robots standing while they wait for the referee's signal).
enum class GameState : int8_t { kInitial = 0, kReady = 1, kSet = 2, kPlaying = 3, kFinished = 4, kStandby = 5 };

/// "INITIAL", "READY", ...: the GameController's names.
inline const char* to_string(GameState state) {
  switch (state) {
    case GameState::kInitial: return "INITIAL";
    case GameState::kReady: return "READY";
    case GameState::kSet: return "SET";
    case GameState::kPlaying: return "PLAYING";
    case GameState::kFinished: return "FINISHED";
    case GameState::kStandby: return "STANDBY";
  }
  return "?";
}

/// Set plays during PLAYING (SPL 2020 and later), with the GameController's numbers: the
/// kicking team may play the ball first; it ends when that team touches the ball or after
/// the rules' set play time.
enum class SetPlay : int8_t {
  kNone = 0,
  kGoalKick = 1,
  kPushingFreeKick = 2,
  kCornerKick = 3,
  kKickIn = 4,
  kPenaltyKick = 5,
};

/// "goal kick", "kick-in", ...
inline const char* to_string(SetPlay set_play) {
  switch (set_play) {
    case SetPlay::kNone: return "none";
    case SetPlay::kGoalKick: return "goal kick";
    case SetPlay::kPushingFreeKick: return "pushing free kick";
    case SetPlay::kCornerKick: return "corner kick";
    case SetPlay::kKickIn: return "kick-in";
    case SetPlay::kPenaltyKick: return "penalty kick";
  }
  return "?";
}

/// What the camera can report. Landmark ids: goal posts 0..3 (team 0's goal left, right
/// as seen from the field centre, then team 1's), field corners 0..3 (counter-clockwise
/// from (-x, -y)), centre-line ends 0 (-y) and 1 (+y), penalty marks 0 (team 0's) and 1.
enum class ObjectKind : int8_t {
  kBall = 0,
  kGoalPost = 1,
  kFieldCorner = 2,
  kCentreLineEnd = 3,
  kPenaltyMark = 4,
  kTeammate = 5,
  kOpponent = 6,
};

/// One thing the camera saw this frame, in the robot's frame (after noise).
struct Observation {
  ObjectKind kind = ObjectKind::kBall;
  int id = 0;             ///< which landmark (see ObjectKind); player number for robots
  float distance_mm = 0;  ///< from the body centre
  float heading_rad = 0;  ///< from the body heading, + left
  float image_x = 0;      ///< Algorithm 2.3's image coordinate, 0..1 across the view
};

/// A team message on its way: who sent it, when, and its bytes.
struct TeamMessageFrame {
  int player = 0;          ///< the sender's player number (same team as the recipient)
  int64_t sent_utime = 0;  ///< simulated time it was sent, microseconds
  std::vector<uint8_t> data;
};

/// The referee's view of the game, as the GameController sends it.
struct GameInfo {
  GameState state = GameState::kPlaying;
  int secs_remaining = 0;          ///< of the current half
  bool first_half = true;
  int kickoff_team = 0;
  std::array<int, 2> score{{0, 0}};
  SetPlay set_play = SetPlay::kNone; ///< the set play under way (PLAYING only)
  int set_play_team = -1;            ///< the team taking it, 0 or 1; -1 with kNone
  /// The last ball put back after leaving the field (SPL 2011, without set plays: the
  /// GameController's dropInTeam and dropInTime): the team whose touch put it out, 0 or 1
  /// (-1: not known), and whole seconds since (-1: none yet).
  int drop_in_team = -1;
  int drop_in_s = -1;
};

/// Which sides of a robot other robots touch: where a NAO feels a contact, its two foot
/// bumpers at the front and its arms at the sides and back (B-Human's ArmContactModel reads
/// an arm pushed off its path). A sector's bearing is from the robot's heading, + left.
struct Touch {
  bool front_left = false;  ///< 0 to 45 deg: the left foot bumper
  bool front_right = false; ///< -45 to 0 deg: the right foot bumper
  bool left = false;        ///< 45 to 135 deg: the left arm
  bool right = false;       ///< -135 to -45 deg: the right arm
  bool back = false;        ///< beyond 135 deg either way: an arm pushed forward
  bool any() const { return front_left || front_right || left || right || back; }
};

/// What one robot senses at the start of a frame.
struct RobotSense {
  RobotId id;
  bool active = true; ///< false while the world treats the robot as crashed
  Pose2D truth;       ///< ground-truth body pose, field frame
  float ball_x_mm = 0, ball_y_mm = 0; ///< ground-truth ball, field frame
  std::vector<Observation> seen;      ///< the camera's observations this frame
  float sonar_left = 1, sonar_right = 1; ///< nearest obstacle, fraction of the sonar range (1: none)
  Touch touch;                        ///< where other robots touch it this frame
  float gyro_turn_rad = 0;            ///< the inertial unit's yaw change since the last frame, + anticlockwise
                                      ///< (the body's true turn, pushes included, plus gyro noise)
  bool penalised = false;             ///< off the field, serving a penalty
  bool fallen = false;                ///< lying on the ground (getting up takes time)
  std::vector<TeamMessageFrame> messages; ///< teammates' messages arriving this frame
  bool placed = false;                ///< the referee put the robot down since the last frame (robots
                                      ///< know where the rules place them: localisation restarts there)
};

/// World -> robots, once per camera frame.
struct SenseFrame {
  int64_t utime = 0;  ///< simulated time at the frame start, microseconds
  int64_t frame = 0;  ///< camera frame index
  int motion_ticks = 3;
  GameInfo game;              ///< the referee's view, as the GameController sends it
  std::vector<RobotSense> robots;

  const RobotSense* find(RobotId id) const {
    for (const auto& r : robots)
      if (r.id == id) return &r;
    return nullptr;
  }
};

/// Robot -> world: the answer to one frame.
struct RobotAct {
  RobotId id;
  int64_t frame = 0;
  int motion_ticks = 0; ///< entries used in ticks
  std::array<TickMotion, kMaxTicksPerFrame> ticks{};
  float head_yaw_rad = 0;   ///< + left
  float head_pitch_rad = 0; ///< + down
  int32_t leds = 0;         ///< chest LED, 0xRRGGBB (the world shows it in its truth)
  int64_t behaviour_cpu_us = 0; ///< CPU time of this frame's behaviour tick (thread CPU clock)
  Pose2D localised;             ///< where the robot believes it is (field frame)
  /// What else it believes, for the viewer (the world reads none of it): localised's position
  /// covariance xx, xy, yy (mm^2; a half turn into the field frame leaves it as it is), ...
  std::array<float, 3> localised_cov_mm2{};
  float ball_x_mm = 0, ball_y_mm = 0; ///< ... the ball (field frame), ...
  int32_t ball_lost_frames = 0;       ///< ... and frames since it last saw the ball
  std::vector<uint8_t> team_message; ///< to the teammates (empty: none this frame)
};

} // namespace touchline
