// Their Blackboard as built from ours: each field against what the robot's adapters wrote,
// and, through a Robot stepping sensed frames, against the world's truth.
#include "touchline/python/runswift/blackboard_builder.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "touchline/robot/robot.hpp"

using namespace touchline;
using namespace touchline::python::runswift;
using touchline::api::kPi;

namespace {

api::Blackboard board() {
  api::Blackboard t;
  t.utime = 12345678;
  t.gameController.team = 0;
  t.gameController.playerNumber = 3;
  t.gameController.state = api::GameState::PLAYING;
  t.gameController.score = {2, 1};
  t.gameController.secsRemaining = 321;
  t.gameController.firstHalf = false;
  t.gameController.kickOffTeam = 1;
  auto& loc = t.localisation;
  loc.robotPos = {1000, -500, kPi / 2};
  loc.robotPosCovariance = {400, 0, 0, 0, 100, 0, 0, 0, 0.01f}; // sigma x 20 mm, y 10 mm, theta 0.1 rad
  loc.ballPos = {1000, 0, 0};
  loc.ballPosRR = api::toRobotRelative(loc.robotPos, 1000, 0);
  loc.ballVel = {100, 0, 0};
  loc.ballPosCovariance = {900, 0, 0, 100}; // sigma 30 mm, 10 mm
  loc.teamBallPos = {1000, 0, 0};
  loc.ballLostCount = 0;
  t.vision.ballSeen = true;
  t.vision.ball = {500, 0};
  t.vision.posts.push_back({{3000, 0.2f}, 2, false});
  t.vision.robots.push_back({{800, -0.3f}, 2, true});
  t.vision.robots.push_back({{1500, 0.4f}, 5, false});
  t.motion.headYaw = 0.4f;
  t.motion.headPitch = 0.2f;
  t.motion.sonarLeft = 0.3f;
  t.motion.sonarRange_mm = 1000;
  return t;
}

} // namespace

TEST(BlackboardBuilder, StateEstimationIsLocalisationInTheirFieldsAndUnits) {
  BlackboardBuilder builder;
  const Blackboard bb = builder.build(board());
  const StateEstimationBlackboard& se = bb.stateEstimation;
  EXPECT_FLOAT_EQ(se.robotPos.x, 1000);
  EXPECT_FLOAT_EQ(se.robotPos.y, -500);
  EXPECT_FLOAT_EQ(se.robotPos.theta, kPi / 2);
  EXPECT_FLOAT_EQ(se.robotPosUncertainty, 20 * 10); // product of the ellipse's sigmas, as their filter reports
  EXPECT_FLOAT_EQ(se.robotHeadingUncertainty, 0.1f);
  EXPECT_FLOAT_EQ(se.robotPos.var[0], 400);
  ASSERT_EQ(se.allRobotPos.size(), 1u);
  EXPECT_NEAR(se.ballPosRR.distance, 500, 1e-3);
  EXPECT_NEAR(se.ballPosRR.heading, 0, 1e-6);
  EXPECT_NEAR(se.ballPosRRC.x, 500, 1e-3); // straight ahead of a robot facing +y
  EXPECT_NEAR(se.ballPosRRC.y, 0, 1e-3);
  EXPECT_FLOAT_EQ(se.ballPos.x, 1000);
  EXPECT_FLOAT_EQ(se.ballVel.x, 100);
  // Rolling along +x, seen by a robot facing +y: to its right.
  EXPECT_NEAR(se.ballVelRRC.x, 0, 1e-3);
  EXPECT_NEAR(se.ballVelRRC.y, -100, 1e-3);
  EXPECT_FLOAT_EQ(se.egoBallPosUncertainty, 30 * 10);
  EXPECT_FLOAT_EQ(se.teamBallPos.x, 1000);
  EXPECT_TRUE(se.sharedStateEstimationBundle.haveBallUpdate);
}

TEST(BlackboardBuilder, TheEllipseSigmaProductIsRotationInvariant) {
  // sigma 20 and 10 along axes turned by 30 degrees
  const float c = std::cos(0.5236f), s = std::sin(0.5236f);
  const float xx = 400 * c * c + 100 * s * s, yy = 400 * s * s + 100 * c * c, xy = (400 - 100) * c * s;
  EXPECT_NEAR(ellipse_sigma_product(xx, xy, yy), 200, 1e-2);
}

