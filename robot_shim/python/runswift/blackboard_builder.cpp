#include "touchline/python/runswift/blackboard_builder.hpp"

#include <algorithm>
#include <cmath>

namespace touchline::python::runswift {

namespace {

constexpr float kHalfPi = 1.5707963f;

AbsCoord abs_coord(const api::AbsCoord& c) { return {c.x, c.y, c.theta}; }
RRCoord rr_coord(const api::RRCoord& c) { return {c.distance, c.heading}; }
AbsCoord cartesian(const api::RRCoord& c) { return {c.x(), c.y(), 0}; }

/// A field-frame vector seen in the frame of a robot heading `theta`.
AbsCoord rotate_into(float x, float y, float theta) {
  const float c = std::cos(theta), s = std::sin(theta);
  return {c * x + s * y, -s * x + c * y, 0};
}

/// Where the camera would show something at `heading` (column) in the top camera.
std::array<int, 2> image_point(float heading) {
  constexpr float kHfov = 1.0641f;
  constexpr int kCols = 1280, kRows = 960;
  const float column = (0.5f - heading / kHfov) * kCols;
  return {static_cast<int>(std::clamp(column, 0.f, static_cast<float>(kCols - 1))), kRows / 2};
}

void fill_state_estimation(const api::Blackboard& t, const BlackboardBuilderDef& def, int our_colour,
                           StateEstimationBlackboard& se) {
  const api::LocalisationBlackboard& loc = t.localisation;
  se.robotPos = abs_coord(loc.robotPos);
  std::copy(loc.robotPosCovariance.begin(), loc.robotPosCovariance.end(), se.robotPos.var.begin());
  const auto& c = loc.robotPosCovariance;
  se.robotPosUncertainty = ellipse_sigma_product(c[0], c[1], c[4]);
  se.robotHeadingUncertainty = std::sqrt(std::max(c[8], 0.f));
  se.allRobotPos = {se.robotPos};
  se.ballPosRR = rr_coord(loc.ballPosRR);
  se.ballPosRRC = cartesian(loc.ballPosRR);
  se.ballPos = {loc.ballPos.x, loc.ballPos.y, 0};
  se.ballVel = {loc.ballVel.x, loc.ballVel.y, 0};
  se.ballVelRRC = rotate_into(loc.ballVel.x, loc.ballVel.y, loc.robotPos.theta);
  se.teamBallPos = {loc.teamBallPos.x, loc.teamBallPos.y, 0};
  se.teamBallVel = se.ballVel;
  const auto& b = loc.ballPosCovariance;
  se.egoBallPosUncertainty = ellipse_sigma_product(b[0], b[1], b[3]);
  se.teamBallPosUncertainty = se.egoBallPosUncertainty;
  se.sharedStateEstimationBundle.robotPos = se.robotPos;
  se.sharedStateEstimationBundle.ballPosRRC = se.ballPosRRC;
  se.sharedStateEstimationBundle.ballVelRRC = se.ballVelRRC;
  se.sharedStateEstimationBundle.haveBallUpdate = t.vision.ballSeen;
  for (const api::SeenObject& r : t.vision.robots) {
    RobotObstacle o;
    o.rr = rr_coord(r.rr);
    o.type = r.teammate ? our_colour : (our_colour == rBlue ? rRed : rBlue);
    o.rrc = cartesian(r.rr);
    const float bearing = loc.robotPos.theta + r.rr.heading;
    o.pos = {loc.robotPos.x + r.rr.distance * std::cos(bearing), loc.robotPos.y + r.rr.distance * std::sin(bearing), 0};
    // The headings that just pass it, and the points where they touch it.
    const float half = std::asin(std::min(1.f, def.obstacle_radius_mm / std::max(r.rr.distance, 1.f)));
    o.tangentHeadingLeft = r.rr.heading + half;
    o.tangentHeadingRight = r.rr.heading - half;
    const float reach = std::sqrt(std::max(0.f, r.rr.distance * r.rr.distance -
                                                    def.obstacle_radius_mm * def.obstacle_radius_mm));
    o.evadeVectorLeft = {reach, static_cast<float>(o.tangentHeadingLeft)};
    o.evadeVectorRight = {reach, static_cast<float>(o.tangentHeadingRight)};
    se.robotObstacles.push_back(o);
  }
}

void fill_vision(const api::Blackboard& t, int our_colour, VisionBlackboard& v) {
  v.timestamp = t.utime;
  if (t.vision.ballSeen) {
    BallInfo ball;
    ball.rr = rr_coord(t.vision.ball);
    ball.imageCoords = image_point(t.vision.ball.heading);
    // The ball's radius in pixels at that distance (focal length ~ 1090 px, 50 mm radius).
    ball.radius = static_cast<int>(std::lround(1090.f * 50.f / std::max(t.vision.ball.distance, 50.f)));
    ball.topCamera = t.vision.ball.distance > 1000.f;
    v.balls.push_back(ball);
  }
  for (const api::SeenObject& r : t.vision.robots)
    v.robots.push_back({rr_coord(r.rr), r.teammate ? our_colour : (our_colour == rBlue ? rRed : rBlue)});
  static const int kPostTypes[] = {pHomeLeft, pHomeRight, pAwayLeft, pAwayRight};
  for (const api::SeenObject& p : t.vision.posts)
    v.posts.push_back({rr_coord(p.rr), p.id >= 0 && p.id < 4 ? kPostTypes[p.id] : pNone, image_point(p.rr.heading)});
}

/// The body command motion is executing, in their terms.
BodyCommand active_body(const api::ActionCommand::Body& b) {
  using api::ActionCommand::ActionType;
  BodyCommand body;
  switch (b.actionType) {
    case ActionType::NONE: body.actionType = NONE; break;
    case ActionType::STAND: body.actionType = STAND; break;
    case ActionType::WALK: body.actionType = WALK; break;
    case ActionType::DRIBBLE: body.actionType = TURN_DRIBBLE; break;
    case ActionType::KICK: body.actionType = KICK; break;
    case ActionType::GETUP_FRONT: body.actionType = GETUP_FRONT; break;
    case ActionType::GETUP_BACK: body.actionType = GETUP_BACK; break;
    case ActionType::DEAD: body.actionType = LIMP; break;
    case ActionType::GOALIE_DIVE_LEFT: body.actionType = GOALIE_DIVE_LEFT; break;
    case ActionType::GOALIE_DIVE_RIGHT: body.actionType = GOALIE_DIVE_RIGHT; break;
  }
  const bool kick = b.actionType == ActionType::KICK || b.actionType == ActionType::DRIBBLE;
  body.forward = static_cast<int>(std::lround(b.forward));
  body.left = static_cast<int>(std::lround(b.left));
  body.turn = kick ? b.bend : b.turn; // a kick's direction is their turn
  body.power = b.power;
  body.speed = b.speed;
  body.foot = b.foot == api::ActionCommand::Foot::RIGHT ? FOOT_RIGHT : FOOT_LEFT;
  return body;
}

void fill_motion(const api::Blackboard& t, MotionBlackboard& m) {
  m.active.body = active_body(t.motion.active);
  auto& joints = m.sensors.joints;
  joints.angles[HeadYaw] = t.motion.headYaw;
  joints.angles[HeadPitch] = t.motion.headPitch;
  joints.stiffnesses.fill(1.f);   // always stiff
  joints.temperatures.fill(30.f); // degrees C: cool joints, never overheating
  auto& s = m.sensors.sensors;
  const float range_m = t.motion.sonarRange_mm / 1000.f;
  s[SonarLeft] = t.motion.sonarLeft * range_m;
  s[SonarRight] = t.motion.sonarRight * range_m;
  // A robot against a foot's front presses both of its bumpers (1: pressed).
  s[LFoot_Bumper_Left] = s[LFoot_Bumper_Right] = t.motion.touchFrontLeft ? 1.f : 0.f;
  s[RFoot_Bumper_Left] = s[RFoot_Bumper_Right] = t.motion.touchFrontRight ? 1.f : 0.f;
  s[InertialSensor_AngleY] = t.motion.fallen ? kHalfPi : 0.f; // lying: the body pitched a quarter turn
  s[Battery_Charge] = 1.f;
  m.uptime = static_cast<float>(t.utime) * 1e-6f;
  m.isStiff = true;
}

} // namespace

float ellipse_sigma_product(float xx, float xy, float yy) {
  return std::sqrt(std::max(0.f, xx * yy - xy * xy)); // sigma_a * sigma_b = sqrt(lambda_a * lambda_b) = sqrt(det)
}

Broadcast BlackboardBuilder::own_broadcast(const api::Blackboard& t) const {
  Broadcast b;
  BroadcastData& d = b.data;
  const api::LocalisationBlackboard& loc = t.localisation;
  d.playerNum = t.gameController.playerNumber;
  d.robotPos = {loc.robotPos.x, loc.robotPos.y, loc.robotPos.theta};
  d.ballPosAbs = {loc.ballPos.x, loc.ballPos.y, 0};
  d.ballPosRR = rr_coord(loc.ballPosRR);
  d.sharedStateEstimationBundle.robotPos = abs_coord(loc.robotPos);
  d.sharedStateEstimationBundle.ballPosRRC = cartesian(loc.ballPosRR);
  d.sharedStateEstimationBundle.ballVelRRC = rotate_into(loc.ballVel.x, loc.ballVel.y, loc.robotPos.theta);
  d.sharedStateEstimationBundle.haveBallUpdate = t.vision.ballSeen;
  d.behaviourSharedData = shared_;
  d.acB = last_action_;
  d.uptime = static_cast<float>(t.utime) * 1e-6f;
  d.gameState = static_cast<int>(t.gameController.state);
  b.fallen = t.motion.fallen;
  b.penalised = t.gameController.penalised;
  b.ball_age_s = loc.ballLostCount >= (1 << 20) ? -1.f : static_cast<float>(loc.ballLostCount) / 30.f;
  return b;
}

void BlackboardBuilder::remember(const BehaviourRequest& request) {
  shared_ = request.behaviourSharedData;
  last_action_ = request.actions.body.actionType;
}

Blackboard BlackboardBuilder::build(const api::Blackboard& t) {
  Blackboard bb;
  const int team = t.gameController.team == 1 ? 1 : 0;
  const int our_colour = team == 0 ? rBlue : rRed;
  fill_state_estimation(t, def_, our_colour, bb.stateEstimation);
  fill_vision(t, our_colour, bb.vision);
  fill_motion(t, bb.motion);

  BehaviourBlackboard& behaviour = bb.behaviour;
  behaviour.skill = def_.skill;
  behaviour.headskill = def_.headskill;
  behaviour.positioning = def_.positioning;
  behaviour.behaviourSharedData = shared_;

  GameControllerBlackboard& gc = bb.gameController;
  GameControlData& data = gc.data;
  data.playersPerTeam = def_.players_per_team;
  data.state = static_cast<int>(t.gameController.state);
  data.firstHalf = t.gameController.firstHalf ? 1 : 0;
  // The GameController's kickingTeam is the set play's team while one is on, else the kick-off's.
  data.setPlay = static_cast<int>(t.gameController.setPlay);
  const bool set_play = t.gameController.setPlay != api::SetPlay::NONE && t.gameController.setPlayTeam >= 0;
  const int kicking = set_play ? t.gameController.setPlayTeam : t.gameController.kickOffTeam;
  data.kickingTeam = def_.team_numbers[kicking == 1 ? 1 : 0];
  data.secsRemaining = t.gameController.secsRemaining;
  const int player = std::clamp(t.gameController.playerNumber, 1, kMaxNumPlayers);
  for (int i = 0; i < 2; ++i) {
    data.teams[i].teamNumber = def_.team_numbers[i];
    data.teams[i].teamColour = i; // TEAM_BLUE, TEAM_RED
    data.teams[i].score = t.gameController.score[i];
  }
  data.teams[team].players[player - 1].penalty = t.gameController.penalised ? 15 /* PENALTY_MANUAL */ : 0;
  gc.our_team = data.teams[team];
  gc.player_number = player;
  gc.gameState = data.state;

  ReceiverBlackboard& rx = bb.receiver;
  rx.team = def_.team_numbers[team];
  // The team ball: the newest sighting, ours or one a teammate broadcast.
  StateEstimationBlackboard& se = bb.stateEstimation;
  if (t.vision.ballSeen)
    team_ball_ = {t.localisation.ballPos.x, t.localisation.ballPos.y, t.localisation.ballVel.x, t.localisation.ballVel.y,
                  t.utime};
  auto hear = [&](int number, const Broadcast& b, int64_t sent_us) {
    const int i = number - 1;
    rx.data[i] = b.data;
    rx.data[i].playerNum = number;
    SplStandardMessage& msg = rx.message[i];
    msg.playerNum = number;
    msg.fallen = b.fallen;
    msg.pose = b.data.robotPos;
    msg.ballAge = b.ball_age_s;
    msg.ball = {b.data.sharedStateEstimationBundle.ballPosRRC.x, b.data.sharedStateEstimationBundle.ballPosRRC.y};
    rx.lastReceived[i] = sent_us / 1000000;
    rx.incapacitated[i] = b.penalised || t.utime - sent_us > def_.incapacitated_after_us;
  };
  for (const api::TeamMessage& m : t.receiver.messages) {
    if (m.playerNumber < 1 || m.playerNumber > kRobotsPerTeam || m.playerNumber == player) continue;
    const auto heard = decode_broadcast(m.data);
    if (!heard) continue;
    hear(m.playerNumber, *heard, m.utime);
    int64_t& read = heard_utime_[static_cast<size_t>(m.playerNumber - 1)];
    if (m.utime > read && heard->data.sharedStateEstimationBundle.haveBallUpdate && !heard->penalised) {
      se.hadTeamBallUpdate = true; // a teammate's sighting arrived this frame
      if (m.utime > team_ball_.utime) {
        // The sender's velocity is in its own frame: back into the field's.
        const AbsCoord& v = heard->data.sharedStateEstimationBundle.ballVelRRC;
        const float c = std::cos(heard->data.robotPos[2]), s = std::sin(heard->data.robotPos[2]);
        team_ball_ = {heard->data.ballPosAbs.x, heard->data.ballPosAbs.y, c * v.x - s * v.y, s * v.x + c * v.y, m.utime};
      }
    }
    read = std::max(read, m.utime);
  }
  if (team_ball_.utime >= 0) {
    se.teamBallPos = {team_ball_.x, team_ball_.y, 0};
    se.teamBallVel = {team_ball_.vx, team_ball_.vy, 0};
  }
  hear(player, own_broadcast(t), t.utime); // a robot hears its own broadcasts
  return bb;
}

} // namespace touchline::python::runswift
