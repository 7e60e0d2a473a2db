#pragma once
// A world config file: [field], [physics] and [match] sections (config/spl2011.ini,
// config/spl2020.ini). Every key is optional; its default is the definition struct's.
#include <string>
#include <vector>

#include "touchline/ini.hpp"
#include "touchline/sim/field.hpp"
#include "touchline/sim/world.hpp"

namespace touchline::sim {

struct MatchDef {
  int team_size = 4;          ///< robots per team, 1..kMaxTeamSize
  float duration_s = 600.f;   ///< simulated seconds the match lasts
  float foot_separation_mm = 100.f; ///< feet apart when robots are placed (match the walk's)
};

struct WorldConfig {
  FieldDef field;
  PhysicsDef physics;
  MatchDef match;
};

void bind(IniSchema& schema, FieldDef& def);
void bind(IniSchema& schema, PhysicsDef& def);
void bind(IniSchema& schema, MatchDef& def);

/// Reads `path` (empty: defaults only), then applies "section.key=value" overrides, then
/// checks ranges. Throws ConfigError with a one-line message.
WorldConfig load_world_config(const std::string& path, const std::vector<std::string>& overrides = {});

/// Checks ranges (positive lengths, goal inside the field, team size, ...). Throws ConfigError.
void validate(const WorldConfig& config);

/// Where a robot stands before the match: its own half, on the touchline, facing the field.
Pose2D initial_pose(const Field& field, int team_size, RobotId id);

} // namespace touchline::sim