TEST(BlackboardBuilder, RobotsSeenAreObstaclesAroundWhereTheyStand) {
  BlackboardBuilder builder;
  const Blackboard bb = builder.build(board());
  ASSERT_EQ(bb.stateEstimation.robotObstacles.size(), 2u);
  const RobotObstacle& mate = bb.stateEstimation.robotObstacles[0];
  EXPECT_EQ(mate.type, rBlue); // team 0 plays blue
  EXPECT_FLOAT_EQ(mate.rr.distance, 800);
  EXPECT_NEAR(mate.rrc.x, 800 * std::cos(-0.3f), 1e-3);
  // facing +y, 0.3 rad to the right: at heading pi/2 - 0.3 on the field
  EXPECT_NEAR(mate.pos.x, 1000 + 800 * std::cos(kPi / 2 - 0.3f), 1e-2);
  EXPECT_NEAR(mate.pos.y, -500 + 800 * std::sin(kPi / 2 - 0.3f), 1e-2);
  EXPECT_GT(mate.tangentHeadingLeft, -0.3);
  EXPECT_LT(mate.tangentHeadingRight, -0.3);
  EXPECT_EQ(bb.stateEstimation.robotObstacles[1].type, rRed);
  ASSERT_EQ(bb.vision.robots.size(), 2u);
  EXPECT_EQ(bb.vision.robots[1].type, rRed);
}

TEST(BlackboardBuilder, VisionHasTheTimestampTheBallAndThePosts) {
  BlackboardBuilder builder;
  api::Blackboard t = board();
  Blackboard bb = builder.build(t);
  EXPECT_EQ(bb.vision.timestamp, 12345678); // microseconds, simulated
  ASSERT_EQ(bb.vision.balls.size(), 1u);
  EXPECT_FLOAT_EQ(bb.vision.balls[0].rr.distance, 500);
  EXPECT_GT(bb.vision.balls[0].radius, 0);
  EXPECT_EQ(bb.vision.balls[0].imageCoords[0], 640); // straight ahead: the image's middle column
  ASSERT_EQ(bb.vision.posts.size(), 1u);
  EXPECT_EQ(bb.vision.posts[0].type, pAwayLeft); // post 2: the opponent goal's left
  t.vision.ballSeen = false;
  bb = builder.build(t);
  EXPECT_TRUE(bb.vision.balls.empty());
}

TEST(BlackboardBuilder, MotionSensorsInTheirUnits) {
  BlackboardBuilder builder;
  api::Blackboard t = board();
  Blackboard bb = builder.build(t);
  const auto& s = bb.motion.sensors;
  EXPECT_FLOAT_EQ(s.joints.angles[HeadYaw], 0.4f);
  EXPECT_FLOAT_EQ(s.joints.angles[HeadPitch], 0.2f);
  EXPECT_FLOAT_EQ(s.sensors[SonarLeft], 0.3f);  // metres: 0.3 of a 1 m range
  EXPECT_FLOAT_EQ(s.sensors[SonarRight], 1.0f); // nothing within range: the range
  EXPECT_FLOAT_EQ(s.sensors[InertialSensor_AngleY], 0);
  EXPECT_FLOAT_EQ(s.joints.stiffnesses[LKneePitch], 1);
  EXPECT_TRUE(bb.motion.isStiff);
  EXPECT_NEAR(bb.motion.uptime, 12.345678f, 1e-4);
  t.motion.fallen = true;
  EXPECT_GT(builder.build(t).motion.sensors.sensors[InertialSensor_AngleY], 1.5f);
  EXPECT_FLOAT_EQ(s.sensors[LFoot_Bumper_Left] + s.sensors[RFoot_Bumper_Right], 0); // nothing touches
  t.motion.touchFrontLeft = true; // a robot against the left foot's front
  const auto& pressed = builder.build(t).motion.sensors.sensors;
  EXPECT_FLOAT_EQ(pressed[LFoot_Bumper_Left], 1);
  EXPECT_FLOAT_EQ(pressed[LFoot_Bumper_Right], 1);
  EXPECT_FLOAT_EQ(pressed[RFoot_Bumper_Left], 0);
}

