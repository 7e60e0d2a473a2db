#include "touchline/apps/summary_json.hpp"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "touchline/lcm/world_messages.hpp"

namespace touchline::apps {

namespace {

using nlohmann::json;

json robot_rows(const sim::Match& match, const sim::TruthFrame& truth) {
  json rows = json::array();
  for (const auto& r : truth.robots) {
    const sim::Member* m = match.roster().find(r.truth.id);
    rows.push_back({{"team", r.truth.id.team},
                    {"player", r.truth.id.player},
                    {"active", r.active},
                    {"frames_answered", m ? m->frames_answered : 0},
                    {"frames_missed", m ? m->frames_missed : 0},
                    {"behaviour_cpu_us_mean", m ? m->behaviour_cpu_us_mean() : 0},
                    {"behaviour_cpu_us_max", m ? m->behaviour_cpu_us_max : 0},
                    {"localisation_rms_mm", m ? m->localisation_rms_mm() : 0},
                    {"localisation_rms_rad", m ? m->localisation_rms_rad() : 0},
                    {"penalised", r.penalised},
                    {"x_mm", r.truth.body.x_mm},
                    {"y_mm", r.truth.body.y_mm},
                    {"theta_rad", r.truth.body.theta_rad}});
  }
  return rows;
}

json event_rows(const std::vector<sim::MatchEvent>& events) {
  json rows = json::array();
  for (const sim::MatchEvent& event : events) {
    const match_event_t e = transport::to_msg(event);
    rows.push_back({{"utime", e.utime}, {"kind", int{e.kind}}, {"team", int{e.team}}, {"player", int{e.player}},
                    {"text", e.text}});
  }
  return rows;
}

/// A ratio that is 0, not a division by zero, before anything was timed.
double per(double numerator, double denominator) { return denominator > 0 ? numerator / denominator : 0; }

} // namespace

void write_summary_json(const std::string& path, const sim::Match& match, const transport::RunSummary& s,
                        uint64_t seed, const std::optional<InProcessExtras>& extras) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write summary to " + path);
  const sim::TruthFrame truth = match.truth();
  json summary = {
      {"seed", seed},
      {"frames", s.frames},
      {"sim_s", s.sim_s},
      {"wall_s", s.wall_s},
      {"rtf", per(s.sim_s, s.wall_s)},
      {"truth_hash", transport::hex_hash(s.truth_hash)},
      {"malformed", s.malformed},
      {"stale", s.stale},
      {"future", s.future},
      {"duplicates", s.duplicates},
      {"implausible", s.implausible},
      {"unauthenticated", s.unauthenticated},
      {"handler_failures", s.handler_failures},
      {"resent_senses", s.resent_senses},
      {"slow_answers", s.slow_answers},
      {"interrupted", s.interrupted},
      {"comm",
       {{"sent", match.comm().sent()},
        {"delivered", match.comm().delivered()},
        {"lost", match.comm().lost()},
        {"refused", match.comm().refused()}}},
      {"score", {match.game().score[0], match.game().score[1]}},
      {"ball", {{"x_mm", truth.ball.x_mm}, {"y_mm", truth.ball.y_mm}}},
      {"robots", robot_rows(match, truth)},
      {"match_events", event_rows(s.events)},
  };
  if (extras) {
    summary["world_wall_s"] = extras->world_wall_s;
    summary["physics_rtf"] = per(s.sim_s, extras->world_wall_s);
    summary["cpu_s"] = extras->cpu_s;
    summary["cpu_rtf"] = per(s.sim_s, extras->cpu_s);
  }
  // Invalid UTF-8 in an event's text is replaced rather than thrown on: the summary is
  // written at the end of a whole match.
  out << summary.dump(2, ' ', false, json::error_handler_t::replace) << "\n";
  if (!out) throw std::runtime_error("cannot write summary to " + path);
}

std::string match_plan_json(const sim::WorldConfig& config) {
  const double duration_s = config.match.duration_s;
  const json plan = {{"planned_s", std::min(duration_s, sim::planned_length_s(config.rules))},
                     {"goal_stoppage_s", sim::goal_stoppage_s(config.rules)},
                     {"duration_s", duration_s},
                     {"team_size", config.match.team_size},
                     {"field_length_mm", config.field.length_mm},
                     {"field_width_mm", config.field.width_mm}};
  return plan.dump();
}

} // namespace touchline::apps
