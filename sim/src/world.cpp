#include "touchline/sim/world.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "box2d_units.hpp"
#include "touchline/angles.hpp"
#include "touchline/hash.hpp"
#include "world_legs.hpp"

namespace touchline::sim {

using detail::FootVelocity;
using detail::pose_of;
using detail::rotate;
using detail::to_m;
using detail::to_mm;

namespace {

// Thickness of the boundary walls beyond the carpet edge (only their inner face matters).
constexpr float kWallThicknessM = 0.5f;
// Thickness of the nets, centred on their nominal lines.
constexpr float kNetThicknessM = 0.02f;
/// A polygon of `half` extents whose rounded skin (b2_polygonRadius, 1 cm) ends at those
/// extents, so the collision outline is the real outline rather than 1 cm larger.
b2PolygonShape skinned_box(b2Vec2 half, b2Vec2 centre = b2Vec2(0, 0)) {
  const float skin = std::min({b2_polygonRadius, half.x / 2, half.y / 2});
  b2PolygonShape box;
  box.SetAsBox(half.x - skin, half.y - skin, centre, 0.f);
  box.m_radius = skin;
  return box;
}

/// Box2D mixes restitution as the max of the pair, which would make the ball bounce off
/// a soft net as hard as off a foot. A static part's own restitution decides instead.
/// Also notes which robots' feet began touching the ball (the referee's ball-out rule and
/// set plays).
class ContactRules : public b2ContactListener {
 public:
  const b2Body* ball = nullptr;
  int last_touch_robot = -1; ///< robot index, -1: none yet
  std::vector<int> touches;  ///< robot indices whose feet began touching the ball this step

  void BeginContact(b2Contact* contact) override {
    const b2Fixture* a = contact->GetFixtureA();
    const b2Fixture* b = contact->GetFixtureB();
    const b2Fixture* other = a->GetBody() == ball ? b : b->GetBody() == ball ? a : nullptr;
    // Feet carry their robot in a negative group index (see add_foot).
    if (other && other->GetFilterData().groupIndex < 0) {
      last_touch_robot = -other->GetFilterData().groupIndex - 1;
      touches.push_back(last_touch_robot);
    }
  }

  void PreSolve(b2Contact* contact, const b2Manifold*) override {
    const b2Fixture* a = contact->GetFixtureA();
    const b2Fixture* b = contact->GetFixtureB();
    if (a->GetBody()->GetType() == b2_staticBody)
      contact->SetRestitution(a->GetRestitution());
    else if (b->GetBody()->GetType() == b2_staticBody)
      contact->SetRestitution(b->GetRestitution());
  }
};

} // namespace

struct World::Impl {
  /// A robot: its feet and the walk's stance its legs hold them in (world_legs.hpp).
  struct Robot : detail::Legs {
    RobotId id;
  };

  Field field;
  PhysicsDef physics;
  float foot_separation_mm;
  b2World world{b2Vec2(0, 0)}; // top-down: no gravity
  ContactRules contact_rules;
  b2Body* ball = nullptr;
  std::vector<Robot> robots;
  std::vector<b2Body*> dynamic_bodies; // creation order, for state_hash
  int64_t ticks = 0;

  Impl(const FieldDef& field_def, const PhysicsDef& physics_def, float separation_mm)
      : field(field_def), physics(physics_def), foot_separation_mm(separation_mm) {
    world.SetContactListener(&contact_rules);
    world.SetAllowSleeping(false); // a resting foot or ball must answer the next command at once
    add_walls();
    add_goal(0);
    add_goal(1);
    add_ball();
    contact_rules.ball = ball;
  }

  b2FixtureDef fixture(const b2Shape& shape, float restitution) const {
    b2FixtureDef def;
    def.shape = &shape;
    def.friction = physics.foot_friction; // equal on every fixture: Box2D's sqrt mix keeps it
    def.restitution = restitution;
    return def;
  }

  b2Body* add_static_body() {
    b2BodyDef def;
    def.type = b2_staticBody;
    return world.CreateBody(&def);
  }

