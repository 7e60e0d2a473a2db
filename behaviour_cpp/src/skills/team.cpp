#include "touchline/behaviour/skills/team.hpp"

#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/track_ball.hpp"

namespace touchline::behaviour::skills {

using namespace api;

int formationRole(int playerNumber) {
  if (playerNumber == GOALIE_PLAYER) return ROLE_GOALIE;
  if (playerNumber == 2) return ROLE_STRIKER;
  return playerNumber % 2 == 1 ? ROLE_DEFENDER : ROLE_MIDFIELDER;
}

FieldPoint readyPosition(int playerNumber, bool kickingOff) {
  const int role = formationRole(playerNumber);
  if (role == ROLE_GOALIE) return {READY_GOALIE_X, READY_GOALIE_Y};
  if (role == ROLE_STRIKER)
    return kickingOff ? FieldPoint{READY_KICKER_X, READY_KICKER_Y} : FieldPoint{READY_STRIKER_X, READY_STRIKER_Y};
  const float mirror = playerNumber >= 5 ? -1.f : 1.f;
  if (role == ROLE_DEFENDER) return {READY_DEFENDER_X, mirror * READY_DEFENDER_Y};
  return {READY_MIDFIELDER_X, mirror * READY_MIDFIELDER_Y};
}

TeamInfo messageInfo(const Blackboard& blackboard, int role) {
  const GameControllerBlackboard& gc = blackboard.gameController;
  const AbsCoord ball = blackboard.localisation.ballPos;
  const AbsCoord pos = blackboard.localisation.robotPos;
  return makeTeamInfo(gc.playerNumber, role, ballRecentlySeen(blackboard), gc.penalised, blackboard.motion.fallen,
                      blackboard.localisation.ballPosRR.distance, ball.x, ball.y, pos.x, pos.y);
}

Team::Team(int fixedRole, const std::optional<std::string>& policy, const SupporterDef& supporters)
    : fixedRole_(fixedRole),
      role_(fixedRole),
      striker_(policy),
      defender_(supporters),
      midfielder_(supporters),
      search_(supporters) {}

ActionCommand::All Team::tick(const Blackboard& blackboard) {
  role_ = chooseRole(blackboard);
  const ActionCommand::Body bodyRequest = body(blackboard);
  // A ball put back unseen is looked for where it was put; else LandmarkGlance.
  const auto& dropIn = search_.dropIn();
  const bool lookAtDropIn = dropIn && role_ != ROLE_GOALIE && blackboard.gameController.state == GameState::PLAYING;
  const ActionCommand::Head head =
      lookAtDropIn ? lookAt(toRobotRelative(blackboard.localisation.robotPos, dropIn->x, dropIn->y))
                   : head_.tick(blackboard).head;
  const int32_t chest = ballRecentlySeen(blackboard) ? TEAM_BALL_SEEN_CHEST : TEAM_BALL_LOST_CHEST;
  ActionCommand::All command = actioncommand::compose(head, bodyRequest, actioncommand::leds(chest));
  if (frame_ % MESSAGE_EVERY_FRAMES == 0) command.teamMessage = encodeMessage(messageInfo(blackboard, role_));
  frame_ += 1;
  return command;
}

int Team::chooseRole(const Blackboard& blackboard) const {
  if (fixedRole_ != ROLE_NONE) return fixedRole_;
  const TeamInfo info = messageInfo(blackboard, role_);
  return assignRole(info.playerNumber, info.ballDistance, role_, blackboard.receiver.messages, blackboard.utime);
}

ActionCommand::Body Team::body(const Blackboard& blackboard) {
  const GameControllerBlackboard& gc = blackboard.gameController;
  const bool playing = gc.state == GameState::PLAYING && !gc.penalised && !blackboard.motion.fallen;
  if (!playing) unstick_.reset(); // stuck counts in play only
  if (gc.penalised || blackboard.motion.fallen) return actioncommand::stand();
  if (gc.state == GameState::READY) {
    const FieldPoint ready = readyPosition(gc.playerNumber, gc.kickOffTeam == gc.team);
    readyPose_.setTarget(ready.x, ready.y, 0.f);
    return readyPose_.tick(blackboard).body;
  }
  if (gc.state != GameState::PLAYING) return actioncommand::stand();
  // Every role's body goes through Unstick: turning on the spot for long, whatever the
  // cause, becomes a walk without turning (issue #17); the goalie's towards its home.
  const std::optional<FieldPoint> home =
      role_ == ROLE_GOALIE ? std::optional<FieldPoint>(FieldPoint{GOALIE_HOME_X, 0.f}) : std::nullopt;
  return unstick_.tick(blackboard, playBody(blackboard), home);
}

ActionCommand::Body Team::playBody(const Blackboard& blackboard) {
  if (role_ != ROLE_GOALIE) {
    if (const auto searchBody = search_.tick(blackboard, role_)) return *searchBody;
  }
  switch (role_) {
    case ROLE_GOALIE: return goalie_.tick(blackboard).body;
    case ROLE_STRIKER: return striker_.tick(blackboard).body;
    case ROLE_DEFENDER: return defender_.tick(blackboard).body;
    default: return midfielder_.tick(blackboard).body;
  }
}

} // namespace touchline::behaviour::skills
