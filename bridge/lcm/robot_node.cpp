#include "touchline/lcm/robot_node.hpp"

#include <unistd.h>

#include <atomic>
#include <spdlog/logger.h>
#include <random>

#include "touchline/game_state_t.hpp"
#include "touchline/join_reply_t.hpp"
#include "touchline/join_t.hpp"
#include "touchline/lcm/bus.hpp"
#include "touchline/lcm/snapshot.hpp"

namespace touchline::transport {

namespace {

std::atomic<bool> g_stop{false};
constexpr int64_t kMaxReports = 20; ///< malformed messages reported, one line each; the rest counted

/// Tells this process's joins and acts from those of another shim claiming the same robot.
int64_t random_instance() {
  std::mt19937_64 rng(std::random_device{}() ^ static_cast<uint64_t>(getpid()));
  return static_cast<int64_t>(rng() >> 1) | 1;
}

} // namespace

class RobotNode::Impl {
 public:
  Impl(robot::Robot& robot, const RobotNodeDef& def, Bus& bus, spdlog::logger& log)
      : robot_(robot), def_(def), log_(log), bus_(bus),
        act_channel_(act_channel(robot.id())), snapshot_channel_(snapshot_channel(robot.id())) {
    instance_ = def.instance ? def.instance : random_instance();
    bus_.subscribe(kJoinReplyChannel, [this](const BusMessage& m) { on_join_reply(m); });
    bus_.subscribe(kSenseChannel, [this](const BusMessage& m) { on_sense(m); });
    bus_.subscribe(kGameChannel, [this](const BusMessage& m) { on_game(m); });
    robot_.keep_behaviour_view(def.snapshot_every > 0);
  }

  /// One request to play (join() repeats it until the world answers).
  void request_join() {
    join_t msg;
    msg.utime = wall_us();
    msg.team = static_cast<int8_t>(robot_.id().team);
    msg.player = static_cast<int8_t>(robot_.id().player);
    msg.instance = instance_;
    msg.pid = static_cast<int32_t>(getpid());
    bus_.publish(kJoinChannel, msg);
  }
  bool joined() const { return joined_; }
  bool match_over() const { return exit_ == RobotExit::kMatchOver; }

  RobotExit run() {
    if (!join()) return exit_;
    last_heard_us_ = wall_us();
    while (exit_ == kPlaying) {
      if (g_stop) return RobotExit::kInterrupted;
      bus_.handle(200);
      if (wall_us() - last_heard_us_ > static_cast<int64_t>(def_.world_timeout_s * 1e6)) {
        log_.error("sim_world silent for {} s, giving up", def_.world_timeout_s);
        return RobotExit::kNoWorld;
      }
    }
    return exit_;
  }

 private:
  static constexpr RobotExit kPlaying = static_cast<RobotExit>(-1);

  /// Asks to play, again every 250 ms, until the world answers.
  bool join() {
    const int64_t deadline = wall_us() + static_cast<int64_t>(def_.join_timeout_s * 1e6);
    int64_t next_request = 0;
    while (!joined_ && exit_ == kPlaying) {
      if (g_stop) {
        exit_ = RobotExit::kInterrupted;
        break;
      }
      const int64_t now = wall_us();
      if (now >= deadline) {
        log_.error("no sim_world accepted the join within {} s", def_.join_timeout_s);
        exit_ = RobotExit::kNoWorld;
        break;
      }
      if (now >= next_request) {
        request_join();
        next_request = now + 250000;
      }
      bus_.handle(50);
    }
    return joined_;
  }

  void on_join_reply(const BusMessage& m) {
    join_reply_t msg;
    if (!decode_or_report(m, msg) || msg.instance != instance_) return;
    if (msg.accepted) {
      joined_ = true;
    } else {
      log_.error("sim_world refused to let us play: {}", msg.reason);
      exit_ = RobotExit::kRejected;
    }
  }

  void on_sense(const BusMessage& m) {
    sense_t msg;
    if (!decode_or_report(m, msg)) return;
    last_heard_us_ = wall_us();
    SenseFrame frame;
    try {
      frame = from_lcm(msg); // also refuses a frame past kMaxFrame or at the wrong time
    } catch (const MalformedMessage& e) {
      report_malformed(e.what());
      return;
    }
    const RobotSense* mine = frame.find(robot_.id());
    if (!joined_ || !mine || frame.frame < last_frame_) return; // not ours yet, or an old frame
    if (frame.frame == last_frame_) {
      // The world sent the frame again: our answer was lost, or is on its way. Answer
      // again with the same bytes (computing it again would tick the behaviour twice).
      if (!last_act_.empty()) bus_.publish_sealed(act_channel_, last_act_);
      return;
    }
    last_frame_ = frame.frame;
    const RobotAct act = robot_.step(frame, *mine);
    publish_snapshot(frame.frame);
    last_act_ = bus_.publish(act_channel_, to_lcm(act, frame.utime, instance_));
  }

  /// Before the act, so a recording world logs the snapshot ahead of the answer.
  void publish_snapshot(int64_t frame) {
    if (def_.snapshot_every <= 0 || !robot_.behaviour_stats().ticked_last_step) return;
    if (behaviour_ticks_++ % def_.snapshot_every != 0) return;
    bus_.publish(snapshot_channel_, to_snapshot(robot_.behaviour_view(), robot_.id(), frame));
  }

  void on_game(const BusMessage& m) {
    game_state_t msg;
    if (!decode_or_report(m, msg)) return;
    last_heard_us_ = wall_us();
    if (msg.state == game_state_t::FINISHED && joined_) exit_ = RobotExit::kMatchOver;
  }

  template <typename Msg>
  bool decode_or_report(const BusMessage& m, Msg& msg) {
    try {
      decode(m.payload, static_cast<int>(m.payload_size), m.channel, msg);
      return true;
    } catch (const MalformedMessage& e) {
      report_malformed(e.what());
      return false;
    }
  }

  void report_malformed(const std::string& what) {
    if (malformed_++ < kMaxReports) log_.warn("ignored malformed message: {}", what);
  }

  robot::Robot& robot_;
  const RobotNodeDef& def_;
  spdlog::logger& log_;

  Bus& bus_;
  std::vector<uint8_t> last_act_; ///< the last answer as sent, for a repeated frame
  std::string act_channel_;
  std::string snapshot_channel_;
  int64_t behaviour_ticks_ = 0;
  int64_t instance_ = 0;
  bool joined_ = false;
  RobotExit exit_ = kPlaying;
  int64_t last_frame_ = -1;
  int64_t last_heard_us_ = 0;
  int64_t malformed_ = 0;
};

RobotNode::RobotNode(robot::Robot& robot, const RobotNodeDef& def, Bus& bus, spdlog::logger& log)
    : impl_(std::make_unique<Impl>(robot, def, bus, log)) {}
RobotNode::~RobotNode() = default;
RobotExit RobotNode::run() { return impl_->run(); }
void RobotNode::request_join() { impl_->request_join(); }
bool RobotNode::joined() const { return impl_->joined(); }
bool RobotNode::match_over() const { return impl_->match_over(); }

void request_robot_stop() { g_stop = true; }

RobotExit run_robot(robot::Robot& robot, const RobotNodeDef& def, spdlog::logger& log) {
  g_stop = false;
  int64_t reports = 0;
  Bus bus(
      def.lcm_url, def.key,
      [&](const std::string& what) {
        if (reports++ < kMaxReports) log.warn("ignored malformed message: {}", what);
      },
      BusRole::kRobot);
  RobotNode node(robot, def, bus, log);
  return node.run();
}

} // namespace touchline::transport
