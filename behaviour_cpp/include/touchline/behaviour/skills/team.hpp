#pragma once
// Team: the whole robot for a match. Game states, team messages, roles; the port of
// behaviour_py/skills/team.py.
//
// Every tick the head runs LandmarkGlance (LookForBall with glances at landmarks), or in
// PLAYING looks where a ball lies that the referee put back and this field player has not seen
// since (search.hpp's drop-in); every MESSAGE_EVERY_FRAMES frames (counted by its own ticks,
// never wall time), the request carries this robot's team message. The body:
// penalised or fallen: stand (it gets up by itself); INITIAL, SET, FINISHED: stand; READY:
// walk to the player number's kick-off position (a fixed legal formation in the own half,
// outside the centre circle, but for player 2 when its team kicks off: the ball is then
// before its foot, and the kick-off is kicked as PLAYING begins, where from outside the
// circle the ball lay still for the first 3.5 s); PLAYING: the role's
// skill, roles assigned from the team messages (assignRole) unless fixed. A field player that
// has not seen the ball for SEARCH_TURN_FRAMES searches (search.hpp: the team ball, else a
// short turn on the spot and a walk to a search spot, in cycles).
#include <cstdint>
#include <optional>
#include <string>

#include "touchline/behaviour/skills/goalie.hpp"
#include "touchline/behaviour/skills/landmark_glance.hpp"
#include "touchline/behaviour/skills/search.hpp"
#include "touchline/behaviour/skills/unstick.hpp"
#include "touchline/behaviour/skills/striker.hpp"
#include "touchline/behaviour/skills/supporter.hpp"
#include "touchline/behaviour/skills/team_comm.hpp"

namespace touchline::behaviour::skills {

inline constexpr int32_t TEAM_BALL_SEEN_CHEST = 0x00ff00;     ///< green: the ball was seen recently
inline constexpr int32_t TEAM_BALL_LOST_CHEST = 0xff0000;     ///< red: searching
inline constexpr float READY_GOALIE_X = GOALIE_HOME_X;        ///< mm: the kick-off formation (player 1 ...
inline constexpr float READY_GOALIE_Y = 0.f;
inline constexpr float READY_STRIKER_X = -700.f;              ///< mm: ... player 2, outside the 600 mm centre circle ...
inline constexpr float READY_STRIKER_Y = 0.f;
inline constexpr float READY_KICKER_X = -150.f;               ///< mm: ... or, when its team kicks off, inside it with the ball
inline constexpr float READY_KICKER_Y = -50.f;                ///< mm: (the centre mark) before its left foot, to kick at once ...
inline constexpr float READY_DEFENDER_X = -1800.f;            ///< mm: ... player 3 ...
inline constexpr float READY_DEFENDER_Y = -600.f;
inline constexpr float READY_MIDFIELDER_X = -1200.f;          ///< mm: ... player 4; players 5 on: 3 and 4 mirrored in y)
inline constexpr float READY_MIDFIELDER_Y = 900.f;

/// The role whose kick-off position a player takes: 1 goalie, 2 striker, 3 defender,
/// 4 midfielder, then defender and midfielder alternately.
int formationRole(int playerNumber);
/// (x, y) of the player's kick-off position, team frame, facing +x; kickingOff: its team
/// kicks off.
FieldPoint readyPosition(int playerNumber, bool kickingOff = false);
/// This robot's TeamInfo from its Blackboard.
TeamInfo messageInfo(const api::Blackboard& blackboard, int role);

class Team : public api::Behaviour {
 public:
  /// fixedRole: play this role always (ROLE_NONE: assign roles from the messages); policy:
  /// the striker's learned walker policy file (nullopt: GoToPose); supporters: the
  /// SupporterDef the midfielder and defender play.
  explicit Team(int fixedRole = ROLE_NONE, const std::optional<std::string>& policy = std::nullopt,
                const SupporterDef& supporters = tunedSupporters());
  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;
  int role() const { return role_; }

 private:
  int chooseRole(const api::Blackboard& blackboard) const;
  api::ActionCommand::Body body(const api::Blackboard& blackboard);
  /// The PLAYING body before Unstick: the search, else the role's skill.
  api::ActionCommand::Body playBody(const api::Blackboard& blackboard);

  int fixedRole_;
  int role_;
  Goalie goalie_;
  Striker striker_;
  Defender defender_;
  Midfielder midfielder_;
  GoToPose readyPose_;
  LandmarkGlance head_;
  Search search_;
  Unstick unstick_;
  int64_t frame_ = 0;
};

} // namespace touchline::behaviour::skills
