#include "touchline/python/robot_module.hpp"

#include "touchline/python/blackboard_view.hpp"
#include "touchline/python/fast_fields.hpp"

#include <pybind11/stl.h>

#include "touchline/robot_api/blackboard.hpp"
#include "touchline/robot_api/data.hpp"

namespace py = pybind11;

namespace touchline::python {

namespace {

using namespace api;
namespace AC = api::ActionCommand;

/// toRobotRelative(robot, x, y) with an AbsCoord and two floats or ints, as pybind11 would
/// compute it but without its dispatch (called for every obstacle every tick); any other
/// call goes to pybind11's function, `fallback`, for its conversions and errors.
PyObject* to_robot_relative(PyObject* fallback, PyObject* const* args, Py_ssize_t nargs, PyObject* kwnames) {
  auto number = [](PyObject* v) { return PyFloat_CheckExact(v) || PyLong_CheckExact(v); };
  const auto* abs_type = fast_fields::type_record<AbsCoord>();
  if (nargs == 3 && !kwnames && abs_type && Py_TYPE(args[0]) == abs_type->type && number(args[1]) &&
      number(args[2])) {
    const AbsCoord* robot = fast_fields::held<AbsCoord>(args[0]);
    if (!robot) return nullptr;
    const double x = PyFloat_AsDouble(args[1]), y = PyFloat_AsDouble(args[2]);
    if (!PyErr_Occurred())
      return fast_fields::cast_out(toRobotRelative(*robot, static_cast<float>(x), static_cast<float>(y)),
                                   py::return_value_policy::move);
    PyErr_Clear(); // an int beyond a double: pybind11's error
  }
  return PyObject_Vectorcall(fallback, args, static_cast<size_t>(nargs), kwnames);
}

void define_geometry(py::module_& m) {
  namespace ff = fast_fields;
  py::class_<AbsCoord> abs(m, "AbsCoord", "A field or odometry pose: x, y (mm), theta (rad)");
  abs.def(py::init<>())
      .def(py::init([](float x, float y, float theta) { return AbsCoord{x, y, theta}; }), py::arg("x"),
           py::arg("y"), py::arg("theta") = 0.f)
      .def("__repr__", [](const AbsCoord& c) {
        return "AbsCoord(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.theta) + ")";
      });
  ff::remember_type<AbsCoord>();
  ff::readwrite<&AbsCoord::x>(abs, "x");
  ff::readwrite<&AbsCoord::y>(abs, "y");
  ff::readwrite<&AbsCoord::theta>(abs, "theta");
  py::class_<RRCoord> rr(m, "RRCoord", "Robot-relative position: distance (mm), heading (rad, + left)");
  rr.def(py::init<>())
      .def(py::init([](float distance, float heading) { return RRCoord{distance, heading}; }),
           py::arg("distance"), py::arg("heading"));
  ff::remember_type<RRCoord>();
  ff::readwrite<&RRCoord::distance>(rr, "distance");
  ff::readwrite<&RRCoord::heading>(rr, "heading");
  ff::getter_method<&RRCoord::x>(rr, "x", "forward component, mm");
  ff::getter_method<&RRCoord::y>(rr, "y", "left component, mm");
  m.def("normaliseTheta", &normaliseTheta, "wraps an angle into [-pi, pi)");
  m.def("toRobotRelative", &toRobotRelative, py::arg("robot"), py::arg("x"), py::arg("y"),
        "robot-relative coordinates of the field point (x, y) seen from `robot`");
  static PyMethodDef fast{"toRobotRelative", reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&to_robot_relative)),
                          METH_FASTCALL | METH_KEYWORDS,
                          "toRobotRelative(robot, x, y): robot-relative coordinates of the field point (x, y) seen "
                          "from `robot` (robot.AbsCoord)"};
  PyObject* function = PyCFunction_NewEx(&fast, m.attr("toRobotRelative").ptr(), m.attr("__name__").ptr());
  if (!function) throw py::error_already_set();
  m.attr("toRobotRelative") = py::reinterpret_steal<py::object>(function);
}

void define_data(py::module_& m) {
  m.def("data_path", &data_path, py::arg("name"),
        "the path of `name` (e.g. 'policies/go_to_pose.policy') in the robot's data directory; an absolute name as is");
  m.def("data_dir", &data_dir, "the robot's data directory (robot_shim --data-dir)");
  m.def("set_data_dir", &set_data_dir, py::arg("directory"),
        "sets the robot's data directory (for tests and tools; robot_shim sets it from --data-dir)");
}

