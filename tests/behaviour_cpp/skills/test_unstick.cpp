// Unstick (issue #17: no robot stuck more than 10 s): turning on the spot for long becomes a
// walk without turning, towards the ball, the team ball, the field's centre or the goalie's
// home; the same hand-worked cases as tests/behaviour_py/test_unstick.py.
#include "touchline/behaviour/skills/unstick.hpp"

#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "boards.hpp"
#include "touchline/behaviour/skills/actioncommand.hpp"
#include "touchline/behaviour/skills/robot_limits.hpp"
#include "touchline/behaviour/skills/team.hpp"
#include "touchline/behaviour/skills/team_comm.hpp"

using namespace touchline::api;
using namespace touchline::behaviour::skills;
using touchline::behaviour::test::teamBoard;

namespace {

using AT = ActionCommand::ActionType;
constexpr int64_t FRAME_US = 33333;
constexpr int STUCK_FRAME = 59; ///< at 0.06 rad a frame, the tick the odometry has turned over UNSTICK_TURN_RAD

struct Spin {
  AbsCoord pos{};
  float turnPerFrame = 0.06f;  ///< rad the odometry turns every frame
  float stepPerFrame = 0.f;    ///< mm the odometry steps forward (x) every frame ...
  bool localised = true;       ///< ... which localisation sees along field x from pos (false: it stays at pos)
  bool seen = true;            ///< the own ball (1000 mm ahead of the field origin) seen recently
  int player = 2;
  std::vector<TeamMessage> messages{};
  float ballX = 1000.f, ballY = 0.f;
};

/// A Spin with `change` applied (C++17 has no designated initialisers).
template <typename Change>
Spin spinWith(Change change) {
  Spin spin;
  change(spin);
  return spin;
}

/// Frame `frame` of a robot whose odometry turns and steps as `spin` says.
Blackboard spinBoard(int frame, const Spin& spin, bool penalised = false) {
  AbsCoord pos = spin.pos;
  if (spin.localised) pos.x += spin.stepPerFrame * static_cast<float>(frame);
  Blackboard board = teamBoard(pos, spin.ballX, spin.ballY, spin.seen, spin.seen ? 0 : 1000, GameState::PLAYING,
                               spin.player, penalised, false, spin.messages, frame * FRAME_US);
  board.motion.odometry = {spin.stepPerFrame * static_cast<float>(frame), 0.f,
                           spin.turnPerFrame * static_cast<float>(frame)};
  return board;
}

/// The bodies Unstick returns for `frames` frames of turning requests (1.5 rad/s).
std::vector<ActionCommand::Body> run(Unstick& unstick, int frames, const Spin& spin,
                                     std::optional<FieldPoint> target = std::nullopt) {
  const ActionCommand::Body turning = touchline::behaviour::actioncommand::walk(0.f, 0.f, 1.5f);
  std::vector<ActionCommand::Body> bodies;
  for (int frame = 0; frame < frames; ++frame) bodies.push_back(unstick.tick(spinBoard(frame, spin), turning, target));
  return bodies;
}

/// A frame's motion along a path: mm stepped forward, rad turned.
struct Step {
  float forward_mm = 0.f;
  float turn_rad = 0.f;
};

/// `frames` copies of `step`, appended to `path`.
std::vector<Step>& repeat(std::vector<Step>& path, const Step& step, int frames) {
  path.insert(path.end(), static_cast<size_t>(frames), step);
  return path;
}

/// The bodies Unstick returns for turning requests (1.5 rad/s) at the field origin (frame 0)
/// and then along `path`, a Step per frame: odometry and localisation see the steps along
/// field x (the test's odometry steps along its own x); the ball 1000 mm ahead of the origin.
std::vector<ActionCommand::Body> runPath(Unstick& unstick, const std::vector<Step>& path) {
  const ActionCommand::Body turning = touchline::behaviour::actioncommand::walk(0.f, 0.f, 1.5f);
  std::vector<ActionCommand::Body> bodies;
  float x = 0.f, theta = 0.f;
  for (size_t frame = 0; frame <= path.size(); ++frame) {
    if (frame > 0) {
      x += path[frame - 1].forward_mm;
      theta += path[frame - 1].turn_rad;
    }
    Blackboard board = teamBoard({x, 0.f, 0.f}, 1000.f, 0.f, true, 0, GameState::PLAYING, 2, false, false, {},
                                 static_cast<int64_t>(frame) * FRAME_US);
    board.motion.odometry = {x, 0.f, theta};
    bodies.push_back(unstick.tick(board, turning, std::nullopt));
  }
  return bodies;
}

/// The recovery walk with the ball 1000 mm ahead: straight at it, at full speed.
void expectRecovery(const ActionCommand::Body& body, int i) {
  EXPECT_EQ(body.actionType, AT::WALK) << i;
  EXPECT_NEAR(body.forward, MAX_FORWARD, 1e-3f) << i;
  EXPECT_NEAR(body.left, 0.f, 1e-3f) << i;
  EXPECT_EQ(body.turn, 0.f) << i;
}

constexpr Step SPIN{0.f, 0.06f}; ///< 1.8 rad/s on the spot: STUCK_FRAME of them turn over UNSTICK_TURN_RAD

} // namespace

