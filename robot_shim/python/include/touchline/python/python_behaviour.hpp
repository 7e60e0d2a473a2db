#pragma once
// PythonBehaviour: the Python behaviour as a robot API Behaviour. It imports MODULE from
// a directory put first on sys.path and calls MODULE.tick(blackboard) once per frame with
// the const Blackboard (read-only views from the embedded `robot` module), expecting a
// robot.All back.
//
// Hot reload: at most every `reload_check_interval_us` of WALL time (adapter code; the
// behaviour itself sees simulated time only) the .py files under the directory are
// compared (which files; mtime, ctime, size) with the last look; on a change every module
// loaded from the directory is dropped from sys.modules and MODULE is imported afresh.
// No bytecode is written (sys.dont_write_bytecode): a .pyc's whole-second freshness check
// could otherwise serve stale code after two quick edits.
//
// Errors never reach the caller after construction: an exception at import or in tick(),
// a syntax error, or a tick() that returns something other than robot.All makes tick()
// return error_request() (STAND, chest LED kErrorChestLed) and logs the traceback once
// per change of the files. The behaviour keeps being ticked, so it recovers as soon as
// tick() succeeds again or the files are fixed ("reloaded" is logged).
//
// Hung code: tick() (with the look at the files and a reload's import) and the first
// import are guarded by a TickGuard (tick_guard.hpp). Python that runs longer than
// `tick_timeout_us` of wall time is interrupted (touchline.TickTimeout raised in it, its
// traceback logged once); a tick() that timed out is not called again until the files
// change (a hung tick would otherwise cost that much wall time every frame), and the
// robot stands meanwhile as for any error. After python::request_stop() (robot_shim's
// SIGTERM/SIGINT) no Python runs any more: running code is interrupted, and tick()
// returns error_request() at once.
//
// Profiles: what tick() is called with, which `robot` module the code imports and how the
// result becomes a request are the profile's (python_profile.hpp): Touchline's own by
// default, rUNSWift's for their framework. Everything above is shared by all profiles.
//
// Needs a running interpreter (pybind11::scoped_interpreter: robot_shim holds one for
// the process) and runs on that interpreter's thread. Several PythonBehaviours may live
// in one process: each keeps its own modules and robot.params/team/player, swapped into
// sys.modules and `robot` before it runs.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "touchline/robot_api/behaviour.hpp"

namespace pybind11 {
class error_already_set;
}

namespace touchline::python {

class PythonProfile;

/// Chest LED of a robot whose Python behaviour failed, constant until it recovers:
/// magenta, a colour no behaviour uses (behaviour_py shows red while the ball is lost).
constexpr int32_t kErrorChestLed = 0xff00ff;

/// What a failed Python behaviour asks for: stand still, head centred, chest kErrorChestLed.
api::ActionCommand::All error_request();

/// A wrong module, directory or missing tick() at construction; one line for the user.
struct PythonBehaviourError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct PythonBehaviourDef {
  std::filesystem::path directory;   ///< put first on sys.path; its .py files are watched
  std::string module = "behaviour";  ///< imported from `directory`; must define tick(blackboard)
  std::map<std::string, std::string> params; ///< robot.params (strings, as --param gives them)
  int team = 0;                      ///< robot.team
  int player = 1;                    ///< robot.player
  std::string name = "robot";        ///< prefixes every log line (robot_shim uses "robot_shim T/P")
  std::ostream* log = nullptr;       ///< errors and reloads; nullptr: std::cerr
  int64_t reload_check_interval_us = 250000; ///< wall time between looks at the files; 0: every tick
  std::function<int64_t()> wall_clock_us;    ///< steady wall clock, microseconds; empty: std::chrono::steady_clock
  /// Wall time Python may run within one tick() (or the first import) before it is
  /// interrupted; 0: never (the default: wall time must not decide what a replay or a test
  /// computes). robot_shim sets it (--tick-timeout-ms) to catch code that hangs.
  int64_t tick_timeout_us = 0;
  /// The framework the module is written for (python_profile.hpp); null: Touchline's own.
  std::shared_ptr<PythonProfile> profile;
};

class PythonBehaviour : public api::Behaviour {
 public:
  /// Imports the module. Throws PythonBehaviourError when no interpreter runs, the
  /// directory or the module does not exist, the module has no callable tick(), or its
  /// optional check_params(params) raises (the exception's first line is the error). An
  /// exception while importing (a syntax error, say) is not thrown: the behaviour starts
  /// in the error state and recovers when the files are fixed.
  explicit PythonBehaviour(PythonBehaviourDef def);
  ~PythonBehaviour() override;
  PythonBehaviour(const PythonBehaviour&) = delete;
  PythonBehaviour& operator=(const PythonBehaviour&) = delete;

  api::ActionCommand::All tick(const api::Blackboard& blackboard) override;

  /// Whether the last tick (or, before any tick, the import) succeeded.
  bool healthy() const { return healthy_; }
  /// Successful imports so far: 1 after a clean start, +1 per successful reload.
  int64_t loads() const { return loads_; }
  const std::filesystem::path& directory() const { return def_.directory; }

 private:
  struct Python; // the interpreter objects this behaviour holds (pybind11 kept out of the header)
  /// What tells an edited file: a change of any of these.
  struct FileStamp {
    int64_t mtime_ns = 0, ctime_ns = 0;
    uintmax_t size = 0;
    bool operator==(const FileStamp& other) const;
  };
  using Files = std::map<std::string, FileStamp>; ///< .py path -> stamp
  static Files scan_python_files(const std::filesystem::path& directory);

  /// Puts this behaviour's modules in sys.modules, its directory first on sys.path and
  /// its params/team/player in `robot` (a no-op when it ran last).
  void activate();
  /// Takes this behaviour's modules out of sys.modules, kept for the next activate().
  void stash();
  /// Takes this behaviour's modules and directory out of the interpreter for good.
  void leave();
  int64_t now_us() const;
  void check_files();
  /// Whether the module's file is in the directory.
  bool module_present() const;
  /// (Re)imports the module. Returns false and reports when it raised or (unless
  /// `starting`, when the constructor throws instead) lacks tick().
  bool load(bool starting);
  /// Calls the module's check_params(robot.params), if it has one; throws
  /// PythonBehaviourError with its exception's first line when it raises.
  void check_params();
  /// Logs `what` (and the traceback of `error`) unless an error was logged since the
  /// files last changed.
  void report_once(const std::string& what, const pybind11::error_already_set* error);
  void log_lines(const std::string& text);

  PythonBehaviourDef def_;
  std::string prefix_; ///< the directory, canonical, with a trailing '/'
  std::unique_ptr<Python> py_;
  Files files_;
  int64_t next_check_us_ = 0;
  bool healthy_ = false;
  bool reported_ = false; ///< an error was logged since the files last changed
  bool timed_out_ = false; ///< tick() ran past tick_timeout_us: not called again until the files change
  int64_t loads_ = 0;
};

} // namespace touchline::python
