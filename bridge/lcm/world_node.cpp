#include "touchline/lcm/world_node.hpp"

#include <atomic>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <spdlog/logger.h>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "touchline/game_state_t.hpp"
#include "touchline/join_reply_t.hpp"
#include "touchline/join_t.hpp"
#include "touchline/lcm/bus.hpp"
#include "touchline/lcm/match_config.hpp"
#include "touchline/lcm/match_recorder.hpp"
#include "touchline/lcm/world_messages.hpp"
#include "touchline/robot_status_t.hpp"
#include "touchline/sim/lockstep.hpp"

namespace touchline::transport {

namespace {

std::atomic<bool> g_stop{false};
/// Malformed or refused messages reported, one line each, per kind; the rest are counted.
constexpr int64_t kMaxReports = 20;

std::string describe(const sim::MatchEvent& event) {
  std::ostringstream out;
  out << "at " << std::fixed << std::setprecision(1) << static_cast<double>(event.utime) * 1e-6 << " s: ";
  switch (event.kind) {
    case sim::MatchEvent::Kind::kPenalty: out << sim::describe(event.robot) << " penalised for " << event.text; break;
    case sim::MatchEvent::Kind::kReleased: out << sim::describe(event.robot) << " " << event.text; break;
    case sim::MatchEvent::Kind::kFall: out << sim::describe(event.robot) << " " << event.text; break;
    default: out << event.text; break;
  }
  return out.str();
}

class WorldNode {
 public:
  WorldNode(sim::Match& match, const WorldNodeDef& def, Bus& bus, spdlog::logger& log)
      : match_(match), def_(def), log_(log), bus_(bus) {
    bus_.subscribe(kJoinChannel, [this](const BusMessage& m) { on_join(m); });
    bus_.subscribe(kActChannelPattern, [this](const BusMessage& m) { on_act(m); });
    if (!def.log_path.empty()) {
      recorder_ = std::make_unique<MatchRecorder>(def.log_path);
      bus_.subscribe(kSnapshotChannelPattern, [this](const BusMessage& m) { record(m); });
    }
  }

  RunSummary run() {
    publish_match_config(); // the log's first message: a reader learns the geometry before any frame
    wait_for_joins();
    if (def_.gamecontroller) {
      gamecontroller_.emplace(*def_.gamecontroller);
      GameInfo waiting; // robots stand in INITIAL until the GameController says otherwise
      waiting.state = GameState::kInitial;
      match_.set_external_game(waiting, {});
      log_.info("taking the game from GameController packets on {}:{}", def_.gamecontroller->address,
                gamecontroller_->port());
    }
    match_.start();
    publish_match_config();
    publish_game_state(false); // the tools and robots learn the state at once
    log_.info("kick-off with {} robots", match_.active_robots().size());
    const int64_t start_us = wall_us();
    while (!match_.finished() && !g_stop) {
      run_frame(start_us);
    }
    summary_.interrupted = g_stop;
    summary_.unauthenticated = bus_.counters().unauthenticated;
    summary_.handler_failures = bus_.counters().handler_failures;
    summary_.frames = match_.frame();
    summary_.sim_s = static_cast<double>(match_.utime()) * 1e-6;
    summary_.wall_s = static_cast<double>(wall_us() - start_us) * 1e-6;
    publish_events();
    // The end is said several times: a shim that missed it would wait out its world
    // timeout and exit as if the world had died (one lost packet in ten: 1 in 10^5).
    for (int i = 0; i < kFinishedRepeats; ++i) {
      publish_game_state(true);
      bus_.handle(kFinishedGapMs);
    }
    publish_status_all("match over");
    return summary_;
  }

 private:
  void wait_for_joins() {
    const int64_t deadline = wall_us() + static_cast<int64_t>(def_.join_timeout_s * 1e6);
    int64_t next_config_us = wall_us() + kConfigPeriodUs;
    while (static_cast<int>(match_.roster().members().size()) < def_.robots) {
      if (wall_us() >= next_config_us) { // for a tool that started after the world
        publish_match_config();
        next_config_us += kConfigPeriodUs;
      }
      if (g_stop) throw std::runtime_error("interrupted while waiting for robots to join");
      if (wall_us() >= deadline)
        throw std::runtime_error("only " + std::to_string(match_.roster().members().size()) + " of " +
                                 std::to_string(def_.robots) + " robots joined within " +
                                 std::to_string(static_cast<int>(def_.join_timeout_s)) + " s");
      bus_.handle(50);
    }
  }

