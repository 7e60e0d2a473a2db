// Bounded fuzzing of every LCM type (all_lcm_types.hpp lists lcm_types/*.lcm) through every
// decoder on the receiving side: the generated decoder (hardened by
// lcm_types/harden_decoders.cmake), transport::decode(), and the validators that turn a
// message into our own types (from_lcm, from_snapshot). Each input must decode or be a
// MalformedMessage: no other exception, no crash (the sanitizer build runs this test too),
// and no allocation larger than the input's size can justify. The inputs: every 1-, 2-, 4-
// and 8-byte window of valid encodings set to edge values, then seeded random mutants.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "all_lcm_types.hpp"
#include "allocation_meter.hpp"
#include "mutator.hpp"
#include "touchline/hash.hpp"
#include "touchline/lcm/codec.hpp"
#include "touchline/lcm/snapshot.hpp"

using namespace touchline;
using fuzz::Bytes;

namespace {

template <typename... T>
constexpr size_t largest_sizeof() {
  return std::max({sizeof(T)...});
}
/// No element of a decoded array is larger than this, so a decoder that checks its counts
/// against the bytes left never allocates more than this per input byte.
constexpr size_t kLargestElementBytes = largest_sizeof<TOUCHLINE_ALL_LCM_TYPES>();

template <typename Msg>
struct Tag {};

// Valid samples of every type, with non-empty arrays and strings where the type has them.
// A new .lcm type needs an overload here (the test does not compile without one).
std::vector<pose2d_t> samples(Tag<pose2d_t>) { return {transport::to_lcm(Pose2D{120, -40, 1.5f})}; }

std::vector<foot_motion_t> samples(Tag<foot_motion_t>) { return {foot_motion_t{2.5f, -1.f, 0.01f}}; }

std::vector<observation_t> samples(Tag<observation_t>) { return {observation_t{1, 2, 1500, 0.3f, 0.6f}}; }

std::vector<team_message_t> samples(Tag<team_message_t>) {
  team_message_t empty{};
  empty.player = 2;
  team_message_t some = empty;
  some.data = {1, 2, 3, 4};
  some.size = 4;
  return {empty, some};
}

RobotAct act(int ticks) {
  RobotAct a;
  a.id = {1, 4};
  a.frame = 77;
  a.motion_ticks = ticks;
  for (int i = 0; i < ticks; ++i) a.left[static_cast<size_t>(i)] = a.right[static_cast<size_t>(i)] = {1.f, 0.5f, 0.01f};
  a.team_message = {9, 8, 7};
  return a;
}

std::vector<act_t> samples(Tag<act_t>) {
  return {transport::to_lcm(act(4), frame_start_utime(77), 5), transport::to_lcm(act(0), frame_start_utime(77), 5)};
}

SenseFrame sense_frame() {
  SenseFrame f;
  f.frame = 8;
  f.utime = frame_start_utime(8);
  f.motion_ticks = ticks_in_frame(8);
  for (int player = 1; player <= 2; ++player) {
    RobotSense r;
    r.id = {player - 1, player};
    r.seen = {{ObjectKind::kBall, 0, 900, 0.1f, 0.5f}, {ObjectKind::kFieldCorner, 2, 3000, -1.f, 0.1f}};
    r.messages = {{2, frame_start_utime(7), {1, 2}}};
    f.robots.push_back(r);
  }
  return f;
}

std::vector<sense_t> samples(Tag<sense_t>) { return {transport::to_lcm(sense_frame()), transport::to_lcm(SenseFrame{})}; }

std::vector<robot_sense_t> samples(Tag<robot_sense_t>) { return {transport::to_lcm(sense_frame()).robots[0]}; }

std::vector<robot_truth_t> samples(Tag<robot_truth_t>) {
  robot_truth_t t{};
  t.team = 1;
  t.player = 3;
  t.body = transport::to_lcm(Pose2D{10, 20, 0.3f});
  return {t};
}

std::vector<world_truth_t> samples(Tag<world_truth_t>) {
  world_truth_t w{};
  w.frame = 8;
  w.robots = {samples(Tag<robot_truth_t>{})[0], samples(Tag<robot_truth_t>{})[0]};
  w.num_robots = 2;
  return {w, world_truth_t{}};
}

std::vector<game_state_t> samples(Tag<game_state_t>) {
  game_state_t g{};
  g.state = game_state_t::PLAYING;
  g.secs_remaining = 300;
  return {g};
}

std::vector<join_t> samples(Tag<join_t>) { return {join_t{0, 1, 3, 424242, 1000}}; }

std::vector<join_reply_t> samples(Tag<join_reply_t>) {
  join_reply_t accepted{};
  accepted.accepted = 1;
  join_reply_t refused = accepted;
  refused.accepted = 0;
  refused.reason = "team 1 player 3 is taken";
  return {accepted, refused};
}

std::vector<match_event_t> samples(Tag<match_event_t>) {
  match_event_t e{};
  e.kind = match_event_t::GOAL;
  e.text = "goal";
  return {e};
}

std::vector<robot_status_t> samples(Tag<robot_status_t>) {
  robot_status_t s{};
  s.state = robot_status_t::JOINED;
  s.detail = "joined (pid 1000)";
  return {s};
}

std::vector<body_request_t> samples(Tag<body_request_t>) { return {body_request_t{2, 200, 0, 0.5f, 0, 0, 1, 0}}; }

std::vector<head_request_t> samples(Tag<head_request_t>) { return {head_request_t{0.5f, 0.1f, 0, 1, 1}}; }

std::vector<blackboard_snapshot_t> samples(Tag<blackboard_snapshot_t>) {
  api::Blackboard bb;
  bb.behaviour.skill = "GoToBall";
  bb.receiver.messages = {{2, 1000, {1, 2, 3}}, {3, 2000, {}}};
  return {transport::to_snapshot(bb, {0, 2}, 30), transport::to_snapshot(api::Blackboard{}, {1, 1}, 0)};
}

// What the receiving programs do with a decoded message: convert and validate it, or use
// it as it is.
void validate(const act_t& m) { transport::from_lcm(m); }
void validate(const sense_t& m) { transport::from_lcm(m); }
void validate(const blackboard_snapshot_t& m) { transport::from_snapshot(m); }
template <typename Msg>
void validate(const Msg&) {}

template <typename Msg>
Bytes encode(const Msg& msg) {
  Bytes bytes(static_cast<size_t>(msg.getEncodedSize()));
  EXPECT_EQ(msg.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  return bytes;
}

struct Outcomes {
  int decoded = 0;
  int malformed = 0;
};

/// Feeds `bytes` to every decoder of Msg; adds a test failure for anything but a decoded
/// message or a MalformedMessage. Returns false on failure (the caller stops).
template <typename Msg>
bool check(const Bytes& bytes, Outcomes& outcomes) {
  const int size = static_cast<int>(bytes.size());
  {
    Msg raw{};
    fuzz::AllocationMeter meter;
    try {
      raw.decode(bytes.data(), 0, size);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "the generated " << Msg::getTypeName() << " decoder threw \"" << e.what() << "\" on "
                    << fuzz::hex(bytes);
      return false;
    }
    const size_t limit = (bytes.size() + 1) * kLargestElementBytes;
    if (meter.largest() > limit) {
      ADD_FAILURE() << "the generated " << Msg::getTypeName() << " decoder allocated " << meter.largest()
                    << " bytes at once for a " << bytes.size() << "-byte input (limit " << limit << "): "
                    << fuzz::hex(bytes);
      return false;
    }
  }
  try {
    Msg msg;
    transport::decode(bytes.data(), size, "FUZZ", msg);
    validate(msg);
    ++outcomes.decoded;
  } catch (const transport::MalformedMessage&) {
    ++outcomes.malformed;
  } catch (const std::exception& e) {
    ADD_FAILURE() << Msg::getTypeName() << ": \"" << e.what() << "\" is not a MalformedMessage, on "
                  << fuzz::hex(bytes);
    return false;
  }
  return true;
}

template <typename Msg>
class FuzzLcm : public ::testing::Test {};

struct TypeName {
  template <typename Msg>
  static std::string GetName(int) {
    return Msg::getTypeName();
  }
};

TYPED_TEST_SUITE(FuzzLcm, ::testing::Types<TOUCHLINE_ALL_LCM_TYPES>, TypeName);

} // namespace

TYPED_TEST(FuzzLcm, EveryInputDecodesOrIsMalformed) {
  using Msg = TypeParam;
  std::vector<Bytes> seeds;
  for (const Msg& sample : samples(Tag<Msg>{})) seeds.push_back(encode(sample));
  Outcomes samples_outcome;
  for (const Bytes& seed : seeds) ASSERT_TRUE(check<Msg>(seed, samples_outcome));
  ASSERT_EQ(samples_outcome.malformed, 0) << "a sample of " << Msg::getTypeName() << " is itself malformed";

  Outcomes outcomes;
  bool ok = true;
  fuzz::sweep_edge_values(seeds, [&](const Bytes& bytes) { ok = ok && check<Msg>(bytes, outcomes); });
  ASSERT_TRUE(ok);

  Fnv1a type_hash;
  type_hash.add(Msg::getTypeName(), std::char_traits<char>::length(Msg::getTypeName()));
  fuzz::Mutator mutator(fuzz::seed() ^ type_hash.value(), seeds, /*keep: the fingerprint*/ 8);
  const int n = fuzz::iterations();
  for (int i = 0; i < n && check<Msg>(mutator.next(), outcomes); ++i) {
  }
  // Both outcomes, or the inputs never reached past the fingerprint check (or never failed).
  EXPECT_GT(outcomes.decoded, 0);
  EXPECT_GT(outcomes.malformed, 0);
  std::cout << Msg::getTypeName() << ": " << outcomes.decoded << " decoded, " << outcomes.malformed
            << " malformed\n";
}
