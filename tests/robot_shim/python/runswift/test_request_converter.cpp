// Their BehaviourRequest -> Touchline's ActionCommand: units, signs, enums, the walk's
// ellipsoid, kicks, the head, LEDs, actions Touchline does not simulate, bad values.
#include "touchline/python/runswift/request_converter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "touchline/python/python_profile.hpp"

using namespace touchline;
using namespace touchline::python::runswift;
namespace AC = touchline::api::ActionCommand;

namespace {

BodyCommand walk(int forward, int left, float turn, float speed = 1) {
  BodyCommand b;
  b.actionType = WALK;
  b.forward = forward;
  b.left = left;
  b.turn = turn;
  b.speed = speed;
  return b;
}

BehaviourRequest with_body(const BodyCommand& body) {
  BehaviourRequest r;
  r.actions.body = body;
  return r;
}

} // namespace

TEST(RequestConverter, AWalkWithinTheLimitsIsTheSameMmAndRadPerSecondWithTheSameSigns) {
  const AC::Body b = convert_body(walk(120, -40, 0.3f));
  EXPECT_EQ(b.actionType, AC::ActionType::WALK);
  EXPECT_FLOAT_EQ(b.forward, 120);  // mm/s forward
  EXPECT_FLOAT_EQ(b.left, -40);     // mm/s, negative: to the right in both
  EXPECT_FLOAT_EQ(b.turn, 0.3f);    // rad/s counter-clockwise in both
  EXPECT_FLOAT_EQ(b.speed, 1);      // their speed is spent on the limits, not on the velocity
  const AC::Body back = convert_body(walk(-100, 50, -0.5f));
  EXPECT_FLOAT_EQ(back.forward, -100);
  EXPECT_FLOAT_EQ(back.left, 50);
  EXPECT_FLOAT_EQ(back.turn, -0.5f);
}

TEST(RequestConverter, ASingleAxisIsCutAtTheirMaximumWhichSpeedScalesFrom66To100Percent) {
  EXPECT_FLOAT_EQ(convert_body(walk(1000, 0, 0, 1)).forward, 300);
  EXPECT_NEAR(convert_body(walk(1000, 0, 0, 0)).forward, 0.66f * 300, 1e-3);
  EXPECT_NEAR(convert_body(walk(1000, 0, 0, 0.5f)).forward, 0.83f * 300, 1e-3);
  EXPECT_NEAR(convert_body(walk(0, -1000, 0, 1)).left, -200, 1e-3);
  EXPECT_NEAR(convert_body(walk(0, 0, 5, 1)).turn, 2, 1e-5);
  EXPECT_NEAR(convert_body(walk(0, 0, -5, 0)).turn, -1.32f, 1e-5);
  // speed outside [0, 1] is clamped as their walk clamps it
  EXPECT_FLOAT_EQ(convert_body(walk(1000, 0, 0, 7)).forward, 300);
}

TEST(RequestConverter, ACombinedWalkOutsideTheEllipsoidKeepsItsDirectionOnTheSurface) {
  const AC::Body b = convert_body(walk(300, 200, 2, 1)); // (1, 1, 1) in units of the maxima
  const float k = 1 / std::sqrt(3.f);
  EXPECT_NEAR(b.forward, 300 * k, 1e-2);
  EXPECT_NEAR(b.left, 200 * k, 1e-2);
  EXPECT_NEAR(b.turn, 2 * k, 1e-4);
  const float norm = std::hypot(b.forward / 300, b.left / 200, b.turn / 2);
  EXPECT_NEAR(norm, 1, 1e-5);
}

TEST(RequestConverter, AZeroWalkIsStandingAsTheirStandIs) {
  BodyCommand stand = walk(0, 0, 0);
  stand.power = 0.1f; // their stand(): walk(0, 0, 0, power 0.1, bend 0)
  EXPECT_EQ(convert_body(stand).actionType, AC::ActionType::STAND);
  BodyCommand none;
  EXPECT_EQ(convert_body(none).actionType, AC::ActionType::STAND);
  BodyCommand st;
  st.actionType = STAND;
  EXPECT_EQ(convert_body(st).actionType, AC::ActionType::STAND);
}

