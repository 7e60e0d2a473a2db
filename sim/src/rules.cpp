#include "touchline/sim/rules.hpp"

#include <limits>
#include <sstream>
#include <string>

namespace touchline::sim {

void bind(IniSchema& s, RulesDef& d) {
  s.bind("rules.referee", &d.referee, "play by the rules; false: the game stays PLAYING")
      .bind("rules.fall_probability", &d.fall_probability, "chance a pushed robot falls, 0..1")
      .bind("rules.getup_s", &d.getup_s, "a fallen robot lies this long, s")
      .bind("rules.initial_s", &d.initial_s, "INITIAL before READY of each half, s")
      .bind("rules.standby_s", &d.standby_s, "STANDBY between INITIAL and READY, s (0: none)")
      .bind("rules.ready_s", &d.ready_s, "READY, robots walk to kick-off positions, s")
      .bind("rules.set_s", &d.set_s, "SET, robots stand until the whistle, s")
      .bind("rules.half_s", &d.half_s, "playing time of a half, s")
      .bind("rules.first_kickoff_team", &d.first_kickoff_team, "team kicking off the first half, 0 or 1")
      .bind("rules.removal_s", &d.removal_s, "time a penalised robot spends off the field, s")
      .bind("rules.pushing", &d.pushing, "penalise pushing an opponent")
      .bind("rules.illegal_defender", &d.illegal_defender, "penalise a field player in its own goal box")
      .bind("rules.leaving_field", &d.leaving_field, "penalise leaving the field")
      .bind("rules.contact_distance_mm", &d.collision.contact_distance_mm, "bodies closer have collided, mm")
      .bind("rules.contest_distance_mm", &d.collision.contest_distance_mm, "both this near the ball: contesting, mm")
      .bind("rules.pushing_cooldown_s", &d.pushing_cooldown_s, "no second pushing penalty from a pair, s")
      .bind("rules.pushing_model", &d.pushing_model,
            "who pushes: thesis (headings alone) or walking_into (the robot walking into the other)")
      .bind("rules.pushing_speed_mm_s", &d.pushing_speed_mm_s, "walking_into: speed towards the other above this, mm/s")
      .bind("rules.pushing_window_s", &d.pushing_window_s, "walking_into: body velocity over this long, s")
      .bind("rules.pushing_min_contact_s", &d.pushing_min_contact_s, "walking_into: contact this long is a foul, s")
      .bind("rules.leave_field_margin_mm", &d.leave_field_margin_mm, "body past a line by more has left, mm")
      .bind("rules.manual_placement", &d.manual_placement, "place robots not in legal positions at SET")
      .bind("rules.ball_out", &d.ball_out, "put back a ball that left the field")
      .bind("rules.ball_out_setback_mm", &d.ball_out_setback_mm, "towards the last toucher's goal, mm")
      .bind("rules.ball_out_inset_mm", &d.ball_out_inset_mm, "the throw-in line: this far inside the touchline, mm")
      .bind("rules.throw_in_line_end_mm", &d.throw_in_line_end_mm, "the throw-in lines end this far short of the goal lines, mm")
      .bind("rules.ball_out_clearance_mm", &d.ball_out_clearance_mm, "a ball put back this far from every robot, mm")
      .bind("rules.set_plays", &d.set_plays, "kick-ins, goal and corner kicks, pushing free and penalty kicks")
      .bind("rules.set_play_s", &d.set_play_s, "a set play ends when its team touches the ball or after this, s")
      .bind("rules.game_stuck_s", &d.game_stuck_s, "no touch or no progress of the ball this long: kick-off, s (0: never)")
      .bind("rules.game_stuck_radius_mm", &d.game_stuck_radius_mm, "a ball within this of one spot makes no progress, mm");
}

void validate(const RulesDef& d) {
  require_non_negative("rules.initial_s", d.initial_s);
  require_non_negative("rules.standby_s", d.standby_s);
  require_non_negative("rules.ready_s", d.ready_s);
  require_non_negative("rules.set_s", d.set_s);
  require_positive("rules.half_s", d.half_s);
  if (d.first_kickoff_team != 0 && d.first_kickoff_team != 1)
    config_fail("rules.first_kickoff_team", "0 or 1", d.first_kickoff_team);
  require_non_negative("rules.removal_s", d.removal_s);
  require_positive("rules.contact_distance_mm", d.collision.contact_distance_mm);
  require_positive("rules.contest_distance_mm", d.collision.contest_distance_mm);
  require_non_negative("rules.pushing_cooldown_s", d.pushing_cooldown_s);
  if (d.pushing_model != "thesis" && d.pushing_model != "walking_into")
    config_fail("rules.pushing_model", "thesis or walking_into", "'" + d.pushing_model + "'");
  require_non_negative("rules.pushing_speed_mm_s", d.pushing_speed_mm_s);
  require_positive("rules.pushing_window_s", d.pushing_window_s, 10.f);
  require_non_negative("rules.pushing_min_contact_s", d.pushing_min_contact_s);
  require_non_negative("rules.leave_field_margin_mm", d.leave_field_margin_mm);
  require_non_negative("rules.ball_out_setback_mm", d.ball_out_setback_mm);
  require_non_negative("rules.ball_out_inset_mm", d.ball_out_inset_mm);
  require_non_negative("rules.throw_in_line_end_mm", d.throw_in_line_end_mm);
  require_non_negative("rules.ball_out_clearance_mm", d.ball_out_clearance_mm);
  require_positive("rules.set_play_s", d.set_play_s);
  require_non_negative("rules.getup_s", d.getup_s);
  require_non_negative("rules.game_stuck_s", d.game_stuck_s);
  require_positive("rules.game_stuck_radius_mm", d.game_stuck_radius_mm);
  require_fraction("rules.fall_probability", d.fall_probability);
}

double planned_length_s(const RulesDef& d) {
  if (!d.referee) return std::numeric_limits<double>::infinity();
  return 2.0 * (double{d.initial_s} + d.standby_s + d.ready_s + d.set_s + d.half_s);
}

double goal_stoppage_s(const RulesDef& d) { return d.referee ? double{d.ready_s} + d.set_s : 0.0; }

} // namespace touchline::sim
