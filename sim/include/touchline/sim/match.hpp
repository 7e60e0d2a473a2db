#pragma once
// A match without transport: the world, the roster of robots, the referee, the camera and
// sonar models, and the camera-frame clock. Each frame the match hands out a SenseFrame,
// takes the robots' RobotActs, steps the world through the frame's 3-4 motion ticks and
// lets the referee judge. sim_world drives it over LCM; tests and the in-process mode
// call it directly. Every random draw is keyed on the seed, the frame and the robots it
// concerns (touchline/random.hpp), so a seed fixes the match whatever order the robots'
// answers arrive in.
#include <cstdint>
#include <array>
#include <deque>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "touchline/frame.hpp"
#include "touchline/sim/config.hpp"
#include "touchline/sim/match_event.hpp"
#include "touchline/sim/perception.hpp"
#include "touchline/sim/referee.hpp"
#include "touchline/sim/roster.hpp"
#include "touchline/sim/world.hpp"

namespace touchline::sim {

/// Ground truth at the end of a frame.
struct TruthFrame {
  int64_t utime = 0; ///< simulated time at the end of the frame, microseconds
  int64_t frame = 0; ///< the frame just completed
  BallTruth ball;
  struct Robot {
    RobotTruth truth;
    bool active = true;
    bool penalised = false;
    bool fallen = false;
    float head_yaw_rad = 0, head_pitch_rad = 0;
    int32_t chest_led = 0; ///< 0xRRGGBB, as the robot last asked
  };
  GameInfo game;
  std::vector<Robot> robots; ///< sorted by (team, player)
};

enum class ActOutcome {
  kApplied,     ///< taken for this frame
  kRejoined,    ///< taken, and the robot is active again after a timeout
  kStale,       ///< for an earlier frame in lockstep: ignored
  kFuture,      ///< for a frame not yet sensed: ignored (no robot can answer it)
  kDuplicate,   ///< a second answer to a frame already answered: ignored
  kImplausible, ///< moves a foot or the head further than a body can (see kMaxFoot*): ignored
  kUnknown,     ///< from a robot or instance that has not joined: ignored
};

/// Foot motion beyond these in one 10 ms tick is no robot's: an act asking for it is
/// refused. Ten times a kick's peak swing (1.6 m/s, config/kick.ini) and a fast turn.
constexpr float kMaxFootTravelPerTickMm = 100.f;
constexpr float kMaxFootTurnPerTickRad = 0.5f;
/// Head angles beyond these (either way) are no robot's.
constexpr float kMaxHeadAngleRad = 3.1416f;

/// Whether every foot motion and head angle of `act` is within the limits above.
bool plausible(const RobotAct& act);

class Match {
 public:
  explicit Match(const WorldConfig& config, uint64_t seed = 1);

  /// A shim asks to play `id`. Before start() accepted robots wait off the field; after
  /// it, a new robot is placed at its initial pose at once.
  JoinReply join(RobotId id, int64_t instance, int pid);
  /// Puts every joined robot on the field in (team, player) order (deterministic
  /// whatever order they joined in) and the ball on the centre spot.
  void start();
  bool started() const { return started_; }

  /// What the robots sense at the start of the current frame. Not const: it hands out the
  /// team messages that have arrived (call it once per frame).
  SenseFrame sense();
  /// Robots that must answer the current frame.
  std::vector<RobotId> active_robots() const;
  /// Every robot on the field, active or not, in (team, player) order.
  std::vector<RobotId> robots_on_field() const;

  /// Takes a robot's answer. `accept_late`: free-running mode, where an answer for an
  /// earlier frame still moves the robot, late.
  ActOutcome apply(const RobotAct& act, int64_t instance, bool accept_late = false);
  /// The robot did not answer in time: it stands still and is inactive until it answers;
  /// an answer it gave this frame is dropped (the frame counts as missed).
  void time_out(RobotId id);

  /// Steps the world through the current frame's motion ticks (robots that may not move
  /// stand: penalised, fallen, or the game in INITIAL/SET/FINISHED), lets the referee
  /// judge, carries out its decisions; the next frame begins.
  void advance();
  /// The game from an external GameController instead of the built-in referee (configure
  /// rules.referee = false): from now on game() is `game`, and robots in `penalised`, or
  /// any robot outside READY and PLAYING, stand still where they are.
  void set_external_game(const GameInfo& game, const std::set<RobotId>& penalised);
  /// Events since the last call, oldest first.
  std::vector<MatchEvent> take_events();
  GameInfo game() const;
  TruthFrame truth() const;

  bool finished() const;
  int64_t frame() const { return frame_; }
  const std::optional<Referee>& referee() const { return referee_; }
  const TeamComm& comm() const { return comm_; }
  int64_t utime() const { return frame_start_utime(frame_); }
  const Roster& roster() const { return roster_; }
  const World& world() const { return world_; }
  World& world() { return world_; }
  const WorldConfig& config() const { return config_; }
  uint64_t seed() const { return seed_; }

 private:
  struct OnField {
    int world_index = 0;
    float head_yaw_rad = 0, head_pitch_rad = 0;
    int32_t chest_led = 0; ///< 0xRRGGBB, from the robot's latest answer
    std::deque<TickMotion> pending; ///< motions not yet stepped, oldest first
    int64_t fallen_until_utime = -1; ///< lying on the ground until then
    std::vector<RobotId> stopped_by; ///< lost ball contests this frame to these: no step towards them
    bool placed = false;             ///< put down by the referee since the last sense
    /// The body's heading when the last frame began: the gyro's turn is from there.
    std::optional<float> frame_start_heading_rad;
  };
  void place(RobotId id);
  bool may_move(RobotId id, const OnField& robot) const;
  /// Whether `motion` steps `robot` towards a robot it lost a ball contest to this frame.
  bool steps_towards_winner(const OnField& robot, const TickMotion& motion) const;
  bool fallen(const OnField& robot) const { return robot.fallen_until_utime > utime(); }
  bool penalised(RobotId id) const;
  void judge();
  void carry_out(const RefereeDecision& decision);
  void fall_after_push(RobotId pusher);
  void record_localisation_error(const RobotAct& act, Member& member) const;
  std::vector<Viewer> viewers() const;

  WorldConfig config_;
  uint64_t seed_; ///< keys the falls' draws; the camera and the radio key theirs on it too
  World world_;
  Roster roster_;
  Perception perception_;
  TeamComm comm_;
  std::optional<Referee> referee_;
  std::optional<GameInfo> external_game_;   ///< from the GameController, when it decides
  std::set<RobotId> external_penalised_;
  std::vector<MatchEvent> events_;
  std::map<RobotId, OnField> on_field_;
  std::array<bool, 2> touched_by_team_{{false, false}}; ///< feet of the team began touching the ball this frame
  int64_t frame_ = 0;
  bool started_ = false;
};

} // namespace touchline::sim
