#include "touchline/python/runswift/team_message.hpp"

#include <cmath>
#include <cstring>

namespace touchline::python::runswift {

namespace {

constexpr uint8_t kVersion = 1;

class Writer {
 public:
  void u8(int v) { bytes.push_back(static_cast<uint8_t>(v)); }
  void i16(int v) {
    const auto u = static_cast<uint16_t>(static_cast<int16_t>(v));
    u8(u & 0xff);
    u8(u >> 8);
  }
  void f32(float v) {
    uint32_t u = 0;
    std::memcpy(&u, &v, sizeof u);
    for (int shift = 0; shift < 32; shift += 8) u8((u >> shift) & 0xff);
  }
  std::vector<uint8_t> bytes;
};

class Reader {
 public:
  explicit Reader(const std::vector<uint8_t>& bytes) : bytes_(bytes) {}
  int u8() { return bytes_[at_++]; }
  int i16() {
    const uint16_t u = static_cast<uint16_t>(u8() | (u8() << 8));
    return static_cast<int16_t>(u);
  }
  float f32() {
    uint32_t u = 0;
    for (int shift = 0; shift < 32; shift += 8) u |= static_cast<uint32_t>(u8()) << shift;
    float v = 0;
    std::memcpy(&v, &u, sizeof v);
    return v;
  }

 private:
  const std::vector<uint8_t>& bytes_;
  size_t at_ = 0;
};

int clamp_int(int v, int lo, int hi) { return v < lo ? lo : v > hi ? hi : v; }

} // namespace

std::vector<uint8_t> encode_broadcast(const Broadcast& b) {
  const BroadcastData& d = b.data;
  const BehaviourSharedData& s = d.behaviourSharedData;
  Writer w;
  w.u8('R');
  w.u8('S');
  w.u8(kVersion);
  w.u8(clamp_int(d.playerNum, 0, 255));
  w.u8((b.fallen ? 1 : 0) | (b.penalised ? 2 : 0) | (d.sharedStateEstimationBundle.haveBallUpdate ? 4 : 0) |
       (s.playingBall ? 8 : 0) | (s.needAssistance ? 16 : 0) | (s.isAssisting ? 32 : 0) | (s.isKickedOff ? 64 : 0) |
       (s.kickNotification ? 128 : 0));
  w.u8(clamp_int(d.acB, 0, 255));
  w.u8(clamp_int(d.gameState, 0, 255));
  w.u8(clamp_int(s.role, 0, 255));
  w.i16(clamp_int(s.secondsSinceLastKick, -32768, 32767));
  for (float v : d.robotPos) w.f32(v);
  w.f32(d.ballPosAbs.x);
  w.f32(d.ballPosAbs.y);
  w.f32(d.ballPosRR.distance);
  w.f32(d.ballPosRR.heading);
  w.f32(d.sharedStateEstimationBundle.ballVelRRC.x);
  w.f32(d.sharedStateEstimationBundle.ballVelRRC.y);
  w.f32(s.walkingToX);
  w.f32(s.walkingToY);
  w.f32(s.walkingToH);
  w.f32(d.uptime);
  w.f32(b.ball_age_s);
  return w.bytes;
}

std::optional<Broadcast> decode_broadcast(const std::vector<uint8_t>& bytes) {
  if (bytes.size() != kBroadcastBytes || bytes[0] != 'R' || bytes[1] != 'S' || bytes[2] != kVersion) return std::nullopt;
  Reader r(bytes);
  r.u8();
  r.u8();
  r.u8();
  Broadcast b;
  BroadcastData& d = b.data;
  BehaviourSharedData& s = d.behaviourSharedData;
  d.playerNum = r.u8();
  const int flags = r.u8();
  b.fallen = flags & 1;
  b.penalised = flags & 2;
  d.sharedStateEstimationBundle.haveBallUpdate = flags & 4;
  s.playingBall = flags & 8;
  s.needAssistance = flags & 16;
  s.isAssisting = flags & 32;
  s.isKickedOff = flags & 64;
  s.kickNotification = flags & 128;
  d.acB = r.u8();
  d.gameState = r.u8();
  s.role = r.u8();
  s.secondsSinceLastKick = r.i16();
  for (float& v : d.robotPos) v = r.f32();
  d.ballPosAbs.x = r.f32();
  d.ballPosAbs.y = r.f32();
  d.ballPosRR.distance = r.f32();
  d.ballPosRR.heading = r.f32();
  d.sharedStateEstimationBundle.ballVelRRC.x = r.f32();
  d.sharedStateEstimationBundle.ballVelRRC.y = r.f32();
  s.walkingToX = r.f32();
  s.walkingToY = r.f32();
  s.walkingToH = r.f32();
  d.uptime = r.f32();
  b.ball_age_s = r.f32();
  // A sender's own numbers: anything not finite is junk, not a teammate's belief.
  for (float v : {d.robotPos[0], d.robotPos[1], d.robotPos[2], d.ballPosAbs.x, d.ballPosAbs.y, d.ballPosRR.distance,
                  d.ballPosRR.heading, s.walkingToX, s.walkingToY, s.walkingToH, d.uptime, b.ball_age_s})
    if (!std::isfinite(v)) return std::nullopt;
  d.sharedStateEstimationBundle.robotPos = {d.robotPos[0], d.robotPos[1], d.robotPos[2]};
  d.sharedStateEstimationBundle.ballPosRRC = {d.ballPosRR.distance * std::cos(d.ballPosRR.heading),
                                              d.ballPosRR.distance * std::sin(d.ballPosRR.heading), 0};
  return b;
}

} // namespace touchline::python::runswift
