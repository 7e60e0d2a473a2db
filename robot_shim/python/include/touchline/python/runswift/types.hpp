#pragma once
// The values rUNSWift's behaviour code reads and writes, as plain structs in their shape:
// the field names, nesting and units their Python sees through their `robot` module
// (mm, rad, microseconds, the GameController's numbers). Written for Touchline from what
// that module exposes; bound to Python in module_*.cpp, filled from Touchline's
// Blackboard by blackboard_builder.cpp, read back by request_converter.cpp.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace touchline::python::runswift {

constexpr int kMaxNumPlayers = 7;  ///< MAX_NUM_PLAYERS of the GameController packet
constexpr int kRobotsPerTeam = 7;  ///< ROBOTS_PER_TEAM: receiver slots, one per player number

/// Body action types, in their order (the values only matter inside one process).
enum ActionType : int {
  NONE = 0, STAND, WALK, TURN_DRIBBLE, GETUP_FRONT, GETUP_BACK, TIP_OVER, KICK, INITIAL, LIMP,
  REF_PICKUP, GOALIE_SIT, GOALIE_DIVE_RIGHT, GOALIE_DIVE_LEFT, GOALIE_CENTRE, GOALIE_UNCENTRE,
  GOALIE_INITIAL, GOALIE_AFTERSIT_INITIAL, DEFENDER_CENTRE, GOALIE_FAST_SIT, MOTION_CALIBRATE,
  STAND_STRAIGHT, LINE_UP, TEST_ARMS, RAISE_ARM, UKEMI_FRONT, UKEMI_BACK, GOALIE_STAND, SIT,
  SIGNAL_KICK_IN_RIGHT, SIGNAL_KICK_IN_LEFT, SIGNAL_GOAL_KICK_RIGHT, SIGNAL_GOAL_KICK_LEFT,
  SIGNAL_CORNER_KICK_RIGHT, SIGNAL_CORNER_KICK_LEFT, SIGNAL_GOAL_RIGHT, SIGNAL_GOAL_LEFT,
  SIGNAL_PUSHING_FREE_KICK_RIGHT, SIGNAL_PUSHING_FREE_KICK_LEFT, SIGNAL_FULL_TIME, NUM_ACTION_TYPES
};
/// Their names, indexed by ActionType.
const char* action_type_name(int type);

enum FootSide : int { FOOT_LEFT = 0, FOOT_RIGHT = 1 };
enum Stiffen : int { STIFFEN_NONE = 0, STIFFEN_STIFFEN = 1 };

/// NAO joints in the robot's order, and the sensors the behaviour code indexes.
enum Joint : int {
  HeadYaw = 0, HeadPitch, LShoulderPitch, LShoulderRoll, LElbowYaw, LElbowRoll, LWristYaw, LHand,
  LHipYawPitch, LHipRoll, LHipPitch, LKneePitch, LAnklePitch, LAnkleRoll, RHipRoll, RHipPitch,
  RKneePitch, RAnklePitch, RAnkleRoll, RShoulderPitch, RShoulderRoll, RElbowYaw, RElbowRoll,
  RWristYaw, RHand, NUMBER_OF_JOINTS
};
enum Sensor : int {
  InertialSensor_AngleX = 0, InertialSensor_AngleY, LFoot_FSR_FrontLeft, LFoot_FSR_FrontRight,
  LFoot_FSR_RearLeft, LFoot_FSR_RearRight, RFoot_FSR_FrontLeft, RFoot_FSR_FrontRight,
  RFoot_FSR_RearLeft, RFoot_FSR_RearRight, LFoot_Bumper_Left, LFoot_Bumper_Right,
  RFoot_Bumper_Left, RFoot_Bumper_Right, ChestBoard_Button, Battery_Charge, Battery_Current,
  SonarLeft, SonarRight, NUMBER_OF_SENSORS
};

/// Row-major 3x3; Python sees it as a tuple of three column tuples.
using Matrix3 = std::array<float, 9>;

struct AbsCoord {
  float x = 0, y = 0;  ///< mm
  float theta = 0;     ///< rad
  float weight = 1;
  Matrix3 var{};       ///< covariance of (x, y, theta): mm^2, mm rad, rad^2
};

