#include "touchline/apps/summary_json.hpp"

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <stdexcept>

#include "touchline/lcm/world_messages.hpp"

namespace touchline::apps {

namespace {

/// `text` as the inside of a JSON string.
std::string json_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char code[8];
      std::snprintf(code, sizeof code, "\\u%04x", c);
      out += code;
    } else {
      out += c;
    }
  }
  return out;
}

} // namespace

void write_summary_json(const std::string& path, const sim::Match& match, const transport::RunSummary& s,
                        uint64_t seed, const std::optional<InProcessExtras>& extras) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write summary to " + path);
  const sim::TruthFrame truth = match.truth();
  out << std::setprecision(9) << "{\n"
      << "  \"seed\": " << seed << ",\n"
      << "  \"frames\": " << s.frames << ",\n"
      << "  \"sim_s\": " << s.sim_s << ",\n"
      << "  \"wall_s\": " << s.wall_s << ",\n"
      << "  \"rtf\": " << (s.wall_s > 0 ? s.sim_s / s.wall_s : 0) << ",\n"
      << "  \"truth_hash\": \"" << transport::hex_hash(s.truth_hash) << "\",\n"
      << "  \"malformed\": " << s.malformed << ",\n"
      << "  \"stale\": " << s.stale << ",\n"
      << "  \"future\": " << s.future << ",\n"
      << "  \"duplicates\": " << s.duplicates << ",\n"
      << "  \"implausible\": " << s.implausible << ",\n"
      << "  \"unauthenticated\": " << s.unauthenticated << ",\n"
      << "  \"handler_failures\": " << s.handler_failures << ",\n"
      << "  \"resent_senses\": " << s.resent_senses << ",\n"
      << "  \"interrupted\": " << (s.interrupted ? "true" : "false") << ",\n"
      << "  \"comm\": {\"sent\": " << match.comm().sent() << ", \"delivered\": " << match.comm().delivered()
      << ", \"lost\": " << match.comm().lost() << ", \"refused\": " << match.comm().refused() << "},\n"
      << "  \"score\": [" << match.game().score[0] << ", " << match.game().score[1] << "],\n"
      << "  \"ball\": {\"x_mm\": " << truth.ball.x_mm << ", \"y_mm\": " << truth.ball.y_mm << "},\n"
      << "  \"robots\": [";
  for (size_t i = 0; i < truth.robots.size(); ++i) {
    const auto& r = truth.robots[i];
    const sim::Member* m = match.roster().find(r.truth.id);
    out << (i ? ",\n" : "\n") << "    {\"team\": " << r.truth.id.team << ", \"player\": " << r.truth.id.player
        << ", \"active\": " << (r.active ? "true" : "false")
        << ", \"frames_answered\": " << (m ? m->frames_answered : 0)
        << ", \"frames_missed\": " << (m ? m->frames_missed : 0)
        << ", \"behaviour_cpu_us_mean\": " << (m ? m->behaviour_cpu_us_mean() : 0)
        << ", \"behaviour_cpu_us_max\": " << (m ? m->behaviour_cpu_us_max : 0)
        << ", \"localisation_rms_mm\": " << (m ? m->localisation_rms_mm() : 0)
        << ", \"localisation_rms_rad\": " << (m ? m->localisation_rms_rad() : 0)
        << ", \"penalised\": " << (r.penalised ? "true" : "false") << ", \"x_mm\": " << r.truth.body.x_mm
        << ", \"y_mm\": " << r.truth.body.y_mm << ", \"theta_rad\": " << r.truth.body.theta_rad << "}";
  }
  out << "\n  ]";
  if (extras) {
    const std::vector<sim::MatchEvent>& events = extras->events;
    out << ",\n  \"world_wall_s\": " << extras->world_wall_s << ",\n  \"physics_rtf\": "
        << (extras->world_wall_s > 0 ? s.sim_s / extras->world_wall_s : 0) << ",\n  \"cpu_s\": " << extras->cpu_s
        << ",\n  \"cpu_rtf\": " << (extras->cpu_s > 0 ? s.sim_s / extras->cpu_s : 0);
    out << ",\n  \"match_events\": [";
    for (size_t i = 0; i < events.size(); ++i) {
      const match_event_t e = transport::to_msg(events[i]);
      out << (i ? ",\n" : "\n") << "    {\"utime\": " << e.utime << ", \"kind\": " << int{e.kind}
          << ", \"team\": " << int{e.team} << ", \"player\": " << int{e.player} << ", \"text\": \""
          << json_escaped(e.text) << "\"}";
    }
    out << "\n  ]";
  }
  out << "\n}\n";
}

} // namespace touchline::apps
