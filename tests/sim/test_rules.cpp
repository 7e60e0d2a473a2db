// The [rules] section: the shipped files hold the code's defaults, bad values are
// one-line errors naming the key, overrides work.
#include "touchline/sim/rules.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace touchline::sim {
namespace {

const std::string kConfigDir = std::string(TOUCHLINE_SOURCE_DIR) + "/config/";

/// The [rules] section of a config file, read alone (other sections belong to others).
RulesDef read_rules_section(const std::string& name) {
  std::ifstream in(kConfigDir + name);
  EXPECT_TRUE(in) << name;
  std::ostringstream section;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] == '[') inside = line.rfind("[rules]", 0) == 0;
    if (inside) section << line << "\n";
  }
  EXPECT_FALSE(section.str().empty()) << name << " has no [rules] section";
  const std::string path = ::testing::TempDir() + "touchline_rules_" + name;
  std::ofstream(path) << section.str();
  RulesDef rules;
  IniSchema schema("rules");
  bind(schema, rules);
  schema.read_file(path);
  return rules;
}

void expect_equal(const RulesDef& a, const RulesDef& b) {
  EXPECT_EQ(a.initial_s, b.initial_s);
  EXPECT_EQ(a.ready_s, b.ready_s);
  EXPECT_EQ(a.set_s, b.set_s);
  EXPECT_EQ(a.half_s, b.half_s);
  EXPECT_EQ(a.first_kickoff_team, b.first_kickoff_team);
  EXPECT_EQ(a.removal_s, b.removal_s);
  EXPECT_EQ(a.pushing, b.pushing);
  EXPECT_EQ(a.illegal_defender, b.illegal_defender);
  EXPECT_EQ(a.leaving_field, b.leaving_field);
  EXPECT_EQ(a.collision.contact_distance_mm, b.collision.contact_distance_mm);
  EXPECT_EQ(a.collision.contest_distance_mm, b.collision.contest_distance_mm);
  EXPECT_EQ(a.pushing_cooldown_s, b.pushing_cooldown_s);
  EXPECT_EQ(a.pushing_model, b.pushing_model);
  EXPECT_EQ(a.pushing_speed_mm_s, b.pushing_speed_mm_s);
  EXPECT_EQ(a.pushing_window_s, b.pushing_window_s);
  EXPECT_EQ(a.pushing_min_contact_s, b.pushing_min_contact_s);
  EXPECT_EQ(a.leave_field_margin_mm, b.leave_field_margin_mm);
  EXPECT_EQ(a.manual_placement, b.manual_placement);
  EXPECT_EQ(a.ball_out, b.ball_out);
  EXPECT_EQ(a.ball_out_setback_mm, b.ball_out_setback_mm);
  EXPECT_EQ(a.ball_out_inset_mm, b.ball_out_inset_mm);
  EXPECT_EQ(a.throw_in_line_end_mm, b.throw_in_line_end_mm);
  EXPECT_EQ(a.ball_out_clearance_mm, b.ball_out_clearance_mm);
}

TEST(Rules, BothShippedFilesHoldTheCodeDefaults) {
  // The 2011 rules on either field: the rule book's numbers do not depend on its size.
  for (const char* name : {"spl2011.ini", "spl2020.ini"}) {
    SCOPED_TRACE(name);
    const RulesDef rules = read_rules_section(name);
    expect_equal(rules, RulesDef{});
    EXPECT_NO_THROW(validate(rules));
  }
}

TEST(Rules, OverridesSetOneRule) {
  RulesDef rules;
  IniSchema schema("rules");
  bind(schema, rules);
  schema.apply_override("rules.pushing=false");
  schema.apply_override("rules.removal_s=10");
  EXPECT_FALSE(rules.pushing);
  EXPECT_EQ(rules.removal_s, 10.f);
  EXPECT_TRUE(rules.illegal_defender);
  schema.apply_override("rules.pushing_model=thesis");
  EXPECT_EQ(rules.pushing_model, "thesis");
}

std::string validation_error(const RulesDef& rules) {
  try {
    validate(rules);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Rules, BadValuesNameTheKey) {
  RulesDef r;
  r.ready_s = -1;
  EXPECT_EQ(validation_error(r), "rules.ready_s must be in [0, 1000000] (got -1)");
  r = RulesDef{};
  r.half_s = 0;
  EXPECT_EQ(validation_error(r), "rules.half_s must be in (0, 1000000] (got 0)");
  r = RulesDef{};
  r.first_kickoff_team = 2;
  EXPECT_EQ(validation_error(r), "rules.first_kickoff_team must be 0 or 1 (got 2)");
  r = RulesDef{};
  r.collision.contact_distance_mm = 0;
  EXPECT_EQ(validation_error(r), "rules.contact_distance_mm must be in (0, 1000000] (got 0)");
  r = RulesDef{};
  r.getup_s = INFINITY; // set in code, past the file reader: validate refuses it all the same
  EXPECT_EQ(validation_error(r), "rules.getup_s must be in [0, 1000000] (got inf)");
  r = RulesDef{};
  r.pushing_model = "heading";
  EXPECT_EQ(validation_error(r), "rules.pushing_model must be thesis or walking_into (got 'heading')");
  r = RulesDef{};
  r.pushing_speed_mm_s = -5;
  EXPECT_EQ(validation_error(r), "rules.pushing_speed_mm_s must be in [0, 1000000] (got -5)");
  r = RulesDef{};
  r.pushing_window_s = 0; // a velocity needs a time to divide by
  EXPECT_EQ(validation_error(r), "rules.pushing_window_s must be in (0, 10] (got 0)");
  r = RulesDef{};
  r.pushing_min_contact_s = NAN;
  EXPECT_EQ(validation_error(r), "rules.pushing_min_contact_s must be in [0, 1000000] (got nan)");
  r = RulesDef{};
  r.throw_in_line_end_mm = -1;
  EXPECT_EQ(validation_error(r), "rules.throw_in_line_end_mm must be in [0, 1000000] (got -1)");
  EXPECT_EQ(validation_error(RulesDef{}), "");
}

TEST(Rules, PlannedLengthIsTwoHalvesWithTheirStates) {
  RulesDef r; // SPL 2011: 1 s INITIAL, 45 s READY, 5 s SET, 600 s PLAYING, twice
  EXPECT_DOUBLE_EQ(planned_length_s(r), 1302.0);
  EXPECT_DOUBLE_EQ(goal_stoppage_s(r), 50.0);
  r.standby_s = 10;
  r.half_s = 300;
  EXPECT_DOUBLE_EQ(planned_length_s(r), 722.0);
  r.referee = false; // the game stays PLAYING: only the world's duration ends it
  EXPECT_TRUE(std::isinf(planned_length_s(r)));
  EXPECT_DOUBLE_EQ(goal_stoppage_s(r), 0.0);
}

} // namespace
} // namespace touchline::sim
