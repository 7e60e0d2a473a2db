#pragma once
// A world config file: [field], [physics], [match], [camera], [noise], [sonar], [rules] and [comm] sections (config/spl2011.ini,
// config/spl2020.ini). Every key is optional; its default is the definition struct's.
#include <string>
#include <vector>

#include "touchline/ini.hpp"
#include "touchline/sim/field.hpp"
#include "touchline/sim/perception_config.hpp"
#include "touchline/sim/rules.hpp"
#include "touchline/sim/team_comm.hpp"
#include "touchline/sim/world.hpp"

namespace touchline::sim {

struct MatchDef {
  int team_size = 4;          ///< robots per team, 1..kMaxTeamSize
  float duration_s = 3600.f;  ///< longest the match may last, s: the referee ends it sooner (two halves and their stoppages)
  float foot_separation_mm = 100.f; ///< feet apart when robots are placed (match the walk's)
  float ball_start_x_mm = 0.f;  ///< where the ball is placed at kick-off (field frame)
  float ball_start_y_mm = 0.f;
};

struct WorldConfig {
  FieldDef field;
  PhysicsDef physics;
  MatchDef match;
  PerceptionDef perception;
  RulesDef rules;
  CommDef comm;
};

void bind(IniSchema& schema, FieldDef& def);
void bind(IniSchema& schema, PhysicsDef& def);
void bind(IniSchema& schema, MatchDef& def);
/// Every section of a world config.
void bind(IniSchema& schema, WorldConfig& config);

/// Reads `path` (empty: defaults only), then applies "section.key=value" overrides in
/// order (later wins), then validates. Throws ConfigError with a one-line message: a
/// missing file, an unknown key, a value that does not parse or is out of range.
WorldConfig load_world_config(const std::string& path, const std::vector<std::string>& overrides = {});

/// Checks ranges (positive lengths and masses, goal narrower than the field, net inside
/// the walls, goal box inside the field, team size 1..kMaxTeamSize, substeps >= 1,
/// restitutions in [0, 1], ...). Throws ConfigError naming the key and the bad value,
/// e.g. "match.team_size must be 1..7 (got 9)".
void validate(const WorldConfig& config);

/// Where a robot stands before the match: on the touchline of its own half, facing into
/// the field. Team 0 (the -x half) stands on y = -half_width facing +y; team 1 is the
/// same picture turned 180 degrees about the centre spot (y = +half_width, facing -y).
/// Players 1..team_size are spread evenly in x between the goal box and the centre
/// circle, player 1 (the keeper) nearest its own goal.
Pose2D initial_pose(const Field& field, int team_size, RobotId id);

} // namespace touchline::sim
