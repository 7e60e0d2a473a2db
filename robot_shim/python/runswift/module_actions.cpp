// What a behaviour returns: BehaviourRequest, All, BodyCommand, HeadCommand, LEDCommand,
// rgb, the shared data and debug info, and the ActionType, Foot and StiffenCommand enums.
#include <pybind11/stl.h>

#include "touchline/python/runswift/module.hpp"
#include "touchline/python/runswift/types.hpp"

namespace py = pybind11;

namespace touchline::python::runswift {

void define_actions(py::module_& m) {
  std::vector<std::pair<const char*, int>> types;
  for (int t = NONE; t <= NUM_ACTION_TYPES; ++t)
    if (t != GOALIE_FAST_SIT) types.emplace_back(action_type_name(t), t); // their module leaves it out
  int_enum(m, "ActionType", types);
  int_enum(m, "Foot", {{"LEFT", FOOT_LEFT}, {"RIGHT", FOOT_RIGHT}});
  int_enum(m, "StiffenCommand", {{"NONE", STIFFEN_NONE}, {"STIFFEN", STIFFEN_STIFFEN}});

  py::class_<BodyCommand>(m, "BodyCommand", "body request: walk (mm/s, rad/s), kick, or a special action")
      .def(py::init<>())
      .def(py::init([](int actionType, int forward, int left, float turn, float power, float bend, float speed, int foot,
                       bool useShuffle, bool leftArmBehind, bool rightArmBehind, bool blocking, bool extraStableKick) {
        return BodyCommand{actionType, forward, left, turn, power, bend, speed, foot, useShuffle, leftArmBehind,
                           rightArmBehind, blocking, extraStableKick};
      }))
      .def_readwrite("actionType", &BodyCommand::actionType)
      .def_readwrite("forward", &BodyCommand::forward)
      .def_readwrite("left", &BodyCommand::left)
      .def_readwrite("turn", &BodyCommand::turn)
      .def_readwrite("power", &BodyCommand::power)
      .def_readwrite("bend", &BodyCommand::bend)
      .def_readwrite("speed", &BodyCommand::speed)
      .def_readwrite("foot", &BodyCommand::foot)
      .def_readwrite("useShuffle", &BodyCommand::useShuffle)
      .def_readwrite("leftArmBehind", &BodyCommand::leftArmBehind)
      .def_readwrite("rightArmBehind", &BodyCommand::rightArmBehind)
      .def_readwrite("blocking", &BodyCommand::blocking)
      .def_readwrite("extraStableKick", &BodyCommand::extraStableKick);

  py::class_<HeadCommand>(m, "HeadCommand", "head request: yaw (+ left), pitch (+ down) rad, isRelative, speeds [0, 1]")
      .def(py::init<>())
      .def(py::init([](float yaw, float pitch, bool isRelative, float yawSpeed, float pitchSpeed) {
             return HeadCommand{yaw, pitch, isRelative, yawSpeed, pitchSpeed};
           }),
           py::arg("yaw"), py::arg("pitch") = 0.f, py::arg("isRelative") = true, py::arg("yawSpeed") = 1.f,
           py::arg("pitchSpeed") = 1.f)
      .def_readwrite("yaw", &HeadCommand::yaw)
      .def_readwrite("pitch", &HeadCommand::pitch)
      .def_readwrite("isRelative", &HeadCommand::isRelative)
      .def_readwrite("yawSpeed", &HeadCommand::yawSpeed)
      .def_readwrite("pitchSpeed", &HeadCommand::pitchSpeed);

  py::class_<Rgb>(m, "rgb", "an LED colour: red, green, blue on or off")
      .def(py::init([](bool r, bool g, bool b) { return Rgb{r, g, b}; }), py::arg("red") = false,
           py::arg("green") = false, py::arg("blue") = false)
      .def_readwrite("red", &Rgb::red)
      .def_readwrite("green", &Rgb::green)
      .def_readwrite("blue", &Rgb::blue);

  py::class_<LedCommand>(m, "LEDCommand", "LED request: eyes, chest button, feet (rgb), ears (10-bit segments)")
      .def(py::init<>())
      .def(py::init([](Rgb leftEye, Rgb rightEye, Rgb chest, Rgb leftFoot, Rgb rightFoot) {
        LedCommand led;
        led.leftEye = leftEye;
        led.rightEye = rightEye;
        led.chestButton = chest;
        led.leftFoot = leftFoot;
        led.rightFoot = rightFoot;
        return led;
      }))
      .def_readwrite("leftEar", &LedCommand::leftEar)
      .def_readwrite("rightEar", &LedCommand::rightEar)
      .def_readwrite("leftEye", &LedCommand::leftEye)
      .def_readwrite("rightEye", &LedCommand::rightEye)
      .def_readwrite("chestButton", &LedCommand::chestButton)
      .def_readwrite("leftFoot", &LedCommand::leftFoot)
      .def_readwrite("rightFoot", &LedCommand::rightFoot);

  py::class_<AllCommand>(m, "All", "a whole request: head, body, leds, stiffen")
      .def(py::init<>())
      .def(py::init([](HeadCommand head, BodyCommand body, LedCommand leds, float, int stiffen) {
        return AllCommand{head, body, leds, stiffen};
      }))
      .def_readwrite("head", &AllCommand::head)
      .def_readwrite("body", &AllCommand::body)
      .def_readwrite("leds", &AllCommand::leds)
      .def_readwrite("stiffen", &AllCommand::stiffen);

  py::class_<BehaviourSharedData>(m, "BehaviourSharedData", "what a robot tells its teammates about its play")
      .def(py::init<>())
      .def_readwrite("secondsSinceLastKick", &BehaviourSharedData::secondsSinceLastKick)
      .def_readwrite("role", &BehaviourSharedData::role)
      .def_readwrite("playingBall", &BehaviourSharedData::playingBall)
      .def_readwrite("needAssistance", &BehaviourSharedData::needAssistance)
      .def_readwrite("isAssisting", &BehaviourSharedData::isAssisting)
      .def_readwrite("isKickedOff", &BehaviourSharedData::isKickedOff)
      .def_readwrite("walkingToX", &BehaviourSharedData::walkingToX)
      .def_readwrite("walkingToY", &BehaviourSharedData::walkingToY)
      .def_readwrite("walkingToH", &BehaviourSharedData::walkingToH)
      .def_readwrite("kickNotification", &BehaviourSharedData::kickNotification);

  py::class_<BehaviourDebugInfo>(m, "BehaviourDebugInfo")
      .def(py::init<>())
      .def_readwrite("bodyBehaviourHierarchy", &BehaviourDebugInfo::bodyBehaviourHierarchy)
      .def_readwrite("headBehaviourHierarchy", &BehaviourDebugInfo::headBehaviourHierarchy)
      .def_readwrite("haveBallManoeuvreTarget", &BehaviourDebugInfo::haveBallManoeuvreTarget)
      .def_readwrite("ballManoeuvreTargetX", &BehaviourDebugInfo::ballManoeuvreTargetX)
      .def_readwrite("ballManoeuvreTargetY", &BehaviourDebugInfo::ballManoeuvreTargetY)
      .def_readwrite("ballManoeuvreHeadingError", &BehaviourDebugInfo::ballManoeuvreHeadingError)
      .def_readwrite("ballManoeuvreType", &BehaviourDebugInfo::ballManoeuvreType)
      .def_readwrite("ballManoeuvreHard", &BehaviourDebugInfo::ballManoeuvreHard)
      .def_readwrite("anticipating", &BehaviourDebugInfo::anticipating)
      .def_readwrite("anticipateX", &BehaviourDebugInfo::anticipateX)
      .def_readwrite("anticipateY", &BehaviourDebugInfo::anticipateY)
      .def_readwrite("anticipateH", &BehaviourDebugInfo::anticipateH);

  py::class_<BehaviourRequest>(m, "BehaviourRequest", "what tick(blackboard) returns")
      .def(py::init<>())
      .def_readwrite("actions", &BehaviourRequest::actions)
      .def_readwrite("behaviourSharedData", &BehaviourRequest::behaviourSharedData)
      .def_readwrite("behaviourDebugInfo", &BehaviourRequest::behaviourDebugInfo);
}

} // namespace touchline::python::runswift
