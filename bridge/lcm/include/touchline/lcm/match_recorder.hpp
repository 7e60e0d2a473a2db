#pragma once
// Writes a match's messages to an LCM event log (the format lcm-logger writes), from
// inside sim_world: everything the world publishes and everything it receives, in the
// order it handled them, so no message is lost however fast the match runs. Event
// timestamps are simulated time, so lcm-logplayer replays the match at real-time speed.
#include <cstdint>
#include <memory>
#include <string>

namespace lcm {
class LogFile;
}

namespace touchline::transport {

class MatchRecorder {
 public:
  /// Opens (truncates) `path`. Throws std::runtime_error if it cannot.
  explicit MatchRecorder(const std::string& path);
  ~MatchRecorder();

  /// Never throws (it runs inside LCM handlers); a failed write (disk full, ...) is kept
  /// in error(), which the world checks every frame: a log with a hole is worse than a
  /// stopped match.
  void record(const std::string& channel, const void* data, int size, int64_t sim_utime) noexcept;
  const std::string& error() const { return error_; }
  int64_t events() const { return events_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::unique_ptr<::lcm::LogFile> log_;
  int64_t events_ = 0;
  std::string error_;
};

} // namespace touchline::transport