struct RRCoord {
  float distance = 0;    ///< mm
  float heading = 0;     ///< rad, + left
  float orientation = 0; ///< rad
  Matrix3 var{};
};

// --- actions ------------------------------------------------------------------------------

struct BodyCommand {
  int actionType = NONE;
  int forward = 0;  ///< mm/s, + forward (the walk's distance per second)
  int left = 0;     ///< mm/s, + left
  float turn = 0;   ///< rad/s, + counter-clockwise; KICK / TURN_DRIBBLE: direction, rad
  float power = 0;  ///< kick power, [0, 1]
  float bend = 0;
  float speed = 0;  ///< [0, 1]: 0 walks at 66 % of the walk's limits, 1 at 100 %
  int foot = FOOT_LEFT;
  bool useShuffle = false, leftArmBehind = false, rightArmBehind = false, blocking = false,
       extraStableKick = false;
};

struct HeadCommand {
  float yaw = 0;          ///< rad, + left
  float pitch = 0;        ///< rad, + down
  bool isRelative = true; ///< add to the current angles
  float yawSpeed = 1, pitchSpeed = 1; ///< fraction of the head's speed, [0, 1]
};

struct Rgb {
  bool red = false, green = false, blue = false;
};

struct LedCommand {
  int leftEar = 0x3FF, rightEar = 0x3FF;      ///< segments lit, 10-bit
  Rgb leftEye{true, true, true}, rightEye{true, true, true}, chestButton{true, true, true};
  Rgb leftFoot, rightFoot;
};

struct AllCommand {
  HeadCommand head;
  BodyCommand body;
  LedCommand leds;
  int stiffen = STIFFEN_NONE;
};

struct BehaviourSharedData {
  int secondsSinceLastKick = -1; ///< -1: never kicked
  int role = 0;                  ///< POSITIONING_*
  bool playingBall = false, needAssistance = false, isAssisting = false, isKickedOff = false;
  float walkingToX = 0, walkingToY = 0, walkingToH = 0; ///< mm, mm, rad
  bool kickNotification = false;
};

struct BehaviourDebugInfo {
  std::string bodyBehaviourHierarchy, headBehaviourHierarchy;
  bool haveBallManoeuvreTarget = false;
  float ballManoeuvreTargetX = 0, ballManoeuvreTargetY = 0, ballManoeuvreHeadingError = 0;
  std::string ballManoeuvreType;
  bool ballManoeuvreHard = false;
  bool anticipating = false;
  float anticipateX = 0, anticipateY = 0, anticipateH = 0;
};

struct BehaviourRequest {
  AllCommand actions;
  BehaviourSharedData behaviourSharedData;
  BehaviourDebugInfo behaviourDebugInfo;
};

// --- perception -----------------------------------------------------------------------------

enum RobotType : int { rUnknown = 0, rBlue = 1, rRed = 2 };
enum PostType : int { pNone = 0, pLeft, pRight, pHome, pAway, pHomeLeft, pHomeRight, pAwayLeft, pAwayRight };

struct BallInfo {
  RRCoord rr;
  int radius = 0;                      ///< pixels in the image
  std::array<int, 2> imageCoords{};    ///< column, row
  bool topCamera = true;
};

struct RobotVisionInfo {
  RRCoord rr;
  int type = rUnknown;
};

struct PostInfo {
  RRCoord rr;
  int type = pNone;
  std::array<int, 2> imageCoords{};
};

struct RobotObstacle {
  RRCoord rr;
  int type = rUnknown;
  AbsCoord rrc;  ///< robot-relative cartesian, mm
  AbsCoord pos;  ///< field frame, mm
  double tangentHeadingLeft = 0, tangentHeadingRight = 0; ///< rad: the headings that pass it
  RRCoord evadeVectorLeft, evadeVectorRight;
};

struct SharedStateEstimationBundle {
  AbsCoord robotPos, ballPosRRC, ballVelRRC;
  bool haveBallUpdate = false;
};

struct BroadcastData {
  int playerNum = 0;
  std::array<float, 3> robotPos{}; ///< x mm, y mm, theta rad
  AbsCoord ballPosAbs;
  RRCoord ballPosRR;
  SharedStateEstimationBundle sharedStateEstimationBundle;
  BehaviourSharedData behaviourSharedData;
  int acB = LIMP;     ///< the body action running
  float uptime = 0;   ///< s
  int gameState = 0;  ///< STATE_*
};

