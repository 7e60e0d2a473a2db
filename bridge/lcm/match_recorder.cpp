#include "touchline/lcm/match_recorder.hpp"

#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

namespace touchline::transport {

MatchRecorder::MatchRecorder(const std::string& path)
    : path_(path), log_(std::make_unique<::lcm::LogFile>(path, "w")) {
  if (!log_->good()) throw std::runtime_error("cannot write the match log " + path);
}

MatchRecorder::~MatchRecorder() = default;

void MatchRecorder::record(const std::string& channel, const void* data, int size, int64_t sim_utime) noexcept {
  if (!error_.empty()) return;
  ::lcm::LogEvent event;
  event.eventnum = events_;
  event.timestamp = sim_utime;
  event.channel = channel;
  event.datalen = size;
  event.data = const_cast<void*>(data); // LogFile writes from it; it never changes it
  if (log_->writeEvent(&event) != 0) {
    error_ = "cannot write to the match log " + path_ + " (disk full?)";
    return;
  }
  ++events_;
}

} // namespace touchline::transport