TEST(BlackboardBuilder, GameControllerDataInTheirNumbers) {
  BlackboardBuilderDef def;
  def.team_numbers = {18, 5};
  BlackboardBuilder builder(def);
  api::Blackboard t = board();
  Blackboard bb = builder.build(t);
  const GameControllerBlackboard& gc = bb.gameController;
  EXPECT_EQ(gc.data.state, 3); // STATE_PLAYING
  EXPECT_EQ(gc.gameState, 3);
  EXPECT_EQ(gc.data.firstHalf, 0);
  EXPECT_EQ(gc.data.kickingTeam, 5); // team 1 kicks off: its team number
  EXPECT_EQ(gc.data.secsRemaining, 321);
  EXPECT_EQ(gc.data.setPlay, 0);
  EXPECT_EQ(gc.data.gamePhase, 0);
  EXPECT_EQ(gc.data.teams[0].score, 2);
  EXPECT_EQ(gc.data.teams[1].score, 1);
  EXPECT_EQ(gc.our_team.teamNumber, 18);
  EXPECT_EQ(gc.player_number, 3);

  EXPECT_EQ(gc.our_team.players[2].penalty, 0); // PENALTY_NONE
  t.gameController.penalised = true;
  t.gameController.state = api::GameState::READY;
  bb = builder.build(t);
  EXPECT_EQ(bb.gameController.our_team.players[2].penalty, 15); // PENALTY_MANUAL: the kind is not sensed
  EXPECT_EQ(bb.gameController.data.state, 1);
  t.gameController.team = 1;
  EXPECT_EQ(builder.build(t).gameController.our_team.teamNumber, 5);

  // A set play: their numbers, and the kicking team is the set play's, not the kick-off's.
  t.gameController.setPlay = api::SetPlay::CORNER_KICK;
  t.gameController.setPlayTeam = 0;
  const Blackboard corner = builder.build(t);
  EXPECT_EQ(corner.gameController.data.setPlay, 3); // SET_PLAY_CORNER_KICK
  EXPECT_EQ(corner.gameController.data.kickingTeam, 18);
  t.gameController.state = api::GameState::STANDBY;
  EXPECT_EQ(builder.build(t).gameController.data.state, 5); // STATE_STANDBY
}

TEST(BlackboardBuilder, TheBehaviourSeesItsSkillNamesAndItsLastSharedData) {
  BlackboardBuilderDef def;
  def.skill = "WalkToPoint";
  def.headskill = "HeadFindBall";
  BlackboardBuilder builder(def);
  BehaviourRequest r;
  r.behaviourSharedData.playingBall = true;
  builder.remember(r);
  const Blackboard bb = builder.build(board());
  EXPECT_EQ(bb.behaviour.skill, "WalkToPoint");
  EXPECT_EQ(bb.behaviour.headskill, "HeadFindBall");
  EXPECT_EQ(bb.behaviour.positioning, "PositioningAgainstKickingTeam");
  EXPECT_TRUE(bb.behaviour.behaviourSharedData.playingBall);
  EXPECT_FALSE(bb.behaviour.remoteStiffen);
  EXPECT_FLOAT_EQ(bb.kinematics.parameters.cameraPitchBottom, 0);
}

TEST(BlackboardBuilder, TheReceiverHasTeammatesBroadcastsByPlayerNumberAndOurOwn) {
  BlackboardBuilder builder;
  api::Blackboard t = board();
  Broadcast mate;
  mate.data.robotPos = {-2000, 1000, 0.5f};
  mate.data.behaviourSharedData.isAssisting = true;
  t.receiver.messages.push_back({5, t.utime - 400000, encode_broadcast(mate)});
  t.receiver.messages.push_back({2, t.utime - 6000000, encode_broadcast(mate)}); // heard 6 s ago
  t.receiver.messages.push_back({4, t.utime, {1, 2, 3}});                        // not a broadcast
  BehaviourRequest ours;
  ours.behaviourSharedData.playingBall = true;
  builder.remember(ours);
  const Blackboard bb = builder.build(t);
  const ReceiverBlackboard& rx = bb.receiver;
  EXPECT_FLOAT_EQ(rx.data[4].robotPos[0], -2000);
  EXPECT_EQ(rx.data[4].playerNum, 5);
  EXPECT_TRUE(rx.data[4].behaviourSharedData.isAssisting);
  EXPECT_FALSE(rx.incapacitated[4]);
  EXPECT_TRUE(rx.incapacitated[1]); // unheard for longer than 5 s
  EXPECT_TRUE(rx.incapacitated[3]); // its bytes were not a broadcast
  EXPECT_TRUE(rx.incapacitated[0]); // never heard
  EXPECT_EQ(rx.lastReceived[4], (t.utime - 400000) / 1000000);
  EXPECT_FLOAT_EQ(rx.message[4].pose[1], 1000);
  // our own slot: what we broadcast, as a robot hears itself
  EXPECT_FALSE(rx.incapacitated[2]);
  EXPECT_FLOAT_EQ(rx.data[2].robotPos[0], 1000);
  EXPECT_TRUE(rx.data[2].behaviourSharedData.playingBall);
}

namespace {

/// A behaviour that does nothing: the adapters alone write the Blackboard.
class Idle : public api::Behaviour {
 public:
  api::ActionCommand::All tick(const api::Blackboard&) override { return {}; }
};

} // namespace