/// The SPL standard message, as far as their behaviours read it.
struct SplStandardMessage {
  int playerNum = 0;
  bool fallen = false;
  std::array<float, 3> pose{};  ///< x mm, y mm, theta rad
  float ballAge = -1;           ///< s since the ball was seen; -1: never
  std::array<float, 2> ball{};  ///< robot-relative, mm
};

// --- GameController ----------------------------------------------------------------------------

struct RobotInfo {
  int penalty = 0;             ///< PENALTY_*
  int secsTillUnpenalised = 0;
};

struct TeamInfo {
  int teamNumber = 0, teamColour = 0, score = 0, penaltyShot = 0, singleShots = 0, messageBudget = 1200;
  std::array<RobotInfo, kMaxNumPlayers> players{};
};

struct GameControlData {
  std::string header = "RGme";
  int version = 14, packetNumber = 0, playersPerTeam = 5, competitionPhase = 0, competitionType = 0;
  int gamePhase = 0, state = 0, setPlay = 0, firstHalf = 1, kickingTeam = 0;
  int secsRemaining = 0, secondaryTime = 0;
  std::array<TeamInfo, 2> teams{};
};

// --- the Blackboard ------------------------------------------------------------------------------

struct JointValues {
  std::array<float, NUMBER_OF_JOINTS> angles{}, stiffnesses{}, temperatures{};
};

struct SensorValues {
  JointValues joints;
  std::array<float, NUMBER_OF_SENSORS> sensors{};
};

struct MotionBlackboard {
  SensorValues sensors;
  float uptime = 0;  ///< s
  AllCommand active;
  bool isStiff = true;
};

struct VisionBlackboard {
  int64_t timestamp = 0; ///< microseconds
  std::vector<BallInfo> balls;
  std::vector<RobotVisionInfo> robots;
  std::vector<PostInfo> posts;
};

struct StateEstimationBlackboard {
  AbsCoord robotPos;
  float robotPosUncertainty = 0;     ///< product of the position ellipse's sigmas, mm^2
  float robotHeadingUncertainty = 0; ///< heading sigma, rad
  std::vector<AbsCoord> allRobotPos;
  RRCoord ballPosRR;
  AbsCoord ballPosRRC, ballVelRRC, ballVel, ballPos, teamBallPos, teamBallVel;
  float teamBallPosUncertainty = 0, egoBallPosUncertainty = 0; ///< mm^2, as robotPosUncertainty
  SharedStateEstimationBundle sharedStateEstimationBundle;
  std::vector<RobotObstacle> robotObstacles;
  bool hadTeamBallUpdate = false;
};

struct BehaviourBlackboard {
  std::string skill = "Game", headskill = "HeadCentre", positioning = "PositioningAgainstKickingTeam";
  BehaviourSharedData behaviourSharedData;
  bool remoteStiffen = false, useGetups = true;
};

struct GameControllerBlackboard {
  bool connect = true, connected = true;
  GameControlData data;
  TeamInfo our_team;
  int player_number = 1;
  int gameState = 0;
  bool whistleDetected = false;
  int challengePhase = 0;
};

struct ReceiverBlackboard {
  std::array<SplStandardMessage, kRobotsPerTeam> message{};
  std::array<BroadcastData, kRobotsPerTeam> data{};
  int team = 0;
  std::array<int64_t, kRobotsPerTeam> lastReceived{}; ///< s (simulated) of the last message; 0: never
  std::vector<bool> incapacitated = std::vector<bool>(kRobotsPerTeam, true);
};

struct KinematicsParameters {
  float cameraPitchBottom = 0; ///< degrees: calibration offset of the bottom camera
  float cameraYawBottom = 0, cameraRollBottom = 0, cameraPitchTop = 0, cameraYawTop = 0, cameraRollTop = 0;
  float bodyPitch = 0;
};

struct KinematicsBlackboard {
  KinematicsParameters parameters;
};

struct Blackboard {
  MotionBlackboard motion;
  VisionBlackboard vision;
  StateEstimationBlackboard stateEstimation;
  BehaviourBlackboard behaviour;
  GameControllerBlackboard gameController;
  ReceiverBlackboard receiver;
  KinematicsBlackboard kinematics;
};

} // namespace touchline::python::runswift
