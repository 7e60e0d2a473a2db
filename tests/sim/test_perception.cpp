// The perception pipeline's geometry, hand-worked with noise and faults off: what is in
// view, where, what other robots hide, who is a teammate, what the sonar hears.
#include "touchline/sim/perception.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "perception_scenes.hpp"
#include "touchline/angles.hpp"
#include "touchline/sim/occlusion.hpp"

namespace touchline::sim {
namespace {

using testing::ball_at;
using testing::find;
using testing::exact;
using testing::kHeadDown;
using testing::kHeadUp;
using testing::viewer;

const Field kField; // SPL 2011


int count(const std::vector<Observation>& seen, ObjectKind kind) {
  int n = 0;
  for (const Observation& o : seen) n += o.kind == kind;
  return n;
}

TEST(Landmarks, IdsAndPositionsFollowTheFrameContract) {
  const auto marks = field_landmarks(kField);
  ASSERT_EQ(marks.size(), 12u);
  struct Expected {
    ObjectKind kind;
    int id;
    float x, y;
  };
  const Expected expected[] = {
      {ObjectKind::kGoalPost, 0, -3000, -700},   // team 0's goal, left seen from the centre
      {ObjectKind::kGoalPost, 1, -3000, 700},
      {ObjectKind::kGoalPost, 2, 3000, 700},     // team 1's goal, left seen from the centre
      {ObjectKind::kGoalPost, 3, 3000, -700},
      {ObjectKind::kFieldCorner, 0, -3000, -2000}, // counter-clockwise from (-x, -y)
      {ObjectKind::kFieldCorner, 1, 3000, -2000},
      {ObjectKind::kFieldCorner, 2, 3000, 2000},
      {ObjectKind::kFieldCorner, 3, -3000, 2000},
      {ObjectKind::kCentreLineEnd, 0, 0, -2000},
      {ObjectKind::kCentreLineEnd, 1, 0, 2000},
      {ObjectKind::kPenaltyMark, 0, -1200, 0},   // 1800 mm in front of team 0's goal line
      {ObjectKind::kPenaltyMark, 1, 1200, 0},
  };
  for (size_t i = 0; i < marks.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(marks[i].kind, expected[i].kind);
    EXPECT_EQ(marks[i].id, expected[i].id);
    EXPECT_EQ(marks[i].x_mm, expected[i].x);
    EXPECT_EQ(marks[i].y_mm, expected[i].y);
  }
  EXPECT_EQ(marks[0].y_mm, kField.goal_post(0, true).y_mm);
  EXPECT_EQ(marks[2].y_mm, kField.goal_post(1, true).y_mm);
}

TEST(Perception, WithoutNoiseTheObservationsAreTheGeometry) {
  // At the centre spot facing the +x goal, head up (4000 mm): the ball 1500 ahead, team
  // 1's posts at (3000, +-700) 13.1 degrees either side, its penalty mark 1200 ahead. The
  // corners (33.7 degrees off) and the centre-line ends (90) are outside the 60-degree view.
  Perception perception(kField, exact(), 1);
  const Viewer me = viewer(0, 1, 0, 0, 0);
  const auto seen = perception.observe(me, {me}, ball_at(1500, 0), 0);
  ASSERT_EQ(seen.size(), 4u);

  EXPECT_EQ(seen[0].kind, ObjectKind::kBall);
  EXPECT_EQ(seen[0].distance_mm, 1500.f);
  EXPECT_EQ(seen[0].heading_rad, 0.f);
  EXPECT_EQ(seen[0].image_x, 0.5f);

  // sqrt(3000^2 + 700^2) = 3080.584 mm, atan2(700, 3000) = 0.229232 rad,
  // image_x = (0.229232 + pi/6) / (pi/3) = 0.718900 (1 is the left edge).
  EXPECT_EQ(seen[1].kind, ObjectKind::kGoalPost);
  EXPECT_EQ(seen[1].id, 2);
  EXPECT_NEAR(seen[1].distance_mm, 3080.584f, 1e-2f);
  EXPECT_NEAR(seen[1].heading_rad, 0.229232f, 1e-5f);
  EXPECT_NEAR(seen[1].image_x, 0.718900f, 1e-5f);
  EXPECT_EQ(seen[2].kind, ObjectKind::kGoalPost);
  EXPECT_EQ(seen[2].id, 3);
  EXPECT_NEAR(seen[2].heading_rad, -0.229232f, 1e-5f);
  EXPECT_NEAR(seen[2].image_x, 1 - 0.718900f, 1e-5f);

  EXPECT_EQ(seen[3].kind, ObjectKind::kPenaltyMark);
  EXPECT_EQ(seen[3].id, 1);
  EXPECT_EQ(seen[3].distance_mm, 1200.f);
}

TEST(Perception, WithoutNoiseEveryObservationIsBitForBitTheCameraModel) {
  // A robot turned and with its head turned, in a busy scene: each observation equals
  // Algorithm 2.3's sighting exactly (noise of zero changes no bit).
  Perception perception(kField, exact(), 7);
  // Facing -x, head 0.3 rad left and a little up (3059 mm): the ball, a teammate, an
  // opponent and both penalty marks are all in view.
  const Viewer me = viewer(1, 3, 1500, 300, kPi, 0.3f, -0.3f);
  const std::vector<Viewer> robots{me, viewer(1, 2, 500, 0, 0), viewer(0, 4, 0, -800, 1)};
  const auto seen = perception.observe(me, robots, ball_at(700, -200), 0);
  ASSERT_EQ(seen.size(), 5u);
  EXPECT_TRUE(find(seen, ObjectKind::kPenaltyMark, 0) && find(seen, ObjectKind::kPenaltyMark, 1));
  EXPECT_TRUE(find(seen, ObjectKind::kTeammate, 2) && find(seen, ObjectKind::kOpponent, 4));
  for (const Observation& o : seen) {
    float x = 0, y = 0;
    if (o.kind == ObjectKind::kBall) {
      x = 700, y = -200;
    } else if (o.kind == ObjectKind::kTeammate || o.kind == ObjectKind::kOpponent) {
      const Viewer& r = o.kind == ObjectKind::kTeammate ? robots[1] : robots[2];
      x = r.body.x_mm, y = r.body.y_mm;
    } else {
      for (const Landmark& m : perception.landmarks())
        if (m.kind == o.kind && m.id == o.id) x = m.x_mm, y = m.y_mm;
    }
    const auto s = sight(CameraDef{}, me.body, me.head_yaw_rad, me.head_pitch_rad, x, y);
    ASSERT_TRUE(s);
    EXPECT_EQ(o.distance_mm, s->distance_mm);
    EXPECT_EQ(o.heading_rad, s->heading_rad);
    EXPECT_EQ(o.image_x, s->image_x);
  }
}

TEST(Perception, CornerBeyondTheRangeIsNotSeen) {
  // Corner 2 (3000, 2000) is 1414 mm away, straight ahead: the head down sees only 1000 mm.
  Perception perception(kField, exact(), 1);
  const Viewer down = viewer(0, 1, 2000, 1000, kPi / 4, 0, kHeadDown);
  EXPECT_FALSE(find(perception.observe(down, {down}, ball_at(0, 0), 0), ObjectKind::kFieldCorner, 2));
  const Viewer up = viewer(0, 1, 2000, 1000, kPi / 4, 0, kHeadUp);
  const auto seen = perception.observe(up, {up}, ball_at(0, 0), 0);
  const Observation* corner = find(seen, ObjectKind::kFieldCorner, 2);
  ASSERT_TRUE(corner);
  EXPECT_NEAR(corner->distance_mm, 1414.2136f, 1e-2f);
  EXPECT_NEAR(corner->heading_rad, 0.f, 1e-6f);
}

TEST(Perception, NothingBehindTheRobotIsSeen) {
  // Facing -x from the centre spot: the ball and a robot 1000 mm behind are not seen;
  // team 0's posts and penalty mark, ahead, are.
  Perception perception(kField, exact(), 1);
  const Viewer me = viewer(0, 1, 0, 0, kPi);
  const auto seen = perception.observe(me, {me, viewer(1, 1, 1000, 0, 0)}, ball_at(1000, 0), 0);
  EXPECT_EQ(count(seen, ObjectKind::kBall), 0);
  EXPECT_EQ(count(seen, ObjectKind::kOpponent), 0);
  EXPECT_TRUE(find(seen, ObjectKind::kGoalPost, 0));
  EXPECT_TRUE(find(seen, ObjectKind::kGoalPost, 1));
  EXPECT_TRUE(find(seen, ObjectKind::kPenaltyMark, 0));
  EXPECT_FALSE(find(seen, ObjectKind::kGoalPost, 2));
}

TEST(Perception, HeadYawTurnsTheView) {
  // Facing +x with the head turned 90 degrees left: the centre-line end at (0, 2000) is
  // seen straight along the head, at heading +90 degrees; the ball ahead of the body is not.
  Perception perception(kField, exact(), 1);
  const Viewer me = viewer(0, 1, 0, 0, 0, kPi / 2);
  const auto seen = perception.observe(me, {me}, ball_at(1000, 0), 0);
  EXPECT_EQ(count(seen, ObjectKind::kBall), 0);
  const Observation* end = find(seen, ObjectKind::kCentreLineEnd, 1);
  ASSERT_TRUE(end);
  EXPECT_NEAR(end->heading_rad, kPi / 2, 1e-6f);
  EXPECT_NEAR(end->image_x, 0.5f, 1e-6f);
}

TEST(Perception, ARobotHidesTheBallBehindItButNotBesideIt) {
  Perception perception(kField, exact(), 1);
  const Viewer me = viewer(0, 1, -800, 0, 0);
  const BallTruth ball = ball_at(1000, 0);
  // In the line of sight, nearer than the ball: hidden. The robot itself is still seen.
  auto seen = perception.observe(me, {me, viewer(1, 1, 0, 0, kPi)}, ball, 0);
  EXPECT_EQ(count(seen, ObjectKind::kBall), 0);
  EXPECT_TRUE(find(seen, ObjectKind::kOpponent, 1));
  EXPECT_FALSE(find(seen, ObjectKind::kPenaltyMark, 1)); // (1200, 0): behind it too
  EXPECT_TRUE(find(seen, ObjectKind::kGoalPost, 2));     // sight line passes 145 mm from it
  // 100 mm off the line (inside the 120 mm body): hidden; 300 mm off: seen.
  EXPECT_EQ(count(perception.observe(me, {me, viewer(1, 1, 0, 100, 0)}, ball, 0), ObjectKind::kBall), 0);
  EXPECT_EQ(count(perception.observe(me, {me, viewer(1, 1, 0, 300, 0)}, ball, 0), ObjectKind::kBall), 1);
  // Beyond the ball: the ball is in front of it.
  EXPECT_EQ(count(perception.observe(me, {me, viewer(1, 1, 1500, 0, 0)}, ball, 0), ObjectKind::kBall), 1);

  PerceptionDef see_through = exact();
  see_through.occluder_radius_mm = 0;
  Perception xray(kField, see_through, 1);
  EXPECT_EQ(count(xray.observe(me, {me, viewer(1, 1, 0, 0, kPi)}, ball, 0), ObjectKind::kBall), 1);
}

TEST(Occlusion, BodyDiscGeometry) {
  const Pose2D eye{0, 0, 0};
  EXPECT_TRUE(body_hides(eye, {500, 0, 0}, 120, 1000, 0));
  EXPECT_TRUE(body_hides(eye, {500, 119, 0}, 120, 1000, 0));
  EXPECT_FALSE(body_hides(eye, {500, 121, 0}, 120, 1000, 0));
  EXPECT_FALSE(body_hides(eye, {-500, 0, 0}, 120, 1000, 0));  // behind the eye
  EXPECT_FALSE(body_hides(eye, {1500, 0, 0}, 120, 1000, 0));  // beyond the target
  // A ball at a robot's toes (100 mm ahead of its centre): hidden from behind it, seen from the front.
  EXPECT_TRUE(body_hides(eye, {1000, 0, 0}, 120, 1100, 0));
  EXPECT_FALSE(body_hides({2000, 0, 0}, {1000, 0, 0}, 120, 1100, 0));
  // Robots pressed into each other: the eye inside the other's disc hides nothing.
  EXPECT_FALSE(body_hides(eye, {100, 0, 0}, 120, 1000, 0));
  EXPECT_FALSE(body_hides(eye, {500, 0, 0}, 0, 1000, 0)); // radius 0: no occlusion
}

TEST(Perception, TeammatesAndOpponentsAreLabelledAndNoRobotSeesItself) {
  Perception perception(kField, exact(), 1);
  const Viewer me = viewer(0, 1, -2000, 0, 0);
  const std::vector<Viewer> robots{
      viewer(1, 1, -1000, 0, kPi),     // the opponent with my player number
      me,
      viewer(0, 2, -1000, 400, 0),     // a teammate
      viewer(1, 3, 0, -500, kPi),      // another opponent
      viewer(0, 3, -3000, 0, 0),       // a teammate behind me: not seen
  };
  const auto seen = perception.observe(me, robots, ball_at(5000, 0), 0);
  ASSERT_TRUE(find(seen, ObjectKind::kOpponent, 1));
  ASSERT_TRUE(find(seen, ObjectKind::kOpponent, 3));
  ASSERT_TRUE(find(seen, ObjectKind::kTeammate, 2));
  EXPECT_FALSE(find(seen, ObjectKind::kTeammate, 1)); // myself
  EXPECT_FALSE(find(seen, ObjectKind::kTeammate, 3)); // behind
  EXPECT_EQ(count(seen, ObjectKind::kTeammate) + count(seen, ObjectKind::kOpponent), 3);
  EXPECT_FLOAT_EQ(find(seen, ObjectKind::kOpponent, 1)->distance_mm, 1000.f);
  // Robots come after the ball and the landmarks, in the order given.
  std::vector<ObjectKind> robot_kinds;
  for (const Observation& o : seen)
    if (o.kind == ObjectKind::kTeammate || o.kind == ObjectKind::kOpponent) robot_kinds.push_back(o.kind);
  EXPECT_EQ(robot_kinds, (std::vector<ObjectKind>{ObjectKind::kOpponent, ObjectKind::kTeammate,
                                                  ObjectKind::kOpponent}));
  // Seen by the opponent facing me: the labels turn round.
  const auto theirs = perception.observe(robots[0], robots, ball_at(5000, 0), 0);
  EXPECT_TRUE(find(theirs, ObjectKind::kOpponent, 1));  // me, 1000 mm ahead of it
  EXPECT_TRUE(find(theirs, ObjectKind::kOpponent, 3));  // my teammate 3, 2000 mm ahead of it
  EXPECT_FALSE(find(theirs, ObjectKind::kTeammate, 1)); // itself
}

TEST(Perception, SonarHearsARobotAheadInTheCorridor) {
  PerceptionDef def = exact();
  def.sonar_sees_goal_posts = false;
  Perception perception(kField, def, 1);
  const Viewer me = viewer(0, 1, 0, 0, kPi / 2); // facing +y
  // 500 mm ahead and 50 mm to its right (+x is right when facing +y).
  SonarReading r = perception.sonar(me, {me, viewer(1, 1, 50, 500, 0)}, 0);
  EXPECT_FLOAT_EQ(r.right, 0.5f);
  EXPECT_FLOAT_EQ(r.left, 1.f);
  // On the left, nearer than another on the left: the nearer wins.
  r = perception.sonar(me, {viewer(0, 2, -40, 700, 0), me, viewer(1, 2, -60, 300, 0)}, 0);
  EXPECT_FLOAT_EQ(r.left, 0.3f);
  EXPECT_FLOAT_EQ(r.right, 1.f);
  // Behind, beyond the range, or outside the corridor: nothing. Alone: nothing.
  r = perception.sonar(me, {me, viewer(1, 1, 0, -500, 0), viewer(1, 2, 0, 1200, 0), viewer(1, 3, 300, 500, 0)}, 0);
  EXPECT_FLOAT_EQ(r.left, 1.f);
  EXPECT_FLOAT_EQ(r.right, 1.f);
  r = perception.sonar(me, {me}, 0);
  EXPECT_FLOAT_EQ(r.left, 1.f);
  EXPECT_FLOAT_EQ(r.right, 1.f);
}

TEST(Perception, SonarHearsGoalPostsWhenConfigured) {
  // 600 mm in front of post 2 (3000, 700), facing it.
  const Viewer me = viewer(0, 1, 2400, 700, 0);
  Perception hears(kField, exact(), 1);
  EXPECT_FLOAT_EQ(hears.sonar(me, {me}, 0).right, 0.6f);
  PerceptionDef deaf_def = exact();
  deaf_def.sonar_sees_goal_posts = false;
  Perception deaf(kField, deaf_def, 1);
  EXPECT_FLOAT_EQ(deaf.sonar(me, {me}, 0).right, 1.f);
}

TEST(Perception, TouchIsFeltFromEveryOtherRobotWithinReachButNotFromItself) {
  Perception perception(kField, exact(), 1);
  const Viewer me = viewer(0, 1, 0, 0, kPi / 2); // facing +y
  // A teammate 200 mm to its left (-x), an opponent 250 mm behind, one 400 mm ahead (out of reach).
  const Touch t = perception.touch(me, {viewer(0, 2, -200, 0, 0), me, viewer(1, 1, 0, -250, 0), viewer(1, 2, 0, 400, 0)});
  EXPECT_TRUE(t.left);
  EXPECT_TRUE(t.back);
  EXPECT_FALSE(t.front_left || t.front_right || t.right);
  EXPECT_FALSE(perception.touch(me, {me}).any());
}

TEST(Perception, AGoalPostWithinReachIsFeltLikeARobot) {
  const Pose2D post = kField.goal_post(0, true); // team 0's goal at -x
  // 150 mm in front of the post facing it (+x of the robot towards -x of the field): the
  // foot bumpers; 250 mm beside it: out of a post's reach, though a robot there would touch.
  const Viewer facing = viewer(0, 1, post.x_mm + 150, post.y_mm, kPi);
  const Viewer beside = viewer(0, 2, post.x_mm, post.y_mm + 250, 0);
  Perception perception(kField, exact(), 1);
  const Touch t = perception.touch(facing, {facing});
  EXPECT_TRUE(t.front_left || t.front_right);
  EXPECT_FALSE(t.left || t.right || t.back);
  EXPECT_FALSE(perception.touch(beside, {beside}).any());
  PerceptionDef numb_def = exact();
  numb_def.touch.post_distance_mm = 0;
  EXPECT_FALSE(Perception(kField, numb_def, 1).touch(facing, {facing}).any()) << "post_distance_mm 0: no post is felt";
}

TEST(Perception, PerceiveIsObserveAndSonarPerRobotInOrder) {
  const std::vector<Viewer> robots{viewer(0, 1, -500, 0, 0), viewer(1, 1, 500, 50, kPi), viewer(0, 2, 0, 800, -1)};
  const BallTruth ball = ball_at(0, 0);
  Perception together(kField, PerceptionDef{}, 99);
  Perception apart(kField, PerceptionDef{}, 99);
  const auto percepts = together.perceive(robots, ball, 0);
  ASSERT_EQ(percepts.size(), robots.size());
  for (size_t i = 0; i < robots.size(); ++i) {
    const auto seen = apart.observe(robots[i], robots, ball, 0);
    const SonarReading sonar = apart.sonar(robots[i], robots, 0);
    EXPECT_EQ(percepts[i].id, robots[i].id);
    ASSERT_EQ(percepts[i].seen.size(), seen.size());
    for (size_t k = 0; k < seen.size(); ++k) {
      EXPECT_EQ(percepts[i].seen[k].distance_mm, seen[k].distance_mm);
      EXPECT_EQ(percepts[i].seen[k].heading_rad, seen[k].heading_rad);
    }
    EXPECT_EQ(percepts[i].sonar.left, sonar.left);
    EXPECT_EQ(percepts[i].sonar.right, sonar.right);
    EXPECT_EQ(percepts[i].touch.any(), apart.touch(robots[i], robots).any());
  }
  // Robots 1 and 2 face each other 1000 mm apart: just out of the 1000 mm sonar range.
  EXPECT_FLOAT_EQ(percepts[0].sonar.left, 1.f);
  EXPECT_FLOAT_EQ(percepts[0].sonar.right, 1.f);
}

} // namespace
} // namespace touchline::sim
