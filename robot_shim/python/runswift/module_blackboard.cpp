// The Blackboard their tick() reads, with its sub-blackboards and the perception, team and
// GameController values in it. Read-only: attributes hand out views or copies (lists for
// arrays), so behaviour code cannot write the robot's state, as on the robot.
#include <pybind11/stl.h>

#include "touchline/python/runswift/module.hpp"
#include "touchline/python/runswift/types.hpp"

namespace py = pybind11;

namespace touchline::python::runswift {

namespace {

py::tuple point(const std::array<int, 2>& p) { return py::make_tuple(p[0], p[1]); }

void define_perception(py::module_& m) {
  int_enum(m, "RobotVisionInfoType", {{"rUnknown", rUnknown}, {"rBlue", rBlue}, {"rRed", rRed}});
  int_enum(m, "PostType", {{"pNone", pNone}, {"pLeft", pLeft}, {"pRight", pRight}, {"pHome", pHome}, {"pAway", pAway},
                           {"pHomeLeft", pHomeLeft}, {"pHomeRight", pHomeRight}, {"pAwayLeft", pAwayLeft},
                           {"pAwayRight", pAwayRight}});
  py::class_<BallInfo>(m, "BallInfo")
      .def(py::init<>())
      .def_readonly("rr", &BallInfo::rr)
      .def_readonly("radius", &BallInfo::radius)
      .def_property_readonly("imageCoords", [](const BallInfo& b) { return point(b.imageCoords); })
      .def_readonly("topCamera", &BallInfo::topCamera);
  py::class_<RobotVisionInfo>(m, "RobotVisionInfo")
      .def(py::init<>())
      .def_readonly("rr", &RobotVisionInfo::rr)
      .def_readonly("type", &RobotVisionInfo::type);
  py::class_<PostInfo>(m, "PostInfo")
      .def(py::init<>())
      .def_readonly("rr", &PostInfo::rr)
      .def_readonly("type", &PostInfo::type)
      .def_property_readonly("imageCoords", [](const PostInfo& p) { return point(p.imageCoords); });
  py::class_<RobotObstacle>(m, "RobotObstacle")
      .def(py::init<>())
      .def_readonly("rr", &RobotObstacle::rr)
      .def_readonly("type", &RobotObstacle::type)
      .def_readonly("rrc", &RobotObstacle::rrc)
      .def_readonly("pos", &RobotObstacle::pos)
      .def_readonly("tangentHeadingLeft", &RobotObstacle::tangentHeadingLeft)
      .def_readonly("tangentHeadingRight", &RobotObstacle::tangentHeadingRight)
      .def_readonly("evadeVectorLeft", &RobotObstacle::evadeVectorLeft)
      .def_readonly("evadeVectorRight", &RobotObstacle::evadeVectorRight);
}

void define_team(py::module_& m) {
  py::class_<SharedStateEstimationBundle>(m, "SharedStateEstimationBundle")
      .def(py::init<>())
      .def_readonly("robotPos", &SharedStateEstimationBundle::robotPos)
      .def_readonly("ballPosRRC", &SharedStateEstimationBundle::ballPosRRC)
      .def_readonly("ballVelRRC", &SharedStateEstimationBundle::ballVelRRC)
      .def_readonly("haveBallUpdate", &SharedStateEstimationBundle::haveBallUpdate);
  py::class_<BroadcastData>(m, "BroadcastData", "what a teammate last broadcast")
      .def(py::init<>())
      .def_readonly("playerNum", &BroadcastData::playerNum)
      .def_readonly("robotPos", &BroadcastData::robotPos)
      .def_readonly("ballPosAbs", &BroadcastData::ballPosAbs)
      .def_readonly("ballPosRR", &BroadcastData::ballPosRR)
      .def_readonly("sharedStateEstimationBundle", &BroadcastData::sharedStateEstimationBundle)
      .def_readonly("behaviourSharedData", &BroadcastData::behaviourSharedData)
      .def_readonly("acB", &BroadcastData::acB)
      .def_readonly("uptime", &BroadcastData::uptime)
      .def_readonly("gameState", &BroadcastData::gameState);
  py::class_<SplStandardMessage>(m, "SPLStandardMessage")
      .def(py::init<>())
      .def_readonly("playerNum", &SplStandardMessage::playerNum)
      .def_readonly("fallen", &SplStandardMessage::fallen)
      .def_readonly("pose", &SplStandardMessage::pose)
      .def_readonly("ballAge", &SplStandardMessage::ballAge)
      .def_readonly("ball", &SplStandardMessage::ball);
}

void define_game_controller(py::module_& m) {
  py::class_<RobotInfo>(m, "RobotInfo")
      .def(py::init<>())
      .def_readonly("penalty", &RobotInfo::penalty)
      .def_readonly("secsTillUnpenalised", &RobotInfo::secsTillUnpenalised);
  py::class_<TeamInfo>(m, "TeamInfo")
      .def(py::init<>())
      .def_readonly("teamNumber", &TeamInfo::teamNumber)
      .def_readonly("teamColour", &TeamInfo::teamColour)
      .def_readonly("score", &TeamInfo::score)
      .def_readonly("penaltyShot", &TeamInfo::penaltyShot)
      .def_readonly("singleShots", &TeamInfo::singleShots)
      .def_readonly("messageBudget", &TeamInfo::messageBudget)
      .def_readonly("players", &TeamInfo::players);
  py::class_<GameControlData>(m, "RoboCupGameControlData")
      .def(py::init<>())
      .def_readonly("header", &GameControlData::header)
      .def_readonly("version", &GameControlData::version)
      .def_readonly("packetNumber", &GameControlData::packetNumber)
      .def_readonly("playersPerTeam", &GameControlData::playersPerTeam)
      .def_readonly("competitionPhase", &GameControlData::competitionPhase)
      .def_readonly("competitionType", &GameControlData::competitionType)
      .def_readonly("gamePhase", &GameControlData::gamePhase)
      .def_readonly("state", &GameControlData::state)
      .def_readonly("setPlay", &GameControlData::setPlay)
      .def_readonly("firstHalf", &GameControlData::firstHalf)
      .def_readonly("kickingTeam", &GameControlData::kickingTeam)
      .def_readonly("secsRemaining", &GameControlData::secsRemaining)
      .def_readonly("secondaryTime", &GameControlData::secondaryTime)
      .def_readonly("teams", &GameControlData::teams);
}

void define_sub_blackboards(py::module_& m) {
  py::class_<JointValues>(m, "JointValues")
      .def(py::init<>())
      .def_readonly("angles", &JointValues::angles)
      .def_readonly("stiffnesses", &JointValues::stiffnesses)
      .def_readonly("temperatures", &JointValues::temperatures);
  py::class_<SensorValues>(m, "SensorValues")
      .def(py::init<>())
      .def_readonly("joints", &SensorValues::joints)
      .def_readonly("sensors", &SensorValues::sensors);
  py::class_<MotionBlackboard>(m, "MotionBlackboard")
      .def_readonly("sensors", &MotionBlackboard::sensors)
      .def_readonly("uptime", &MotionBlackboard::uptime)
      .def_readonly("active", &MotionBlackboard::active)
      .def_readonly("isStiff", &MotionBlackboard::isStiff);
  py::class_<VisionBlackboard>(m, "VisionBlackboard")
      .def_readonly("timestamp", &VisionBlackboard::timestamp)
      .def_readonly("balls", &VisionBlackboard::balls)
      .def_readonly("robots", &VisionBlackboard::robots)
      .def_readonly("posts", &VisionBlackboard::posts);
  py::class_<StateEstimationBlackboard>(m, "StateEstimationBlackboard")
      .def_readonly("robotPos", &StateEstimationBlackboard::robotPos)
      .def_readonly("robotPosUncertainty", &StateEstimationBlackboard::robotPosUncertainty)
      .def_readonly("robotHeadingUncertainty", &StateEstimationBlackboard::robotHeadingUncertainty)
      .def_readonly("allRobotPos", &StateEstimationBlackboard::allRobotPos)
      .def_readonly("ballPosRR", &StateEstimationBlackboard::ballPosRR)
      .def_readonly("ballPosRRC", &StateEstimationBlackboard::ballPosRRC)
      .def_readonly("ballVelRRC", &StateEstimationBlackboard::ballVelRRC)
      .def_readonly("ballVel", &StateEstimationBlackboard::ballVel)
      .def_readonly("ballPos", &StateEstimationBlackboard::ballPos)
      .def_readonly("teamBallPos", &StateEstimationBlackboard::teamBallPos)
      .def_readonly("teamBallVel", &StateEstimationBlackboard::teamBallVel)
      .def_readonly("teamBallPosUncertainty", &StateEstimationBlackboard::teamBallPosUncertainty)
      .def_readonly("egoBallPosUncertainty", &StateEstimationBlackboard::egoBallPosUncertainty)
      .def_readonly("sharedStateEstimationBundle", &StateEstimationBlackboard::sharedStateEstimationBundle)
      .def_readonly("robotObstacles", &StateEstimationBlackboard::robotObstacles)
      .def_readonly("hadTeamBallUpdate", &StateEstimationBlackboard::hadTeamBallUpdate);
  py::class_<BehaviourBlackboard>(m, "BehaviourBlackboard")
      .def_readonly("skill", &BehaviourBlackboard::skill)
      .def_readonly("headskill", &BehaviourBlackboard::headskill)
      .def_readonly("positioning", &BehaviourBlackboard::positioning)
      .def_readonly("behaviourSharedData", &BehaviourBlackboard::behaviourSharedData)
      .def_readonly("remoteStiffen", &BehaviourBlackboard::remoteStiffen)
      .def_readonly("useGetups", &BehaviourBlackboard::useGetups);
  py::class_<GameControllerBlackboard>(m, "GameControllerBlackboard")
      .def_readonly("connect", &GameControllerBlackboard::connect)
      .def_readonly("connected", &GameControllerBlackboard::connected)
      .def_readonly("data", &GameControllerBlackboard::data)
      .def_readonly("our_team", &GameControllerBlackboard::our_team)
      .def_readonly("player_number", &GameControllerBlackboard::player_number)
      .def_readonly("gameState", &GameControllerBlackboard::gameState)
      .def_readonly("whistleDetected", &GameControllerBlackboard::whistleDetected)
      .def_readonly("challengePhase", &GameControllerBlackboard::challengePhase);
  py::class_<ReceiverBlackboard>(m, "ReceiverBlackboard")
      .def_readonly("message", &ReceiverBlackboard::message)
      .def_readonly("data", &ReceiverBlackboard::data)
      .def_readonly("team", &ReceiverBlackboard::team)
      .def_readonly("lastReceived", &ReceiverBlackboard::lastReceived)
      .def_readonly("incapacitated", &ReceiverBlackboard::incapacitated);
  py::class_<KinematicsParameters>(m, "KinematicsParameters")
      .def_readonly("cameraPitchBottom", &KinematicsParameters::cameraPitchBottom)
      .def_readonly("cameraYawBottom", &KinematicsParameters::cameraYawBottom)
      .def_readonly("cameraRollBottom", &KinematicsParameters::cameraRollBottom)
      .def_readonly("cameraPitchTop", &KinematicsParameters::cameraPitchTop)
      .def_readonly("cameraYawTop", &KinematicsParameters::cameraYawTop)
      .def_readonly("cameraRollTop", &KinematicsParameters::cameraRollTop)
      .def_readonly("bodyPitch", &KinematicsParameters::bodyPitch);
  py::class_<KinematicsBlackboard>(m, "KinematicsBlackboard").def_readonly("parameters", &KinematicsBlackboard::parameters);
}

} // namespace

void define_blackboard(py::module_& m) {
  define_perception(m);
  define_team(m);
  define_game_controller(m);
  define_sub_blackboards(m);
  py::class_<Blackboard>(m, "Blackboard", "the robot's Blackboard as their behaviour reads it (read-only)")
      .def(py::init<>()) // empty boards, for tests of behaviour code
      .def_readonly("motion", &Blackboard::motion)
      .def_readonly("vision", &Blackboard::vision)
      .def_readonly("stateEstimation", &Blackboard::stateEstimation)
      .def_readonly("behaviour", &Blackboard::behaviour)
      .def_readonly("gameController", &Blackboard::gameController)
      .def_readonly("receiver", &Blackboard::receiver)
      .def_readonly("kinematics", &Blackboard::kinematics);
}

} // namespace touchline::python::runswift