TEST(BlackboardBuilder, WithTheRobotsAdaptersEveryPositionIsTheWorldsTruthInTheTeamsFrame) {
  for (int team : {0, 1}) {
    robot::RobotDef def;
    def.id = {team, 2};
    def.localisation.perfect = true; // the pose is the truth; the ball is where the camera saw it
    robot::Robot robot(def, std::make_unique<Idle>());
    RobotSense sense;
    sense.id = def.id;
    sense.truth = {1000, -500, kPi / 2}; // world frame
    sense.ball_x_mm = 1000;
    sense.ball_y_mm = 0;
    sense.sonar_left = 0.25f;
    sense.seen.push_back({ObjectKind::kBall, 0, 500, 0, 0.5f}); // exactly where it is
    sense.seen.push_back({ObjectKind::kGoalPost, 0, 2600, 1.f, 0.2f});
    SenseFrame frame;
    frame.utime = 1000000;
    frame.frame = 30;
    frame.game.state = GameState::kPlaying;
    frame.robots.push_back(sense);
    robot.step(frame, sense);
    const Blackboard bb = BlackboardBuilder().build(robot.blackboard());
    // Team 1 sees the world turned by pi: +x towards the goal it attacks.
    const float sign = team == 0 ? 1.f : -1.f;
    const StateEstimationBlackboard& se = bb.stateEstimation;
    EXPECT_NEAR(se.robotPos.x, sign * 1000, 1e-2) << "team " << team;
    EXPECT_NEAR(se.robotPos.y, sign * -500, 1e-2) << "team " << team;
    EXPECT_NEAR(std::remainder(se.robotPos.theta - (kPi / 2 + (team ? kPi : 0)), 2 * kPi), 0, 1e-5);
    EXPECT_NEAR(se.ballPos.x, sign * 1000, 1e-2) << "team " << team;
    EXPECT_NEAR(se.ballPos.y, 0, 1e-2) << "team " << team;
    EXPECT_NEAR(se.ballPosRR.distance, 500, 1e-2);
    EXPECT_NEAR(se.ballPosRRC.x, 500, 1e-2);
    EXPECT_EQ(bb.gameController.data.state, 3);
    EXPECT_EQ(bb.gameController.player_number, 2);
    EXPECT_EQ(bb.vision.timestamp, 1000000);
    EXPECT_FLOAT_EQ(bb.motion.sensors.sensors[SonarLeft], 0.25f);
    ASSERT_EQ(bb.vision.posts.size(), 1u);
    // World post 0 is team 0's own goal's left post: the away goal's for team 1.
    EXPECT_EQ(bb.vision.posts[0].type, team == 0 ? pHomeLeft : pAwayLeft);
  }
}

TEST(BlackboardBuilder, TheTeamBallIsTheNewestSightingOursOrATeammates) {
  BlackboardBuilder builder;
  api::Blackboard t = board(); // we see the ball at (1000, 0), rolling +x at 100 mm/s
  Blackboard bb = builder.build(t);
  EXPECT_FLOAT_EQ(bb.stateEstimation.teamBallPos.x, 1000);
  EXPECT_FALSE(bb.stateEstimation.hadTeamBallUpdate);

  // We lose it; a teammate facing -x saw it at (-500, 300) rolling towards its own +x.
  t.utime += 1000000;
  t.vision.ballSeen = false;
  Broadcast mate;
  mate.data.robotPos = {0, 0, kPi};
  mate.data.ballPosAbs = {-500, 300, 0};
  mate.data.sharedStateEstimationBundle.haveBallUpdate = true;
  mate.data.sharedStateEstimationBundle.ballVelRRC = {200, 0, 0};
  t.receiver.messages.push_back({4, t.utime - 100000, encode_broadcast(mate)});
  bb = builder.build(t);
  EXPECT_TRUE(bb.stateEstimation.hadTeamBallUpdate);
  EXPECT_FLOAT_EQ(bb.stateEstimation.teamBallPos.x, -500);
  EXPECT_FLOAT_EQ(bb.stateEstimation.teamBallPos.y, 300);
  EXPECT_NEAR(bb.stateEstimation.teamBallVel.x, -200, 1e-3); // its +x is the field's -x
  EXPECT_NEAR(bb.stateEstimation.teamBallVel.y, 0, 1e-3);
  EXPECT_FLOAT_EQ(bb.stateEstimation.ballPos.x, 1000); // our own belief is unchanged

  // The same message again is no new update; our own sighting later wins again.
  t.utime += 33333;
  EXPECT_FALSE(builder.build(t).stateEstimation.hadTeamBallUpdate);
  t.vision.ballSeen = true;
  EXPECT_FLOAT_EQ(builder.build(t).stateEstimation.teamBallPos.x, 1000);
}