  /// Four boxes just outside the carpet (field plus border on every side).
  void add_walls() {
    const float hx = to_m(field.half_length() + field.def().border_mm);
    const float hy = to_m(field.half_width() + field.def().border_mm);
    const float t = kWallThicknessM;
    b2Body* walls = add_static_body();
    const b2PolygonShape sides[] = {
        skinned_box(b2Vec2(t / 2, hy + t), b2Vec2(-hx - t / 2, 0)),
        skinned_box(b2Vec2(t / 2, hy + t), b2Vec2(hx + t / 2, 0)),
        skinned_box(b2Vec2(hx + t, t / 2), b2Vec2(0, -hy - t / 2)),
        skinned_box(b2Vec2(hx + t, t / 2), b2Vec2(0, hy + t / 2)),
    };
    for (const auto& side : sides) {
      const b2FixtureDef def = fixture(side, physics.wall_restitution);
      walls->CreateFixture(&def);
    }
  }

  /// Two posts on the goal line and a net behind them: two sides and a back.
  void add_goal(int defending_team) {
    b2Body* goal = add_static_body();
    b2CircleShape post;
    post.m_radius = to_m(field.def().goal_post_diameter_mm / 2);
    for (bool left : {true, false}) {
      const Pose2D centre = field.goal_post(defending_team, left);
      post.m_p = to_m(centre.x_mm, centre.y_mm);
      const b2FixtureDef def = fixture(post, physics.post_restitution);
      goal->CreateFixture(&def);
    }
    // Thin boxes rather than edges: an edge's end vertex in the inside corner would
    // deflect a ball sliding along the back net out of the goal. The boxes overlap at
    // the corners, so the inside corner is two plain faces.
    const float line_x = to_m(field.goal_line_x(defending_team));
    const float depth = to_m(field.def().goal_depth_mm);
    const float half_w = to_m(field.def().goal_width_mm / 2);
    const float out = defending_team == 0 ? -1.f : 1.f; // from the field into the goal
    const float t = kNetThicknessM / 2;
    const b2Vec2 side_half(depth / 2 + t, t);
    const b2PolygonShape nets[] = {
        skinned_box(side_half, b2Vec2(line_x + out * depth / 2, half_w)),
        skinned_box(side_half, b2Vec2(line_x + out * depth / 2, -half_w)),
        skinned_box(b2Vec2(t, half_w + t), b2Vec2(line_x + out * depth, 0)),
    };
    for (const auto& net : nets) {
      const b2FixtureDef def = fixture(net, physics.net_restitution);
      goal->CreateFixture(&def);
    }
  }

  b2Body* add_dynamic_body(b2Vec2 position, float angle, bool bullet) {
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position = position;
    def.angle = angle;
    def.bullet = bullet;
    b2Body* body = world.CreateBody(&def);
    dynamic_bodies.push_back(body);
    return body;
  }

  void add_ball() {
    const float radius = to_m(physics.ball_diameter_mm / 2);
    ball = add_dynamic_body(b2Vec2(0, 0), 0.f, /*bullet=*/true); // shots must not tunnel
    ball->SetLinearDamping(physics.ball_linear_damping);
    // Seen from above, Box2D would spin the ball about the vertical axis whenever it
    // rubs a net or a wall, and turn that spin back into speed at the next contact (a
    // ball sliding into a net's corner would shoot out of the goal). A real ball's spin
    // about the vertical is negligible: keep it at zero.
    ball->SetFixedRotation(true);
    b2CircleShape circle;
    circle.m_radius = radius;
    b2FixtureDef def = fixture(circle, physics.ball_restitution);
    def.density = physics.ball_mass_kg / (b2_pi * radius * radius);
    ball->CreateFixture(&def);
  }

  b2Body* add_foot(int robot_index, const Pose2D& pose) {
    b2Body* foot = add_dynamic_body(to_m(pose.x_mm, pose.y_mm), pose.theta_rad, /*bullet=*/false);
    const b2Vec2 half(to_m(physics.foot_length_mm / 2), to_m(physics.foot_width_mm / 2));
    const b2PolygonShape box = skinned_box(half);
    b2FixtureDef def = fixture(box, 0.f);
    def.density = 1.f;                             // replaced by the exact mass below
    def.filter.groupIndex = static_cast<int16>(-(robot_index + 1)); // a robot's feet never touch
    foot->CreateFixture(&def);
    // Exact mass and rectangle inertia, not the skin-shrunk polygon's.
    b2MassData mass;
    mass.mass = physics.foot_mass_kg;
    mass.center = b2Vec2(0, 0);
    mass.I = physics.foot_mass_kg * (4 * half.x * half.x + 4 * half.y * half.y) / 12;
    foot->SetMassData(&mass);
    return foot;
  }

