// Field geometry: where the lines, carpet, goals and goal boxes are.
#include "touchline/sim/field.hpp"

#include <gtest/gtest.h>

namespace touchline::sim {
namespace {

FieldDef modern_field() {
  FieldDef def;
  def.length_mm = 9000;
  def.width_mm = 6000;
  def.goal_width_mm = 1500;
  return def;
}

TEST(Field, InsideLinesIncludesTheLinesAndNothingBeyond) {
  const Field field; // 6000 x 4000
  EXPECT_TRUE(field.inside_lines(0, 0));
  EXPECT_TRUE(field.inside_lines(3000, 2000));   // the corner, on the lines' outer edge
  EXPECT_TRUE(field.inside_lines(-3000, -2000));
  EXPECT_FALSE(field.inside_lines(3001, 0));
  EXPECT_FALSE(field.inside_lines(0, -2001));
}

TEST(Field, OnCarpetReachesTheBorderOnEverySide) {
  const Field field; // border 700
  EXPECT_TRUE(field.on_carpet(3700, 2700));
  EXPECT_TRUE(field.on_carpet(-3700, -2700));
  EXPECT_TRUE(field.on_carpet(3500, 0));     // off the field, still on the carpet
  EXPECT_FALSE(field.inside_lines(3500, 0));
  EXPECT_FALSE(field.on_carpet(3701, 0));
  EXPECT_FALSE(field.on_carpet(0, 2701));
  EXPECT_FALSE(field.on_carpet(-3701, 0));
  EXPECT_FALSE(field.on_carpet(0, -2701));
}

struct PostCase {
  FieldDef def;
  int team;
  bool left;
  float x, y;
};

class GoalPosts : public ::testing::TestWithParam<PostCase> {};

TEST_P(GoalPosts, StandOnTheGoalLineAHalfGoalWidthOut) {
  const PostCase& c = GetParam();
  const Pose2D post = Field(c.def).goal_post(c.team, c.left);
  EXPECT_FLOAT_EQ(post.x_mm, c.x);
  EXPECT_FLOAT_EQ(post.y_mm, c.y);
}

// Team 0 defends -x; "left" is seen from the centre looking at that goal.
INSTANTIATE_TEST_SUITE_P(
    BothFields, GoalPosts,
    ::testing::Values(PostCase{FieldDef{}, 0, true, -3000, -700},
                      PostCase{FieldDef{}, 0, false, -3000, 700},
                      PostCase{FieldDef{}, 1, true, 3000, 700},
                      PostCase{FieldDef{}, 1, false, 3000, -700},
                      PostCase{modern_field(), 0, true, -4500, -750},
                      PostCase{modern_field(), 0, false, -4500, 750},
                      PostCase{modern_field(), 1, true, 4500, 750},
                      PostCase{modern_field(), 1, false, 4500, -750}));

TEST(Field, GoalBoxIsInFrontOfEachTeamsOwnGoal) {
  for (const FieldDef& def : {FieldDef{}, modern_field()}) {
    const Field field(def);
    const float hl = field.half_length();
    // Team 0: box from x = -hl to -hl + 600, |y| <= 1100.
    EXPECT_TRUE(field.in_goal_box(0, -hl + 300, 0));
    EXPECT_TRUE(field.in_goal_box(0, -hl + 600, 1100));
    EXPECT_FALSE(field.in_goal_box(0, -hl + 601, 0));
    EXPECT_FALSE(field.in_goal_box(0, -hl + 300, 1101));
    EXPECT_FALSE(field.in_goal_box(0, -hl - 10, 0)); // in the goal, not the box
    EXPECT_FALSE(field.in_goal_box(0, hl - 300, 0)); // the other team's box
    // Team 1 mirrored.
    EXPECT_TRUE(field.in_goal_box(1, hl - 300, -1000));
    EXPECT_FALSE(field.in_goal_box(1, hl - 601, 0));
    EXPECT_FALSE(field.in_goal_box(1, -hl + 300, 0));
  }
}

TEST(Field, PenaltyAreaIsTheModernAreaOrTheGoalBoxWithoutOne) {
  FieldDef def = modern_field();
  def.penalty_area_length_mm = 1650;
  def.penalty_area_width_mm = 4000;
  const Field modern(def);
  const float hl = modern.half_length();
  EXPECT_TRUE(modern.in_penalty_area(0, -hl + 1650, 2000));
  EXPECT_FALSE(modern.in_penalty_area(0, -hl + 1651, 0));
  EXPECT_FALSE(modern.in_penalty_area(0, -hl + 800, 2001));
  EXPECT_TRUE(modern.in_penalty_area(1, hl - 1000, -1900));
  EXPECT_FALSE(modern.in_penalty_area(1, -hl + 1000, 0)); // the other team's
  const Field old(FieldDef{}); // 2011: no penalty area, the goal box (600 x 2200) serves
  EXPECT_TRUE(old.in_penalty_area(0, -old.half_length() + 600, 1100));
  EXPECT_FALSE(old.in_penalty_area(0, -old.half_length() + 601, 0));
}

TEST(Field, InGoalIsBehindTheLineBetweenTheNets) {
  const Field field; // goal width 1400, depth 500
  EXPECT_TRUE(field.in_goal(0, -3100, 0));
  EXPECT_TRUE(field.in_goal(0, -3500, 700));
  EXPECT_FALSE(field.in_goal(0, -3000, 0));   // on the line: not in
  EXPECT_FALSE(field.in_goal(0, -2900, 0));   // in front
  EXPECT_FALSE(field.in_goal(0, -3501, 0));   // behind the net
  EXPECT_FALSE(field.in_goal(0, -3100, 701)); // beside the net
  EXPECT_FALSE(field.in_goal(1, -3100, 0));   // team 1's goal is at +x
  EXPECT_TRUE(field.in_goal(1, 3100, 0));
  EXPECT_FALSE(field.in_goal(1, 2900, 0));
}

TEST(Field, GoalLineIsOnEachTeamsOwnSide) {
  const Field field(modern_field());
  EXPECT_FLOAT_EQ(field.goal_line_x(0), -4500);
  EXPECT_FLOAT_EQ(field.goal_line_x(1), 4500);
}

} // namespace
} // namespace touchline::sim