TEST(RequestConverter, AKickKeepsFootAndPowerAndItsTurnIsTheSwingDirection) {
  BodyCommand k;
  k.actionType = KICK;
  k.foot = FOOT_RIGHT;
  k.power = 0.7f;
  k.turn = 0.4f; // + left, counter-clockwise
  const AC::Body b = convert_body(k);
  EXPECT_EQ(b.actionType, AC::ActionType::KICK);
  EXPECT_EQ(b.foot, AC::Foot::RIGHT);
  EXPECT_FLOAT_EQ(b.power, 0.7f);
  EXPECT_FLOAT_EQ(b.bend, 0.4f);
  k.foot = FOOT_LEFT;
  k.power = 3; // clamped to their [0, 1]
  k.turn = -0.2f;
  const AC::Body left = convert_body(k);
  EXPECT_EQ(left.foot, AC::Foot::LEFT);
  EXPECT_FLOAT_EQ(left.power, 1);
  EXPECT_FLOAT_EQ(left.bend, -0.2f);
}

TEST(RequestConverter, ATurnDribbleIsOurDribbleTowardsItsTurn) {
  BodyCommand d;
  d.actionType = TURN_DRIBBLE;
  d.foot = FOOT_LEFT;
  d.power = 1;
  d.turn = 0.5f;
  const AC::Body b = convert_body(d);
  EXPECT_EQ(b.actionType, AC::ActionType::DRIBBLE);
  EXPECT_FLOAT_EQ(b.bend, 0.5f);
  EXPECT_EQ(b.foot, AC::Foot::LEFT);
}

TEST(RequestConverter, TheHeadIsTheSameAnglesSignsAndSpeeds) {
  HeadCommand h{0.5f, 0.3f, false, 0.8f, 0.25f};
  const AC::Head head = convert_head(h);
  EXPECT_FLOAT_EQ(head.yaw, 0.5f);   // + left in both
  EXPECT_FLOAT_EQ(head.pitch, 0.3f); // + down in both
  EXPECT_FALSE(head.isRelative);
  EXPECT_FLOAT_EQ(head.yawSpeed, 0.8f);
  EXPECT_FLOAT_EQ(head.pitchSpeed, 0.25f);
  EXPECT_TRUE(convert_head(HeadCommand{}).isRelative); // their default: relative
}

TEST(RequestConverter, TheChestButtonsColourIsTheChestLed) {
  EXPECT_EQ(led_colour({true, false, false}), 0xff0000);
  EXPECT_EQ(led_colour({false, true, true}), 0x00ffff);
  EXPECT_EQ(led_colour({true, true, true}), 0xffffff);
  EXPECT_EQ(led_colour({}), 0);
  RequestConverter c(nullptr);
  BehaviourRequest r;
  r.actions.leds.chestButton = {true, false, true};
  EXPECT_EQ(c.convert(r, 0).leds.chest, 0xff00ff);
}

TEST(RequestConverter, AnUnsimulatedActionStandsForItsDurationWithOneWarningPerType) {
  std::vector<std::string> warnings;
  RequestConverter c([&](const std::string& line) { warnings.push_back(line); });
  BodyCommand sit;
  sit.actionType = SIT;
  const int64_t start = 1000000;
  EXPECT_EQ(c.convert(with_body(sit), start).body.actionType, AC::ActionType::STAND);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "action SIT is not simulated: the robot stands for 3.05 s (its duration on the robot)");
  // Whatever is asked meanwhile, the action runs to its end (3.05 s on the robot).
  EXPECT_EQ(c.convert(with_body(walk(200, 0, 0)), start + 3049000).body.actionType, AC::ActionType::STAND);
  EXPECT_EQ(c.busy_with(), SIT);
  EXPECT_EQ(c.convert(with_body(walk(200, 0, 0)), start + 3050000).body.actionType, AC::ActionType::WALK);
  EXPECT_EQ(c.busy_with(), -1);
  // The same action again: no second warning; another one: its own.
  c.convert(with_body(sit), start + 4000000);
  BodyCommand signal;
  signal.actionType = SIGNAL_GOAL_LEFT;
  c.convert(with_body(signal), start + 8000000);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_NE(warnings[1].find("SIGNAL_GOAL_LEFT"), std::string::npos);
}