  /// Foot poses of a robot standing at `body`: left at +sep/2, right at -sep/2 (body y).
  std::pair<Pose2D, Pose2D> feet_at(const Pose2D& body) const {
    const b2Vec2 offset = rotate(body.theta_rad, b2Vec2(0, foot_separation_mm / 2));
    return {Pose2D{body.x_mm + offset.x, body.y_mm + offset.y, body.theta_rad},
            Pose2D{body.x_mm - offset.x, body.y_mm - offset.y, body.theta_rad}};
  }

  const Robot& robot_at(int index) const {
    if (index < 0 || index >= static_cast<int>(robots.size()))
      throw std::out_of_range("World: no robot " + std::to_string(index));
    return robots[static_cast<std::size_t>(index)];
  }
  Robot& robot_at(int index) { return const_cast<Robot&>(std::as_const(*this).robot_at(index)); }

  /// Constant rolling resistance (Box2D has none): slows the ball by decel*h, never reverses it.
  void apply_rolling_resistance(float h) {
    const b2Vec2 v = ball->GetLinearVelocity();
    const float speed = v.Length();
    const float dv = to_m(physics.ball_rolling_decel_mm_s2) * h;
    ball->SetLinearVelocity(speed <= dv ? b2Vec2(0, 0) : (1.f - dv / speed) * v);
  }

  /// velocity = displacement / dt, displacement rotated from the body frame at the tick start.
  static FootVelocity foot_velocity(b2Body* foot, float body_theta, const FootMotion& m) {
    const b2Vec2 v = rotate(body_theta, b2Vec2(to_m(m.dx_mm) / kMotionTick_s, to_m(m.dy_mm) / kMotionTick_s));
    return FootVelocity{foot, v, m.dtheta_rad / kMotionTick_s};
  }

  /// `pose` after `m`, a displacement in the body frame of heading `body_theta`.
  static Pose2D moved(const Pose2D& pose, float body_theta, const FootMotion& m) {
    const b2Vec2 d = rotate(body_theta, b2Vec2(m.dx_mm, m.dy_mm));
    return Pose2D{pose.x_mm + d.x, pose.y_mm + d.y, normalise_angle(pose.theta_rad + m.dtheta_rad)};
  }

  void step(const std::vector<TickMotion>& motions, const std::vector<TickMotion>& legs) {
    if (motions.size() != robots.size() || legs.size() != robots.size())
      throw std::invalid_argument("World::step: " + std::to_string(motions.size()) + " motions and " +
                                  std::to_string(legs.size()) + " leg motions for " +
                                  std::to_string(robots.size()) + " robots");
    contact_rules.touches.clear();
    std::vector<FootVelocity> commands;
    commands.reserve(2 * robots.size());
    for (std::size_t i = 0; i < robots.size(); ++i) {
      Robot& r = robots[i];
      const float theta = mean_heading(r.left->GetAngle(), r.right->GetAngle());
      commands.push_back(foot_velocity(r.left, theta, motions[i].left));
      commands.push_back(foot_velocity(r.right, theta, motions[i].right));
      const float walk_theta = mean_heading(r.walk_left.theta_rad, r.walk_right.theta_rad);
      r.walk_left = moved(r.walk_left, walk_theta, legs[i].left);
      r.walk_right = moved(r.walk_right, walk_theta, legs[i].right);
      detail::return_to_stance(physics, r, motions[i], commands[commands.size() - 2], commands.back());
    }
    const int substeps = std::max(1, physics.substeps);
    const float h = kMotionTick_s / static_cast<float>(substeps);
    for (int s = 0; s < substeps; ++s) {
      // Re-impose the commands each substep: contacts must not leave feet drifting.
      for (const FootVelocity& c : commands) set_velocity(c.foot, c.linear, c.angular);
      apply_rolling_resistance(h);
      world.Step(h, physics.velocity_iterations, physics.position_iterations);
    }
    // A foot without a command next tick stays put.
    for (const FootVelocity& c : commands) set_velocity(c.foot, b2Vec2(0, 0), 0.f);
    if (physics.max_foot_twist_rad > 0)
      for (const Robot& r : robots) detail::hold_twist(physics, r);
    ++ticks;
  }

