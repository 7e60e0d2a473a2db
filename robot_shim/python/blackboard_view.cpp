#include "touchline/python/blackboard_view.hpp"
#include "touchline/python/fast_fields.hpp"

#include <pybind11/stl.h>

#include <array>
#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>

namespace py = pybind11;

namespace touchline::python {

namespace {

using namespace api;

/// The parts of a Blackboard, in the order of its part getters and types.
enum Part : size_t { kMotion, kLocalisation, kVision, kGameController, kReceiver, kBehaviour, kParts };

/// Every view type's instance: what it views, what keeps that alive, and (a Blackboard's)
/// its parts, made on first read and kept.
struct View {
  PyObject_HEAD
  const void* data;                        ///< the viewed struct
  std::shared_ptr<const Blackboard> owned; ///< robot.Blackboard()'s own board; empty for a tick's view
  std::array<PyObject*, kParts> parts;     ///< a Blackboard's part views, or null
};

View* as_view(PyObject* self) { return reinterpret_cast<View*>(self); }

// The types of this interpreter's robot module; made again by a new interpreter's import.
// Raw pointers on purpose: nothing here may be released after the interpreter has gone.
PyTypeObject* g_blackboard_type = nullptr;
std::array<PyTypeObject*, kParts> g_part_types{};
constexpr int kEnumValues = 8;
std::array<PyObject*, kEnumValues> g_game_states{}; ///< robot.GameState by value, handed out as they are
std::array<PyObject*, kEnumValues> g_set_plays{};

/// A new view of `data` (kept alive by `owned`, if set) of `type`; null with a Python error.
PyObject* make_view(PyTypeObject* type, const void* data, const std::shared_ptr<const Blackboard>& owned) {
  PyObject* self = type->tp_alloc(type, 0); // zeroed; owns a reference to the (heap) type
  if (!self) return nullptr;
  View* view = as_view(self);
  view->data = data;
  new (&view->owned) std::shared_ptr<const Blackboard>(owned);
  view->parts.fill(nullptr);
  return self;
}

void view_dealloc(PyObject* self) {
  View* view = as_view(self);
  for (PyObject*& part : view->parts) Py_CLEAR(part);
  view->owned.~shared_ptr();
  PyTypeObject* type = Py_TYPE(self);
  type->tp_free(self);
  Py_DECREF(type);
}

/// robot.Blackboard(): an empty board of its own, for tests of behaviour code.
PyObject* blackboard_new(PyTypeObject* type, PyObject* args, PyObject* kwargs) {
  if (PyTuple_GET_SIZE(args) != 0 || (kwargs && PyDict_GET_SIZE(kwargs) != 0)) {
    PyErr_SetString(PyExc_TypeError, "robot.Blackboard() takes no arguments");
    return nullptr;
  }
  try {
    auto board = std::make_shared<const Blackboard>();
    return make_view(type, board.get(), board);
  } catch (const std::bad_alloc&) {
    return PyErr_NoMemory();
  }
}

// Field values as Python objects, as pybind11 made them before: numbers and bools as such,
// enums as robot.GameState/SetPlay, everything else through pybind11 as a fresh copy.
PyObject* to_python(bool v) { return PyBool_FromLong(v); }
PyObject* to_python(int v) { return PyLong_FromLong(v); }
PyObject* to_python(int64_t v) { return PyLong_FromLongLong(v); }
PyObject* to_python(float v) { return PyFloat_FromDouble(static_cast<double>(v)); }

template <typename Enum>
PyObject* enum_to_python(Enum v, const std::array<PyObject*, kEnumValues>& cache) {
  const int index = static_cast<int>(v);
  if (index >= 0 && index < kEnumValues && cache[static_cast<size_t>(index)]) {
    Py_INCREF(cache[static_cast<size_t>(index)]);
    return cache[static_cast<size_t>(index)];
  }
  return py::cast(v).release().ptr();
}
PyObject* to_python(GameState v) { return enum_to_python(v, g_game_states); }
PyObject* to_python(SetPlay v) { return enum_to_python(v, g_set_plays); }

template <typename T>
PyObject* to_python(const T& v) {
  if constexpr (std::is_class_v<T> && std::is_base_of_v<py::detail::type_caster_generic, py::detail::make_caster<T>>)
    return fast_fields::cast_out(v, py::return_value_policy::copy); // a pybind11 class: no lookup by type
  else
    return py::cast(v, py::return_value_policy::copy).release().ptr();
}

template <typename>
struct MemberOf;
template <typename Struct, typename Type>
struct MemberOf<Type Struct::*> {
  using Owner = Struct;
};

/// The getter of one field; the descriptor has checked that `self` is a view of Owner.
template <auto Member>
PyObject* get_field(PyObject* self, void*) {
  using Owner = typename MemberOf<decltype(Member)>::Owner;
  try {
    return to_python(static_cast<const Owner*>(as_view(self)->data)->*Member);
  } catch (py::error_already_set& e) {
    e.restore();
  } catch (const std::exception& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
  }
  return nullptr;
}

/// The getter of a Blackboard's part: its view, made on the first read.
template <Part part, auto Member>
PyObject* get_part(PyObject* self, void*) {
  View* view = as_view(self);
  PyObject*& cached = view->parts[part];
  if (!cached) {
    const auto& value = static_cast<const Blackboard*>(view->data)->*Member;
    cached = make_view(g_part_types[part], &value, view->owned);
    if (!cached) return nullptr;
  }
  Py_INCREF(cached);
  return cached;
}

/// receiver.messages: a new list at every read, as any field, of message copies made at the
/// first read and shared by the later ones (read-only objects: only `is` tells). The skills
/// read it several times a tick.
PyObject* get_messages(PyObject* self, void*) {
  PyObject*& cached = as_view(self)->parts[0]; // a receiver view has no parts of its own
  if (!cached && !(cached = get_field<&ReceiverBlackboard::messages>(self, nullptr))) return nullptr;
  return PyList_GetSlice(cached, 0, PY_SSIZE_T_MAX);
}

#define TL_FIELD(Struct, name, doc) {#name, &get_field<&Struct::name>, nullptr, doc, nullptr}
#define TL_PART(part, name) {#name, &get_part<part, &Blackboard::name>, nullptr, nullptr, nullptr}

PyGetSetDef g_motion_fields[] = {
    TL_FIELD(MotionBlackboard, odometry, "dead-reckoned body pose since the robot started (a copy)"),
    TL_FIELD(MotionBlackboard, active, "the body command being executed (a copy)"),
    TL_FIELD(MotionBlackboard, headYaw, "rad, measured"),
    TL_FIELD(MotionBlackboard, headPitch, "rad, measured"),
    TL_FIELD(MotionBlackboard, standing, "the walk is not stepping"),
    TL_FIELD(MotionBlackboard, kickPhase, "0 none, 1 prepare, 2 swing, 3 recover"),
    TL_FIELD(MotionBlackboard, fallen, "lying on the ground"),
    TL_FIELD(MotionBlackboard, ticks, "motion ticks run"),
    TL_FIELD(MotionBlackboard, sonarLeft, "nearest obstacle on the left, fraction of sonarRange_mm (1: none)"),
    TL_FIELD(MotionBlackboard, sonarRight, "nearest obstacle on the right, fraction of sonarRange_mm (1: none)"),
    TL_FIELD(MotionBlackboard, sonarRange_mm, "the sonars' range, mm"),
    TL_FIELD(MotionBlackboard, touchFrontLeft, "a robot touches the left foot bumper (0 to 45 deg left)"),
    TL_FIELD(MotionBlackboard, touchFrontRight, "a robot touches the right foot bumper (0 to 45 deg right)"),
    TL_FIELD(MotionBlackboard, touchLeft, "a robot touches the left arm (45 to 135 deg left)"),
    TL_FIELD(MotionBlackboard, touchRight, "a robot touches the right arm (45 to 135 deg right)"),
    TL_FIELD(MotionBlackboard, touchBack, "a robot touches the back (beyond 135 deg)"),
    {nullptr, nullptr, nullptr, nullptr, nullptr}};

PyGetSetDef g_localisation_fields[] = {
    TL_FIELD(LocalisationBlackboard, robotPos, "where the robot believes it is, field frame (a copy)"),
    TL_FIELD(LocalisationBlackboard, ballPos, "absolute ball estimate (a copy)"),
    TL_FIELD(LocalisationBlackboard, ballPosRR, "ball relative to the robot (a copy)"),
    TL_FIELD(LocalisationBlackboard, teamBallPos, "the team's shared ball estimate (a copy)"),
    TL_FIELD(LocalisationBlackboard, ballLostCount, "frames since the ball was last seen"),
    TL_FIELD(LocalisationBlackboard, robotPosCovariance,
             "row-major covariance of robotPos (x mm, y mm, theta rad), a list of 9 (a copy)"),
    {nullptr, nullptr, nullptr, nullptr, nullptr}};

PyGetSetDef g_vision_fields[] = {
    TL_FIELD(VisionBlackboard, ball, "the ball as seen, robot-relative (a copy)"),
    TL_FIELD(VisionBlackboard, ballSeen, "the ball was seen this frame"),
    TL_FIELD(VisionBlackboard, frame, "camera frame index"),
    TL_FIELD(VisionBlackboard, robots, "robots seen this frame, robot.SeenObject (copies)"),
    {nullptr, nullptr, nullptr, nullptr, nullptr}};

PyGetSetDef g_game_controller_fields[] = {
    TL_FIELD(GameControllerBlackboard, state, "robot.GameState"),
    TL_FIELD(GameControllerBlackboard, team, "our team index, 0 or 1"),
    TL_FIELD(GameControllerBlackboard, playerNumber, "1..7"),
    TL_FIELD(GameControllerBlackboard, penalised, nullptr),
    TL_FIELD(GameControllerBlackboard, score, "[team 0's, team 1's]"),
    TL_FIELD(GameControllerBlackboard, secsRemaining, nullptr),
    TL_FIELD(GameControllerBlackboard, firstHalf, "in the first half"),
    TL_FIELD(GameControllerBlackboard, kickOffTeam, "the team index (0 or 1) that kicks off"),
    TL_FIELD(GameControllerBlackboard, setPlay, "robot.SetPlay"),
    TL_FIELD(GameControllerBlackboard, setPlayTeam, "the team index taking the set play, -1: none"),
    TL_FIELD(GameControllerBlackboard, dropInTeam, "the team index whose touch put the last ball out, -1: not known"),
    TL_FIELD(GameControllerBlackboard, dropInTime, "whole seconds since that ball was put back, -1: none yet"),
    {nullptr, nullptr, nullptr, nullptr, nullptr}};

PyGetSetDef g_receiver_fields[] = {
    {"messages", &get_messages, nullptr, "each teammate's latest robot.TeamMessage, by player number (copies)", nullptr},
    {nullptr, nullptr, nullptr, nullptr, nullptr}};

PyGetSetDef g_behaviour_fields[] = {
    TL_FIELD(BehaviourBlackboard, request, "the request the behaviour returned last (a copy)"),
    TL_FIELD(BehaviourBlackboard, skill, "name of the running behaviour"),
    {nullptr, nullptr, nullptr, nullptr, nullptr}};

PyGetSetDef g_blackboard_fields[] = {
    TL_FIELD(Blackboard, utime, "simulated time of this perception frame, us"),
    TL_PART(kMotion, motion),
    TL_PART(kLocalisation, localisation),
    TL_PART(kVision, vision),
    TL_PART(kGameController, gameController),
    TL_PART(kReceiver, receiver),
    TL_PART(kBehaviour, behaviour),
    {nullptr, nullptr, nullptr, nullptr, nullptr}};

#undef TL_FIELD
#undef TL_PART

#ifdef Py_TPFLAGS_DISALLOW_INSTANTIATION
constexpr unsigned long kPartFlags = Py_TPFLAGS_DEFAULT | Py_TPFLAGS_DISALLOW_INSTANTIATION;
#else
constexpr unsigned long kPartFlags = Py_TPFLAGS_DEFAULT;
#endif

/// A view type named `qualified` ("robot.Name", a literal: the type keeps pointing at it),
/// added to `m` as Name.
PyTypeObject* define_view_type(py::module_& m, const char* qualified, const char* doc, PyGetSetDef* fields,
                               newfunc new_function) {
  std::array<PyType_Slot, 5> slots{{{Py_tp_dealloc, reinterpret_cast<void*>(&view_dealloc)},
                                    {Py_tp_getset, fields},
                                    {Py_tp_doc, const_cast<char*>(doc)},
                                    {0, nullptr},
                                    {0, nullptr}}};
  if (new_function) slots[3] = {Py_tp_new, reinterpret_cast<void*>(new_function)};
  PyType_Spec spec{qualified, static_cast<int>(sizeof(View)), 0,
                   static_cast<unsigned int>(new_function ? Py_TPFLAGS_DEFAULT : kPartFlags), slots.data()};
  PyObject* type = PyType_FromSpec(&spec);
  if (!type) throw py::error_already_set();
  m.add_object(std::strchr(qualified, '.') + 1, type); // the module holds the type; so does every view
  return reinterpret_cast<PyTypeObject*>(type);
}

} // namespace

void define_blackboard_views(py::module_& m) {
  for (int i = 0; i < kEnumValues; ++i) {
    g_game_states[static_cast<size_t>(i)] =
        i <= static_cast<int>(GameState::STANDBY) ? py::cast(static_cast<GameState>(i)).release().ptr() : nullptr;
    g_set_plays[static_cast<size_t>(i)] =
        i <= static_cast<int>(SetPlay::PENALTY_KICK) ? py::cast(static_cast<SetPlay>(i)).release().ptr() : nullptr;
  }
  g_part_types[kMotion] = define_view_type(m, "robot.MotionBlackboard", "what the motion adapter wrote, read-only",
                                           g_motion_fields, nullptr);
  g_part_types[kLocalisation] = define_view_type(m, "robot.LocalisationBlackboard", "where the robot and the ball are, read-only",
                                                 g_localisation_fields, nullptr);
  g_part_types[kVision] = define_view_type(m, "robot.VisionBlackboard", "what the camera saw, read-only", g_vision_fields, nullptr);
  g_part_types[kGameController] = define_view_type(m, "robot.GameControllerBlackboard", "the game, read-only",
                                                   g_game_controller_fields, nullptr);
  g_part_types[kReceiver] = define_view_type(m, "robot.ReceiverBlackboard", "teammates' messages, read-only",
                                             g_receiver_fields, nullptr);
  g_part_types[kBehaviour] = define_view_type(m, "robot.BehaviourBlackboard", "the last request, read-only",
                                              g_behaviour_fields, nullptr);
  g_blackboard_type = define_view_type(m, "robot.Blackboard", "the robot's Blackboard, read-only", g_blackboard_fields,
                                       &blackboard_new);
}

py::object blackboard_view(const Blackboard& blackboard) {
  if (!g_blackboard_type) throw std::logic_error("blackboard_view before the robot module was imported");
  PyObject* view = make_view(g_blackboard_type, &blackboard, nullptr);
  if (!view) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(view);
}

} // namespace touchline::python