  /// The latest GameController packet, if one came since the last frame.
  void poll_gamecontroller() {
    if (!gamecontroller_) return;
    const auto packet = gamecontroller_->poll();
    if (!packet) return;
    std::set<RobotId> penalised;
    for (int team = 0; team < 2; ++team)
      for (int player = 1; player <= kMaxTeamSize; ++player)
        if (packet->penalties[static_cast<size_t>(team)][static_cast<size_t>(player - 1)].penalised)
          penalised.insert({team, player});
    if (match_.game().state != packet->game.state || !gamecontroller_seen_)
      log_.info("GameController says {} (packet {})", to_string(packet->game.state), packet->packet_number);
    gamecontroller_seen_ = true;
    match_.set_external_game(packet->game, penalised);
  }

  void run_frame(int64_t start_us) {
    poll_gamecontroller();
    bus_.drain(); // joins and answers that came meanwhile, whatever the robots are doing
    const std::vector<uint8_t> sense = publish(kSenseChannel, to_lcm(match_.sense()));
    if (def_.pacing != Pacing::kFree) wait_for_answers(sense);
    if (def_.pacing != Pacing::kLockstep) pace(start_us);
    match_.advance();
    const auto bytes = publish(kTruthChannel, to_msg(match_.truth()));
    publish_events();
    if (recorder_ && !recorder_->error().empty()) throw std::runtime_error(recorder_->error());
    // The hash covers the encoding, not the tag: the same seed gives the same hash whatever
    // the match secret.
    truth_hash_.add(bytes.data(), bytes.size() - kTagBytes);
    summary_.truth_hash = truth_hash_.value();
    if (match_.frame() % kFramesPerSecond == 0) {
      publish_match_config();
      publish_game_state(false);
      publish_status_all("");
    }
    if (def_.progress && match_.frame() % (10 * kFramesPerSecond) == 0) {
      const double sim_s = static_cast<double>(match_.utime()) * 1e-6;
      const double wall_s = static_cast<double>(wall_us() - start_us) * 1e-6;
      log_.info("{:.0f} s simulated, x{:.1f} real time", sim_s, sim_s / std::max(wall_s, 1e-9));
    }
  }

  /// Waits for this frame's answers. The sense goes out again to whoever is late every
  /// resend_ms, so a lost packet (sense or act: a robot answers a repeated frame with its
  /// answer again) costs milliseconds, not the timeout. A robot late by robot_timeout_ms is
  /// timed out, unless (lockstep and realtime) its robot_shim still runs: then it is waited
  /// for up to live_robot_timeout_ms, since a robot timed out stands still and the match
  /// would no longer be its seed's. With no robot active (all of them timed out at once) the
  /// world waits for every robot on the field, so that any of them can come back instead of
  /// the match racing on without anyone.
  void wait_for_answers(const std::vector<uint8_t>& sense_wire) {
    std::vector<RobotId> expected = match_.active_robots();
    if (expected.empty()) expected = match_.robots_on_field();
    const int64_t start = wall_us();
    const int64_t timeout_us = def_.robot_timeout_ms * 1000;
    const int64_t live_deadline = start + std::max(def_.live_robot_timeout_ms * 1000, timeout_us);
    barrier_.begin(match_.frame(), expected, start, timeout_us);
    std::vector<std::pair<RobotId, bool>> late; // timed out, and whether its shim still ran
    std::set<RobotId> waited;                   // waited for past robot_timeout_ms
    for (int64_t now = await_barrier(sense_wire); !barrier_.missing().empty(); now = await_barrier(sense_wire)) {
      for (RobotId id : barrier_.missing()) {
        const bool runs = shim_runs(id);
        if (runs && now < live_deadline) {
          if (waited.insert(id).second && summary_.slow_answers++ < kMaxReports)
            log_.warn("{} has not answered frame {} in {} ms, but its robot_shim still runs: waiting for it up to "
                      "{} ms, so that the match stays its seed's",
                      sim::describe(id), match_.frame(), def_.robot_timeout_ms, def_.live_robot_timeout_ms);
          continue;
        }
        barrier_.give_up(id);
        late.emplace_back(id, runs);
      }
      barrier_.wait_until(std::min(now + timeout_us, live_deadline));
    }
    for (const auto& [id, ran] : late) {
      match_.time_out(id);
      report(id, robot_status_t::TIMED_OUT,
             "no answer within " + std::to_string(ran ? def_.live_robot_timeout_ms : def_.robot_timeout_ms) +
                 " ms at frame " + std::to_string(match_.frame()) + (ran ? " though its robot_shim runs" : "") +
                 "; it stands still and the match goes on");
    }
  }