TEST(Unstick, TurningOnTheSpotBecomesAWalkToTheBallWithoutTurningUntilItHasMoved) {
  Unstick unstick;
  std::vector<Step> path;
  repeat(path, SPIN, STUCK_FRAME);
  repeat(path, {6.f, 0.f}, UNSTICK_RECOVER_FRAMES - 1); // 354 mm
  repeat(path, {}, 1);
  const auto bodies = runPath(unstick, path);
  for (int i = 0; i < STUCK_FRAME; ++i) EXPECT_FLOAT_EQ(bodies[i].turn, 1.5f) << i;
  for (int i = STUCK_FRAME; i < STUCK_FRAME + UNSTICK_RECOVER_FRAMES; ++i) expectRecovery(bodies[i], i);
  EXPECT_FLOAT_EQ(bodies.back().turn, 1.5f); // moved away from the turning: the request again
}

TEST(Unstick, ABlockedRecoveryGoesOnUntilTheTurningHasLeftTheWindow) {
  Unstick unstick;
  std::vector<Step> path;
  repeat(path, SPIN, STUCK_FRAME);
  repeat(path, {}, UNSTICK_WINDOW_FRAMES + UNSTICK_RECOVER_FRAMES);
  const auto bodies = runPath(unstick, path);
  for (int i = STUCK_FRAME; i < UNSTICK_WINDOW_FRAMES; ++i) expectRecovery(bodies[i], i);
  EXPECT_FLOAT_EQ(bodies.back().turn, 1.5f);
}

TEST(Unstick, AWalkBeforeTheTurningDoesNotHideIt) {
  Unstick unstick;
  std::vector<Step> path;
  repeat(path, {6.f, 0.f}, 100); // 600 mm, then the spin
  repeat(path, SPIN, STUCK_FRAME);
  const auto bodies = runPath(unstick, path);
  EXPECT_FLOAT_EQ(bodies[bodies.size() - 2].turn, 1.5f);
  expectRecovery(bodies.back(), static_cast<int>(bodies.size()) - 1);
}

TEST(Unstick, TheWindowAndLimitTheCasesRelyOn) {
  EXPECT_LT(0.06f * (STUCK_FRAME - 1), UNSTICK_TURN_RAD);
  EXPECT_GT(0.06f * STUCK_FRAME, UNSTICK_TURN_RAD);
  EXPECT_LT(0.011f * (UNSTICK_WINDOW_FRAMES - 1), UNSTICK_TURN_RAD);
  EXPECT_LT(100 + STUCK_FRAME, UNSTICK_WINDOW_FRAMES); // the walk before the spin is in the window
  EXPECT_GT(6.f * (UNSTICK_RECOVER_FRAMES - 1), UNSTICK_MOVE_MM);
}