TEST(RequestConverter, AGoalieDiveBecomesOurDiveToTheSameSideWithNoWarning) {
  std::vector<std::string> warnings;
  RequestConverter c([&](const std::string& line) { warnings.push_back(line); });
  BodyCommand dive;
  dive.actionType = GOALIE_DIVE_RIGHT;
  EXPECT_EQ(c.convert(with_body(dive), 1000000).body.actionType, AC::ActionType::GOALIE_DIVE_RIGHT);
  EXPECT_EQ(c.busy_with(), -1); // the dive latches in motion (DiveGenerator), not here
  dive.actionType = GOALIE_DIVE_LEFT;
  EXPECT_EQ(c.convert(with_body(dive), 1010000).body.actionType, AC::ActionType::GOALIE_DIVE_LEFT);
  // The next frame's walk goes through: motion ignores it while the robot is down.
  EXPECT_EQ(c.convert(with_body(walk(200, 0, 0)), 1020000).body.actionType, AC::ActionType::WALK);
  EXPECT_TRUE(warnings.empty());
  EXPECT_TRUE(is_simulated(GOALIE_DIVE_LEFT));
  EXPECT_TRUE(is_simulated(GOALIE_DIVE_RIGHT));
}

TEST(RequestConverter, TimeGoingBackwardsEndsAnActionInProgress) {
  RequestConverter c(nullptr);
  BodyCommand sit;
  sit.actionType = SIT;
  c.convert(with_body(sit), 5000000);
  EXPECT_EQ(c.busy_with(), SIT);
  // a new run of frames (a restarted match, a replay) starts from time 0
  EXPECT_EQ(c.convert(with_body(walk(100, 0, 0)), 0).body.actionType, AC::ActionType::WALK);
}

TEST(RequestConverter, EveryActionTypeConvertsWithoutThrowing) {
  RequestConverter c(nullptr);
  int64_t t = 0;
  for (int type = 0; type < NUM_ACTION_TYPES; ++type) {
    BodyCommand b;
    b.actionType = type;
    c.reset();
    const AC::All all = c.convert(with_body(b), t += 1000000);
    if (!is_simulated(type)) {
      EXPECT_EQ(all.body.actionType, AC::ActionType::STAND) << action_type_name(type);
      EXPECT_GT(action_duration_s(type), 0) << action_type_name(type);
    }
  }
}

TEST(RequestConverter, AValueNoRobotCouldExecuteIsAnErrorNamingTheField) {
  RequestConverter c(nullptr);
  auto message = [&](const BehaviourRequest& r) {
    try {
      c.convert(r, 0);
    } catch (const touchline::python::RequestError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  BehaviourRequest r;
  r.actions.body.actionType = 99;
  EXPECT_EQ(message(r), "BehaviourRequest.actions.body.actionType is 99, not a robot.ActionType");
  r = {};
  r.actions.body.foot = 2;
  EXPECT_EQ(message(r), "BehaviourRequest.actions.body.foot is 2, not a robot.Foot");
  r = {};
  r.actions.body.turn = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(message(r), "BehaviourRequest.actions.body.turn is nan, not a finite number");
  r = {};
  r.actions.head.yaw = std::numeric_limits<float>::infinity();
  EXPECT_EQ(message(r), "BehaviourRequest.actions.head.yaw is inf, not a finite number");
}

TEST(RequestConverter, EveryActionTypeHasItsName) {
  EXPECT_STREQ(action_type_name(WALK), "WALK");
  EXPECT_STREQ(action_type_name(SIGNAL_FULL_TIME), "SIGNAL_FULL_TIME");
  EXPECT_STREQ(action_type_name(-1), "?");
  EXPECT_STREQ(action_type_name(NUM_ACTION_TYPES + 1), "?");
}