  /// Handles messages, sending the sense again to the late every resend_ms, until every
  /// robot the barrier waits for answered or its deadline passed; returns the time then.
  int64_t await_barrier(const std::vector<uint8_t>& sense_wire) {
    const int64_t resend_us = def_.resend_ms * 1000;
    int64_t now = wall_us();
    for (int64_t next_resend = now + resend_us; !barrier_.complete(now); now = wall_us()) {
      if (now >= next_resend) {
        bus_.publish_sealed(kSenseChannel, sense_wire);
        ++summary_.resent_senses;
        next_resend = now + resend_us;
      }
      const int64_t wait_us = std::min(barrier_.remaining_us(now), next_resend - now);
      bus_.handle(static_cast<int>(std::max<int64_t>(1, (wait_us + 999) / 1000)));
    }
    return now;
  }

  /// Whether the robot_shim that joined as `id` still runs on this machine (def_.shim_runs).
  bool shim_runs(RobotId id) const {
    const sim::Member* member = match_.roster().find(id);
    return member && def_.shim_runs && def_.shim_runs(member->pid);
  }

  /// Holds the frame until the wall clock catches up with `speed` x simulated time,
  /// handling messages meanwhile (free mode applies answers as they come).
  void pace(int64_t start_us) {
    const double frame_end_sim_us = static_cast<double>(frame_start_utime(match_.frame() + 1));
    const int64_t due = start_us + static_cast<int64_t>(frame_end_sim_us / def_.speed);
    for (int64_t now = wall_us(); now < due && !g_stop; now = wall_us())
      bus_.handle(static_cast<int>(std::max<int64_t>(1, (due - now) / 1000)));
  }

  /// Publishes and records; returns the bytes as sent (encoding, then tag).
  template <typename Msg>
  std::vector<uint8_t> publish(const char* channel, const Msg& msg) {
    std::vector<uint8_t> wire = bus_.publish(channel, msg);
    if (recorder_) recorder_->record(channel, wire.data(), static_cast<int>(wire.size()), match_.utime());
    return wire;
  }

  /// The log holds each message as it was on the wire, tag included.
  void record(const BusMessage& m) {
    if (recorder_) recorder_->record(m.channel, m.wire, static_cast<int>(m.wire_size), match_.utime());
  }

  void on_join(const BusMessage& m) {
    record(m);
    const std::string& channel = m.channel;
    join_t msg;
    try {
      decode(m.payload, static_cast<int>(m.payload_size), channel, msg);
    } catch (const MalformedMessage& e) {
      malformed(e.what());
      return;
    }
    const RobotId id{msg.team, msg.player};
    const sim::JoinReply reply = match_.join(id, msg.instance, msg.pid);
    join_reply_t out;
    out.utime = match_.utime();
    out.team = msg.team;
    out.player = msg.player;
    out.instance = msg.instance;
    out.accepted = reply.accepted;
    out.reason = reply.reason;
    publish(kJoinReplyChannel, out);
    if (!reply.accepted) {
      if (rejected_.insert(msg.instance).second)
        log_.warn("refused a robot_shim (pid {}): {}", msg.pid, reply.reason);
    } else if (joined_.insert(msg.instance).second) {
      report(id, robot_status_t::JOINED, "joined (pid " + std::to_string(msg.pid) + ")");
    }
  }

  void on_act(const BusMessage& m) {
    record(m);
    const std::string& channel = m.channel;
    act_t msg;
    RobotAct act;
    try {
      decode(m.payload, static_cast<int>(m.payload_size), channel, msg);
      act = from_lcm(msg);
      if (channel != act_channel(act.id))
        throw MalformedMessage(channel + ": carries an act of " + sim::describe(act.id));
    } catch (const MalformedMessage& e) {
      malformed(e.what());
      return;
    }
    switch (match_.apply(act, msg.instance, def_.pacing == Pacing::kFree)) {
      case sim::ActOutcome::kRejoined:
        report(act.id, robot_status_t::REJOINED, "answered again at frame " + std::to_string(act.frame));
        [[fallthrough]];
      case sim::ActOutcome::kApplied:
        barrier_.answer(act.id, act.frame);
        break;
      case sim::ActOutcome::kStale:
        ++summary_.stale;
        break;
      case sim::ActOutcome::kFuture:
        ++summary_.future;
        malformed(channel + ": answers frame " + std::to_string(act.frame) + ", which has not been sensed yet");
        break;
      case sim::ActOutcome::kDuplicate:
        ++summary_.duplicates; // a repeated answer to a repeated sense: expected, harmless
        break;
      case sim::ActOutcome::kImplausible:
        ++summary_.implausible;
        malformed(channel + ": moves a foot or the head further than a robot can in one tick; refused");
        break;
      case sim::ActOutcome::kUnknown:
        if (unknown_.insert(msg.instance).second)
          log_.warn("ignoring answers from a {} that has not joined (instance {})", sim::describe(act.id),
                    msg.instance);
        break;
    }
  }