  static void set_velocity(b2Body* body, b2Vec2 linear, float angular) {
    body->SetLinearVelocity(linear);
    body->SetAngularVelocity(angular);
  }

  static void place(b2Body* body, const Pose2D& pose) {
    body->SetTransform(to_m(pose.x_mm, pose.y_mm), pose.theta_rad);
    set_velocity(body, b2Vec2(0, 0), 0.f);
    body->SetAwake(true);
  }
};

World::World(const FieldDef& field, const PhysicsDef& physics, float foot_separation_mm)
    : impl_(std::make_unique<Impl>(field, physics, foot_separation_mm)) {}

World::~World() = default;

int World::add_robot(RobotId id, const Pose2D& body) {
  const int index = static_cast<int>(impl_->robots.size());
  const auto [left, right] = impl_->feet_at(body);
  Impl::Robot robot;
  robot.id = id;
  robot.left = impl_->add_foot(index, left);
  robot.right = impl_->add_foot(index, right);
  std::tie(robot.walk_left, robot.walk_right) = impl_->feet_at(Pose2D{}); // standing square
  detail::add_rope(impl_->world, robot, impl_->physics.max_foot_spread_mm);
  impl_->robots.push_back(robot);
  return index;
}

void World::place_robot(int index, const Pose2D& body) {
  Impl::Robot& robot = impl_->robot_at(index);
  const auto [left, right] = impl_->feet_at(body);
  Impl::place(robot.left, left);
  Impl::place(robot.right, right);
  std::tie(robot.walk_left, robot.walk_right) = impl_->feet_at(Pose2D{}); // placed square
}

void World::place_ball(float x_mm, float y_mm, float vx_mm_s, float vy_mm_s) {
  Impl::place(impl_->ball, Pose2D{x_mm, y_mm, 0.f});
  impl_->ball->SetLinearVelocity(to_m(vx_mm_s, vy_mm_s));
}

void World::step(const std::vector<TickMotion>& motions) { impl_->step(motions, motions); }

void World::step(const std::vector<TickMotion>& motions, const std::vector<TickMotion>& legs) {
  impl_->step(motions, legs);
}

int World::robot_count() const { return static_cast<int>(impl_->robots.size()); }

int World::last_ball_touch() const { return impl_->contact_rules.last_touch_robot; }

const std::vector<int>& World::ball_touches() const { return impl_->contact_rules.touches; }

RobotTruth World::robot(int index) const {
  const Impl::Robot& r = impl_->robot_at(index);
  RobotTruth truth;
  truth.id = r.id;
  truth.left_foot = pose_of(*r.left);
  truth.right_foot = pose_of(*r.right);
  truth.body = Pose2D{(truth.left_foot.x_mm + truth.right_foot.x_mm) / 2,
                      (truth.left_foot.y_mm + truth.right_foot.y_mm) / 2,
                      mean_heading(r.left->GetAngle(), r.right->GetAngle())};
  return truth;
}

BallTruth World::ball() const {
  const b2Vec2 p = impl_->ball->GetPosition();
  const b2Vec2 v = impl_->ball->GetLinearVelocity();
  return BallTruth{to_mm(p.x), to_mm(p.y), to_mm(v.x), to_mm(v.y)};
}

const Field& World::field() const { return impl_->field; }

const PhysicsDef& World::physics() const { return impl_->physics; }

int64_t World::ticks() const { return impl_->ticks; }

uint64_t World::state_hash() const {
  Fnv1a hash;
  for (const b2Body* body : impl_->dynamic_bodies) {
    const b2Vec2 p = body->GetPosition();
    const b2Vec2 v = body->GetLinearVelocity();
    for (float value : {p.x, p.y, body->GetAngle(), v.x, v.y, body->GetAngularVelocity()})
      hash.add_value(value);
  }
  for (const Impl::Robot& r : impl_->robots)
    for (const Pose2D& p : {r.walk_left, r.walk_right})
      for (float value : {p.x_mm, p.y_mm, p.theta_rad}) hash.add_value(value);
  hash.add_value(impl_->ticks);
  return hash.value();
}

} // namespace touchline::sim
