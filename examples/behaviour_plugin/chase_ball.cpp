// ChaseBall: a team's own behaviour, outside the Touchline tree. While the game is PLAYING
// and the robot is not penalised it turns towards the ball it believes in and walks to it;
// with the ball lost it turns on the spot to find it; otherwise it stands. It sees only the
// robot API (touchline::robot_api) and is loaded by name from this library by
// robot_shim --behaviour-plugin libchase_ball.so --behaviour ChaseBall [--param speed=0.8].
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "touchline/robot_api/plugin.hpp"

namespace {

namespace api = touchline::api;
namespace ac = touchline::api::ActionCommand;

/// How ChaseBall walks; defaults suit the default walk.
struct ChaseBallDef {
  float speed = 1.0f;               ///< fraction of the walk's speed limits, (0, 1] (--param speed=)
  float forward_mm_s = 300;         ///< forward request when the ball is far
  float turn_gain_per_s = 1.5f;     ///< turn rate per rad of ball heading, 1/s
  float search_turn_rad_s = 0.6f;   ///< turn rate while the ball is lost
  float facing_rad = 0.5f;          ///< walk forward only with the ball within this of straight ahead
  int lost_after_frames = 45;       ///< frames without a sighting (1.5 s) before searching
  // The camera sees farther the higher the head: 1000 mm fully down (0.51 rad), 3000 mm more
  // fully up (-0.67 rad), linearly (the world's default [camera]).
  float search_pitch_rad = -0.4f;   ///< head pitch while searching: about 3.7 m of field
  float near_pitch_rad = 0.51f;     ///< head pitch that sees 1000 mm
  float pitch_per_mm = 1.18f / 3000;///< head pitch up per mm of range beyond that, rad/mm
};

class ChaseBall : public api::Behaviour {
 public:
  explicit ChaseBall(ChaseBallDef def) : def_(def) {}

  ac::All tick(const api::Blackboard& blackboard) override {
    ac::All request;
    const auto& game = blackboard.gameController;
    if (game.state != api::GameState::PLAYING || game.penalised) return request; // stand
    const auto& localisation = blackboard.localisation;
    if (localisation.ballLostCount > def_.lost_after_frames) {
      request.head.pitch = def_.search_pitch_rad;
      request.body = ac::walk(0, 0, def_.search_turn_rad_s);
    } else {
      const api::RRCoord& ball = localisation.ballPosRR;
      // The head just high enough to keep the ball in range (and a little beyond it).
      request.head.pitch = std::max(def_.search_pitch_rad,
                                    def_.near_pitch_rad - def_.pitch_per_mm * std::max(0.f, ball.distance - 700));
      const float turn = def_.turn_gain_per_s * ball.heading;
      const float forward = std::abs(ball.heading) < def_.facing_rad ? std::min(def_.forward_mm_s, ball.distance) : 0;
      request.body = ac::walk(forward, 0, turn);
    }
    request.body.speed = def_.speed;
    request.leds.chest = 0x0000ff; // blue: ours, not the tree's
    return request;
  }

 private:
  ChaseBallDef def_;
};

float parse_speed(const std::string& text) {
  std::size_t used = 0;
  float value = 0;
  try {
    value = std::stof(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value > 0 && value <= 1))
    throw std::invalid_argument("ChaseBall: speed must be a number in (0, 1] (got '" + text + "')");
  return value;
}

std::unique_ptr<api::Behaviour> make(const api::PluginRequest& request) {
  if (request.name != "ChaseBall")
    throw std::invalid_argument("unknown behaviour '" + request.name + "' (this library has ChaseBall)");
  ChaseBallDef def;
  for (const auto& [key, value] : request.params) {
    if (key != "speed") throw std::invalid_argument("ChaseBall: unknown parameter '" + key + "' (it has speed)");
    def.speed = parse_speed(value);
  }
  return std::make_unique<ChaseBall>(def);
}

} // namespace

TOUCHLINE_BEHAVIOUR_PLUGIN(make)