  void malformed(const std::string& what) {
    if (summary_.malformed++ < kMaxReports) log_.warn("ignored malformed message: {}", what);
  }

  void report(RobotId id, int8_t state, const std::string& detail) {
    log_.info("{} {}", sim::describe(id), detail);
    publish_status(id, state, detail);
  }

  void publish_status(RobotId id, int8_t state, const std::string& detail) {
    const sim::Member* member = match_.roster().find(id);
    robot_status_t msg;
    msg.utime = match_.utime();
    msg.team = static_cast<int8_t>(id.team);
    msg.player = static_cast<int8_t>(id.player);
    msg.state = state;
    msg.frames_answered = member ? member->frames_answered : 0;
    msg.frames_missed = member ? member->frames_missed : 0;
    msg.behaviour_cpu_us_mean = member ? static_cast<int32_t>(member->behaviour_cpu_us_mean()) : 0;
    msg.behaviour_cpu_us_max = member ? static_cast<int32_t>(member->behaviour_cpu_us_max) : 0;
    msg.detail = detail;
    publish(kStatusChannel, msg);
  }

  void publish_status_all(const std::string& detail) {
    for (const auto& [id, member] : match_.roster().members())
      publish_status(id, member.active ? robot_status_t::ACTIVE : robot_status_t::TIMED_OUT, detail);
  }

  /// The game as the referee sees it; `finished` marks the end of the run for the shims
  /// (also when it ends on the duration cap or a stop before the referee's FINISHED).
  void publish_game_state(bool finished) {
    publish(kGameChannel, to_msg(match_.game(), match_.utime(), finished));
  }

  /// TL_MATCH: the geometry and set-up this match runs with (the config after every override).
  void publish_match_config() { publish(kMatchChannel, to_lcm(match_.config(), match_.seed(), match_.utime())); }

  void publish_events() {
    const std::vector<sim::MatchEvent> events = match_.take_events();
    for (const sim::MatchEvent& event : events) {
      publish(kEventChannel, to_msg(event));
      if (def_.progress) log_.info("{}", describe(event));
    }
    if (!events.empty()) publish_game_state(false); // the game changed: tell the robots and tools at once
    summary_.events.insert(summary_.events.end(), events.begin(), events.end());
  }

  static constexpr int kFinishedRepeats = 5;
  static constexpr int kFinishedGapMs = 10;
  static constexpr int64_t kConfigPeriodUs = 1000000; ///< TL_MATCH while the robots join, wall time

  sim::Match& match_;
  const WorldNodeDef& def_;
  spdlog::logger& log_;
  Bus& bus_;
  sim::FrameBarrier barrier_;
  std::unique_ptr<MatchRecorder> recorder_;
  std::optional<GameControllerReceiver> gamecontroller_;
  bool gamecontroller_seen_ = false;
  TruthHash truth_hash_;
  RunSummary summary_;
  std::set<int64_t> joined_, rejected_, unknown_;
};

} // namespace

void request_stop() { g_stop = true; }

RunSummary run_world(sim::Match& match, const WorldNodeDef& def, Bus& bus, spdlog::logger& log) {
  g_stop = false;
  WorldNode node(match, def, bus, log);
  return node.run();
}

RunSummary run_world(sim::Match& match, const WorldNodeDef& def, spdlog::logger& log) {
  int64_t reports = 0; // a message the bus refused (no valid tag) or whose handler failed
  Bus bus(def.lcm_url, def.key, [&](const std::string& what) {
    if (reports++ < kMaxReports) log.warn("{}", what);
  });
  return run_world(match, def, bus, log);
}

std::string hex_hash(uint64_t value) {
  std::ostringstream out;
  out << std::hex << std::setw(16) << std::setfill('0') << value;
  return out.str();
}

} // namespace touchline::transport
