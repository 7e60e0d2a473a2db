#pragma once
// Valid samples of every input the fuzz tests mutate: each LCM type (with non-empty arrays
// and strings where the type has them) and GameController packets. A new .lcm type needs a
// samples() overload here (test_fuzz_lcm.cpp does not compile without one).
#include <vector>

#include "all_lcm_types.hpp"
#include "mutator.hpp"

namespace touchline::fuzz {

template <typename Msg>
struct Tag {};

std::vector<act_t> samples(Tag<act_t>);
std::vector<blackboard_snapshot_t> samples(Tag<blackboard_snapshot_t>);
std::vector<body_request_t> samples(Tag<body_request_t>);
std::vector<foot_motion_t> samples(Tag<foot_motion_t>);
std::vector<game_state_t> samples(Tag<game_state_t>);
std::vector<head_request_t> samples(Tag<head_request_t>);
std::vector<join_reply_t> samples(Tag<join_reply_t>);
std::vector<join_t> samples(Tag<join_t>);
std::vector<match_config_t> samples(Tag<match_config_t>);
std::vector<match_event_t> samples(Tag<match_event_t>);
std::vector<observation_t> samples(Tag<observation_t>);
std::vector<pose2d_t> samples(Tag<pose2d_t>);
std::vector<robot_sense_t> samples(Tag<robot_sense_t>);
std::vector<robot_status_t> samples(Tag<robot_status_t>);
std::vector<robot_truth_t> samples(Tag<robot_truth_t>);
std::vector<sense_t> samples(Tag<sense_t>);
std::vector<team_message_t> samples(Tag<team_message_t>);
std::vector<world_truth_t> samples(Tag<world_truth_t>);

/// The encodings of samples(Tag<Msg>{}), fingerprint first.
template <typename Msg>
std::vector<Bytes> sample_encodings() {
  std::vector<Bytes> out;
  for (const Msg& msg : samples(Tag<Msg>{})) {
    Bytes bytes(static_cast<size_t>(msg.getEncodedSize()));
    msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    out.push_back(bytes);
  }
  return out;
}

/// Valid GameController data packets (layout in touchline/gamecontroller/packet.hpp) of teams
/// 5 and 12: versions 15 and 18, PLAYING, STANDBY and READY, penalties on both sides.
std::vector<Bytes> gamecontroller_samples();

} // namespace touchline::fuzz