TEST(Unstick, WalkingOrTurningSlowlyIsNotStuck) {
  Unstick walking, slow;
  for (const auto& b : run(walking, 400, spinWith([](Spin& s) { s.stepPerFrame = 6.f; })))
    EXPECT_FLOAT_EQ(b.turn, 1.5f); // 354 mm in 59 frames
  for (const auto& b : run(slow, 400, spinWith([](Spin& s) { s.turnPerFrame = 0.011f; })))
    EXPECT_FLOAT_EQ(b.turn, 1.5f); // 3.3 rad in 10 s
}

TEST(Unstick, AWalkThatStepsOnInOdometryOnlyIsStuck) {
  Unstick unstick;
  const auto bodies = run(unstick, STUCK_FRAME + 1, spinWith([](Spin& s) {
                            s.stepPerFrame = 6.f;
                            s.localised = false;
                          }));
  EXPECT_FLOAT_EQ(bodies[STUCK_FRAME - 1].turn, 1.5f);
  EXPECT_EQ(bodies[STUCK_FRAME].turn, 0.f);
}

TEST(Unstick, WithoutTheOwnBallItWalksToTheTeamBallElseTheCentreAndTheGoalieHome) {
  Unstick centre, team, goalie;
  // No ball known: back to the centre, 500 mm behind.
  const Spin behind = spinWith([](Spin& s) {
    s.pos = {500.f, 0.f, 0.f};
    s.seen = false;
  });
  EXPECT_NEAR(run(centre, STUCK_FRAME + 1, behind).back().forward, -MAX_BACKWARD, 1e-3f);
  const TeamInfo info{3, ROLE_DEFENDER, true, false, false, 500, 0, 400};
  const Spin teamBall = spinWith([&](Spin& s) {
    s.seen = false;
    s.messages = {{3, STUCK_FRAME * FRAME_US, encodeMessage(info)}};
  });
  const ActionCommand::Body toTeamBall = run(team, STUCK_FRAME + 1, teamBall).back(); // 400 mm to the left
  EXPECT_NEAR(toTeamBall.forward, 0.f, 1e-3f);
  EXPECT_NEAR(toTeamBall.left, 200.f, 1e-3f);
  EXPECT_EQ(toTeamBall.turn, 0.f);
  const ActionCommand::Body home =
      run(goalie, STUCK_FRAME + 1, spinWith([](Spin& s) {
            s.pos = {-2000.f, 0.f, 0.f};
            s.player = 1;
          }),
          FieldPoint{-2700.f, 0.f})
          .back();
  EXPECT_NEAR(home.forward, -MAX_BACKWARD, 1e-3f);
  EXPECT_NEAR(home.left, 0.f, 1e-3f);
  EXPECT_EQ(home.turn, 0.f);
}

TEST(Unstick, TheTeamUnsticksInPlayOnlyAndStartsAfreshAfterAPenalty) {
  Team team(ROLE_STRIKER);
  const Spin left = spinWith([](Spin& s) { // to the left: the striker turns on the spot to face the goal
    s.ballX = 0.f;
    s.ballY = 1000.f;
  });
  const int frames = STUCK_FRAME - 1;
  for (int frame = 0; frame < frames; ++frame) team.tick(spinBoard(frame, left));
  team.tick(spinBoard(frames, left, true));
  for (int frame = frames + 1; frame < frames + 1 + STUCK_FRAME; ++frame) // the window starts again
    EXPECT_LT(team.tick(spinBoard(frame, left)).body.turn, 0.f) << frame;
  const ActionCommand::Body body = team.tick(spinBoard(frames + 1 + STUCK_FRAME, left)).body;
  EXPECT_EQ(body.turn, 0.f); // stuck in play: sideways to the ball
  EXPECT_NEAR(body.left, 200.f, 1e-3f);
}