void define_action_command(py::module_& m) {
  py::enum_<AC::ActionType> action_type(m, "ActionType");
  action_type.value("NONE", AC::ActionType::NONE)
      .value("STAND", AC::ActionType::STAND)
      .value("WALK", AC::ActionType::WALK)
      .value("DRIBBLE", AC::ActionType::DRIBBLE)
      .value("KICK", AC::ActionType::KICK)
      .value("GETUP_FRONT", AC::ActionType::GETUP_FRONT)
      .value("GETUP_BACK", AC::ActionType::GETUP_BACK)
      .value("DEAD", AC::ActionType::DEAD)
      .value("GOALIE_DIVE_LEFT", AC::ActionType::GOALIE_DIVE_LEFT)
      .value("GOALIE_DIVE_RIGHT", AC::ActionType::GOALIE_DIVE_RIGHT);
  py::enum_<AC::Foot> foot(m, "Foot");
  foot.value("LEFT", AC::Foot::LEFT).value("RIGHT", AC::Foot::RIGHT);
  fast_fields::fast_compare(action_type); // == and != without pybind11's dispatch
  fast_fields::fast_compare(foot);

  // The fields as plain getset descriptors (fast_fields.hpp): a request is built field by
  // field every tick.
  namespace ff = fast_fields;
  py::class_<AC::Head> head(m, "Head", "head request: yaw, pitch (rad), isRelative, yawSpeed, pitchSpeed (0..1]");
  head.def(py::init<>());
  ff::fast_default_init<AC::Head>(head);
  ff::readwrite<&AC::Head::yaw>(head, "yaw");
  ff::readwrite<&AC::Head::pitch>(head, "pitch");
  ff::readwrite<&AC::Head::isRelative>(head, "isRelative");
  ff::readwrite<&AC::Head::yawSpeed>(head, "yawSpeed");
  ff::readwrite<&AC::Head::pitchSpeed>(head, "pitchSpeed");
  py::class_<AC::Body> body(m, "Body", "body request: actionType, forward, left (mm/s), turn (rad/s), power, bend, speed, foot");
  body.def(py::init<>());
  ff::fast_default_init<AC::Body>(body);
  ff::readwrite<&AC::Body::actionType>(body, "actionType");
  ff::readwrite<&AC::Body::forward>(body, "forward");
  ff::readwrite<&AC::Body::left>(body, "left");
  ff::readwrite<&AC::Body::turn>(body, "turn");
  ff::readwrite<&AC::Body::power>(body, "power");
  ff::readwrite<&AC::Body::bend>(body, "bend");
  ff::readwrite<&AC::Body::speed>(body, "speed");
  ff::readwrite<&AC::Body::foot>(body, "foot");
  py::class_<AC::LED> leds(m, "LED", "LED request: chest (0xRRGGBB)");
  leds.def(py::init<>());
  ff::fast_default_init<AC::LED>(leds);
  ff::readwrite<&AC::LED::chest>(leds, "chest");
  py::class_<AC::All> request(m, "All", "a whole request: head, body, leds, sonar");
  request.def(py::init<>());
  ff::fast_default_init<AC::All>(request);
  ff::readwrite<&AC::All::head>(request, "head");
  ff::readwrite<&AC::All::body>(request, "body");
  ff::readwrite<&AC::All::leds>(request, "leds");
  ff::readwrite<&AC::All::sonar>(request, "sonar");
  request.def_property(
      "teamMessage",
      [](const AC::All& all) {
        return py::bytes(reinterpret_cast<const char*>(all.teamMessage.data()), all.teamMessage.size());
      },
      [](AC::All& all, const py::bytes& data) {
        const std::string bytes = data;
        all.teamMessage.assign(bytes.begin(), bytes.end());
      },
      "bytes to send to the teammates this frame (b'': none)");
}

void define_blackboard(py::module_& m) {
  py::enum_<GameState> game_state(m, "GameState");
  game_state.value("INITIAL", GameState::INITIAL)
      .value("READY", GameState::READY)
      .value("SET", GameState::SET)
      .value("PLAYING", GameState::PLAYING)
      .value("FINISHED", GameState::FINISHED)
      .value("STANDBY", GameState::STANDBY);
  py::enum_<SetPlay> set_play(m, "SetPlay");
  set_play.value("NONE", SetPlay::NONE)
      .value("GOAL_KICK", SetPlay::GOAL_KICK)
      .value("PUSHING_FREE_KICK", SetPlay::PUSHING_FREE_KICK)
      .value("CORNER_KICK", SetPlay::CORNER_KICK)
      .value("KICK_IN", SetPlay::KICK_IN)
      .value("PENALTY_KICK", SetPlay::PENALTY_KICK);
  fast_fields::fast_compare(game_state); // compared every tick
  fast_fields::fast_compare(set_play);

  py::class_<TeamMessage> message(m, "TeamMessage");
  fast_fields::remember_type<TeamMessage>();
  fast_fields::readonly<&TeamMessage::playerNumber>(message, "playerNumber");
  fast_fields::readonly<&TeamMessage::utime>(message, "utime");
  fast_fields::readonly<&TeamMessage::data>(message, "data", "the message's bytes (a copy)");
  py::class_<SeenObject> seen(m, "SeenObject", "a goal post or robot the camera saw this frame");
  fast_fields::remember_type<SeenObject>();
  fast_fields::readonly<&SeenObject::rr>(seen, "rr", "where, robot-relative (robot.RRCoord)");
  fast_fields::readonly<&SeenObject::id>(seen, "id", "posts: 0..3; robots: the player number");
  fast_fields::readonly<&SeenObject::teammate>(seen, "teammate", "robots: one of ours");
  // The Blackboard and its parts: read-only views of their own (blackboard_view.hpp).
  define_blackboard_views(m);
}

} // namespace

void define_robot_module(py::module_& m) {
  m.doc() = "The robot API for behaviour code: Blackboard (read-only), ActionCommand types, constants. mm, rad.";
  define_geometry(m);
  define_data(m);
  define_action_command(m);
  define_blackboard(m);
}

} // namespace touchline::python
