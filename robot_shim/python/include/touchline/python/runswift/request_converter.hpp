#pragma once
// Their BehaviourRequest -> Touchline's ActionCommand, in their units and signs:
// - WALK: forward, left (mm/s) and turn (rad/s) as their walk reads them: limited to the
//   ellipsoid of their walk's maxima (300 mm/s, 200 mm/s, 2 rad/s), which `speed` in
//   [0, 1] scales from 66 % to 100 %; then Touchline's walk (config/walk.ini) applies its
//   own limits. All zero: stand (their stand() is such a walk). useShuffle, the arms and
//   blocking change how the feet move, not where: no effect.
// - KICK: foot, power [0, 1], turn (the kick's direction, rad, + left) -> our KICK with
//   bend = turn. TURN_DRIBBLE: our DRIBBLE the same way. STAND, NONE: stand.
// - Head: yaw (+ left), pitch (+ down), isRelative, yawSpeed/pitchSpeed: the same.
// - LEDs: the chest button's colour -> the chest LED (0xRRGGBB); eyes, ears, feet unseen.
// - stiffen: the simulated robot is always stiff: no effect.
// - Any other action (dives, signals, sit, get-ups, ...): the robot stands for the
//   action's duration on the robot (their key frames' total), whatever is asked meanwhile,
//   and the first request of each such action logs one line naming it.
// A value no robot could execute (NaN, an action type or foot out of range) is a
// RequestError naming the field: the robot stands with the error LED, as for an exception.
#include <cstdint>
#include <functional>
#include <set>
#include <string>

#include "touchline/python/runswift/types.hpp"
#include "touchline/robot_api/action_command.hpp"

namespace touchline::python::runswift {

/// Their walk's speed limits (their walk generator's maxima).
struct RunswiftWalkLimits {
  float max_forward_mm_s = 300.f; ///< either way
  float max_left_mm_s = 200.f;    ///< either side
  float max_turn_rad_s = 2.f;     ///< either way
  float min_speed_fraction = 0.66f; ///< of the maxima at speed 0 (1 at speed 1)
};

/// forward, left, turn limited to the ellipsoid of `limits` at `speed` (clamped to [0, 1]).
api::ActionCommand::Body convert_walk(float forward_mm_s, float left_mm_s, float turn_rad_s, float speed,
                                      const RunswiftWalkLimits& limits = {});
/// The Body for WALK, KICK, TURN_DRIBBLE, GOALIE_DIVE_LEFT/RIGHT, STAND and NONE (stand
/// for anything else).
api::ActionCommand::Body convert_body(const BodyCommand& body, const RunswiftWalkLimits& limits = {});
api::ActionCommand::Head convert_head(const HeadCommand& head);
/// 0xRRGGBB of an rgb.
int32_t led_colour(const Rgb& rgb);
/// Whether Touchline executes `type` (WALK, KICK, TURN_DRIBBLE, the goalie dives, STAND, NONE).
bool is_simulated(int type);
/// How long an unsimulated `type` takes on the robot, seconds (their key-frame files'
/// totals; 1 s where they have none). The dives' 2.4 s is the robot's DiveDef.
double action_duration_s(int type);

/// Checks every number of `request` a robot would act on. Throws RequestError
/// ("BehaviourRequest.actions.body.turn is nan") naming the first bad field.
void validate(const BehaviourRequest& request);

class RequestConverter {
 public:
  /// `warn` gets the one line per unsimulated action type.
  explicit RequestConverter(std::function<void(const std::string&)> warn, RunswiftWalkLimits limits = {});

  /// The command for `request` at simulated time `utime_us`. Throws RequestError.
  api::ActionCommand::All convert(const BehaviourRequest& request, int64_t utime_us);
  /// Forgets an action in progress (the behaviour failed; the robot stands anyway).
  void reset() { busy_until_us_ = -1; }
  /// The unsimulated action the robot is standing through, if any (else -1).
  int busy_with() const { return busy_until_us_ >= 0 ? busy_type_ : -1; }

 private:
  std::function<void(const std::string&)> warn_;
  RunswiftWalkLimits limits_;
  std::set<int> warned_;
  int busy_type_ = NONE;
  int64_t busy_since_us_ = 0;  ///< when busy_type_ began
  int64_t busy_until_us_ = -1; ///< standing through busy_type_ until then; -1: not
};

} // namespace touchline::python::runswift
