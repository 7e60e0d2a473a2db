#pragma once
// PythonProfile: what one framework's Python behaviour needs from the runtime beyond
// "import MODULE, call tick() each frame". PythonBehaviour keeps the machinery every
// framework shares (hot reload, the tick timeout, errors -> stand with the chest LED
// magenta, one report per change); a profile says which `robot` module the code imports,
// what tick() is called with and how its result becomes an ActionCommand.
//
// Touchline's own profile (the default): `robot` is the robot API module, tick() gets the
// const Blackboard, returns a robot.All. rUNSWift's (runswift/profile.hpp): their `robot`
// module, their Blackboard built from ours, their BehaviourRequest converted back.
#include <memory>
#include <stdexcept>
#include <string>

#include <pybind11/pybind11.h>

#include "touchline/robot_api/action_command.hpp"
#include "touchline/robot_api/blackboard.hpp"

namespace touchline::python {

/// What tick() returned cannot be used: what() is one line naming the type or the field.
struct RequestError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class PythonProfile {
 public:
  virtual ~PythonProfile() = default;

  /// Once, before the behaviour's module is first looked for (GIL held): environment
  /// variables the framework reads, its own modules. `directory` is the behaviour's folder.
  virtual void prepare(const std::string& directory) { (void)directory; }
  /// The module the behaviour's code gets for `import robot` (put in sys.modules while
  /// this behaviour runs; robot.params, robot.team and robot.player are set on it).
  virtual pybind11::module_ robot_module() = 0;
  /// Whether a missing MODULE is an error at start (robot_shim exits 2). false: the robot
  /// stands, one line says which file is missing, and the file is loaded when it appears.
  virtual bool module_required() const { return true; }
  /// What tick() is called with this frame.
  virtual pybind11::object argument(const api::Blackboard& blackboard) = 0;
  /// The request tick()'s `result` asks for. Throws RequestError (or a Python error).
  virtual api::ActionCommand::All request(pybind11::handle result, const api::Blackboard& blackboard) = 0;
  /// Called when tick() failed (the robot stands): e.g. to forget a half-done action.
  virtual void on_error() {}
};

/// Touchline's own profile: the robot API module, the Blackboard as it is, robot.All.
std::shared_ptr<PythonProfile> touchline_profile();

} // namespace touchline::python
