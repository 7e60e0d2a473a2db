#include "touchline/sim/world.hpp"

#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "touchline/angles.hpp"
#include "touchline/hash.hpp"

namespace touchline::sim {

namespace {

// Box2D is tuned for objects of 0.1-10 m, so the world runs in metres; the API is in mm.
float to_m(float mm) { return mm / 1000.f; }
float to_mm(float m) { return m * 1000.f; }
b2Vec2 to_m(float x_mm, float y_mm) { return b2Vec2(to_m(x_mm), to_m(y_mm)); }

// Thickness of the boundary walls beyond the carpet edge (only their inner face matters).
constexpr float kWallThicknessM = 0.5f;
// Thickness of the nets, centred on their nominal lines.
constexpr float kNetThicknessM = 0.02f;
/// A foot's turn counts as this much travel at its toe when telling the lifted foot, mm/rad.
constexpr float kFootTurnRadius_mm = 80.f;
/// A foot commanded to travel less than this in a tick stands (the solver's and a joint
/// walk's jitter), mm.
constexpr float kLiftedTravel_mm = 0.01f;

b2Vec2 rotate(float theta, b2Vec2 v) {
  const float c = std::cos(theta), s = std::sin(theta);
  return b2Vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

Pose2D pose_of(const b2Body& body) {
  const b2Vec2 p = body.GetPosition();
  return Pose2D{to_mm(p.x), to_mm(p.y), normalise_angle(body.GetAngle())};
}

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
  struct Robot {
    RobotId id;
    b2Body* left = nullptr;
    b2Body* right = nullptr;
    /// Where the walk's own commands alone would have put the feet since the robot was
    /// placed (square, around the origin): the stance its legs hold the feet in. Their twist
    /// is what hold_twist leaves alone; a foot the walk moves returns to its place beside the
    /// other (return_to_stance).
    Pose2D walk_left, walk_right;
    /// The twist (right foot's heading less the left's) the walk's own commands made, rad.
    float walk_twist_rad() const { return normalise_angle(walk_right.theta_rad - walk_left.theta_rad); }
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

  /// The legs: a rope between the foot centres, slack until they are max_foot_spread_mm
  /// apart (Box2D's distance joint with only its upper limit), so a push that would part
  /// the feet drags the other foot along, as it drags a Nao's whole body.
  void add_legs(b2Body* left, b2Body* right) {
    b2DistanceJointDef legs;
    legs.Initialize(left, right, left->GetPosition(), right->GetPosition());
    legs.minLength = 0.f; // Box2D raises it to its linear slop: the feet may pass each other
    legs.maxLength = to_m(physics.max_foot_spread_mm);
    legs.stiffness = legs.damping = 0.f; // no spring: only the limit acts
    world.CreateJoint(&legs);
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

  struct FootVelocity {
    b2Body* foot;
    b2Vec2 linear;
    float angular;
  };

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

  /// A foot's pose after its velocity command for one tick.
  static Pose2D after_command(const FootVelocity& c) {
    const Pose2D now = pose_of(*c.foot);
    return Pose2D{now.x_mm + to_mm(c.linear.x) * kMotionTick_s, now.y_mm + to_mm(c.linear.y) * kMotionTick_s,
                  normalise_angle(now.theta_rad + c.angular * kMotionTick_s)};
  }

  /// The legs place a lifted foot: the foot the walk moves this tick (the other stands)
  /// also moves, at up to stance_return_mm_s and stance_return_rad_s, towards where the
  /// walk's own steps put it beside the other foot (r.walk_left, r.walk_right). Contacts
  /// move feet apart from where the walk put them (a foot blocked by another robot's, a
  /// foot dragged by the legs' rope); without this nothing brings them back, and a robot's
  /// stance drifts for the rest of the match (a kick's foot 100 mm off where the walk put
  /// it misses the ball). A standing foot is never moved: only the legs' swing corrects.
  void return_to_stance(const Robot& r, const TickMotion& m, FootVelocity& left, FootVelocity& right) const {
    if (physics.stance_return_mm_s <= 0 && physics.stance_return_rad_s <= 0) return;
    const auto travel = [](const FootMotion& f) {
      return std::hypot(f.dx_mm, f.dy_mm) + kFootTurnRadius_mm * std::fabs(f.dtheta_rad);
    };
    const float left_travel = travel(m.left), right_travel = travel(m.right);
    if (std::max(left_travel, right_travel) < kLiftedTravel_mm) return; // standing, or both feet still
    const bool left_lifted = left_travel > right_travel;
    FootVelocity& lifted = left_lifted ? left : right;
    const FootVelocity& standing = left_lifted ? right : left;
    // Where the walk put the lifted foot in the standing one's frame, set on the standing foot.
    const Pose2D& walk_lifted = left_lifted ? r.walk_left : r.walk_right;
    const Pose2D& walk_standing = left_lifted ? r.walk_right : r.walk_left;
    const b2Vec2 offset = rotate(-walk_standing.theta_rad, b2Vec2(walk_lifted.x_mm - walk_standing.x_mm,
                                                                   walk_lifted.y_mm - walk_standing.y_mm));
    const Pose2D base = after_command(standing);
    const b2Vec2 placed = rotate(base.theta_rad, offset);
    const Pose2D at = after_command(lifted);
    b2Vec2 error(base.x_mm + placed.x - at.x_mm, base.y_mm + placed.y - at.y_mm);
    const float max_mm = physics.stance_return_mm_s * kMotionTick_s;
    if (error.Length() > max_mm) error *= max_mm / error.Length();
    const float max_rad = physics.stance_return_rad_s * kMotionTick_s;
    const float turn_error = base.theta_rad + walk_lifted.theta_rad - walk_standing.theta_rad - at.theta_rad;
    const float turn = std::clamp(normalise_angle(turn_error), -max_rad, max_rad);
    lifted.linear += to_m(error.x / kMotionTick_s, error.y / kMotionTick_s);
    lifted.angular += turn / kMotionTick_s;
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
      return_to_stance(r, motions[i], commands[commands.size() - 2], commands.back());
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
      for (const Robot& r : robots) hold_twist(r);
    ++ticks;
  }

  /// The right foot's heading less the left's, rad.
  static float twist_of(const Robot& r) { return normalise_angle(r.right->GetAngle() - r.left->GetAngle()); }

  /// Turns both feet of `r` towards each other, equally (their mean heading stays where it
  /// was), until one is at most max_foot_twist_rad from the other, or as far as the walk
  /// itself turned them apart (r.walk_twist_rad()): only a contact's twist is held, never the
  /// walk's own (a turning walk's feet open ~0.83 rad). The bound is the walk's twist, not
  /// the twist before the tick plus the walk's turn in it: that ratchets, a contact's excess
  /// kept whenever the walk turned the same way, up to the feet pi apart.
  /// The legs' own limit holds even the walk's twist: a Nao's hip yaw-pitch joint turns its
  /// feet apart by at most 65.6 deg (1.15 rad). A walk whose state parted from the feet (it
  /// was mid-turn when the referee put the robot down) could otherwise twist them pi apart.
  void hold_twist(const Robot& r) const {
    constexpr float kSolverSlack_rad = 1e-4f; // the solver's rounding on an untouched foot: no correction
    constexpr float kLegTwistLimit_rad = 1.15f;
    const float twist = twist_of(r);
    const float walk_twist = std::min(std::fabs(r.walk_twist_rad()), kLegTwistLimit_rad);
    const float bound = std::max(physics.max_foot_twist_rad, walk_twist);
    if (std::fabs(twist) <= bound + kSolverSlack_rad) return;
    const float excess = 0.5f * (twist - std::copysign(bound, twist));
    r.left->SetTransform(r.left->GetPosition(), r.left->GetAngle() + excess);
    r.right->SetTransform(r.right->GetPosition(), r.right->GetAngle() - excess);
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
  impl_->add_legs(robot.left, robot.right);
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
