// Constants and enums of the `robot` module: joints and sensors, the NAO's joint limits,
// the GameController's numbers (the SPL protocol's), positioning roles, the camera image,
// and the field's dimensions (from the world's config: set_field_constants).
#include <cmath>

#include "touchline/python/runswift/module.hpp"

#include <pybind11/embed.h>

#include "touchline/python/runswift/types.hpp"

namespace py = pybind11;

// Their `robot`, built in under its own name (in the file every user of the module links:
// set_field_constants is here); the rUNSWift profile puts it in sys.modules as `robot`.
PYBIND11_EMBEDDED_MODULE(touchline_runswift_robot, m) { touchline::python::runswift::define_runswift_module(m); }

namespace touchline::python::runswift {

py::object int_enum(py::module_& m, const char* name, const std::vector<std::pair<const char*, int>>& members) {
  py::list items;
  for (const auto& [member, value] : members) items.append(py::make_tuple(member, value));
  py::object cls = py::module_::import("enum").attr("IntEnum")(name, items);
  cls.attr("__module__") = m.attr("__name__");
  m.attr(name) = cls;
  return cls;
}

namespace {

void define_body(py::module_& m) {
  static const char* const kJoints[] = {
      "HeadYaw", "HeadPitch", "LShoulderPitch", "LShoulderRoll", "LElbowYaw", "LElbowRoll", "LWristYaw",
      "LHand", "LHipYawPitch", "LHipRoll", "LHipPitch", "LKneePitch", "LAnklePitch", "LAnkleRoll",
      "RHipRoll", "RHipPitch", "RKneePitch", "RAnklePitch", "RAnkleRoll", "RShoulderPitch", "RShoulderRoll",
      "RElbowYaw", "RElbowRoll", "RWristYaw", "RHand"};
  std::vector<std::pair<const char*, int>> joints;
  for (int j = 0; j < NUMBER_OF_JOINTS; ++j) joints.emplace_back(kJoints[j], j);
  joints.emplace_back("NUMBER_OF_JOINTS", NUMBER_OF_JOINTS);
  int_enum(m, "Joints", joints);

  static const char* const kSensors[] = {
      "InertialSensor_AngleX", "InertialSensor_AngleY", "LFoot_FSR_FrontLeft", "LFoot_FSR_FrontRight",
      "LFoot_FSR_RearLeft", "LFoot_FSR_RearRight", "RFoot_FSR_FrontLeft", "RFoot_FSR_FrontRight",
      "RFoot_FSR_RearLeft", "RFoot_FSR_RearRight", "LFoot_Bumper_Left", "LFoot_Bumper_Right",
      "RFoot_Bumper_Left", "RFoot_Bumper_Right", "ChestBoard_Button", "Battery_Charge", "Battery_Current",
      "SonarLeft", "SonarRight"};
  std::vector<std::pair<const char*, int>> sensors;
  for (int s = 0; s < NUMBER_OF_SENSORS; ++s) sensors.emplace_back(kSensors[s], s);
  sensors.emplace_back("NUMBER_OF_SENSORS", NUMBER_OF_SENSORS);
  int_enum(m, "Sensors", sensors);

  // The NAO V6's joint ranges (rad), from the robot's public documentation.
  struct Range {
    const char* joint;
    double min, max;
  };
  static const Range kRanges[] = {
      {"HeadYaw", -2.0857, 2.0857},        {"HeadPitch", -0.6720, 0.5149},      {"LShoulderPitch", -2.0857, 2.0857},
      {"LShoulderRoll", -0.3142, 1.3265},  {"LElbowYaw", -2.0857, 2.0857},      {"LElbowRoll", -1.5446, -0.0349},
      {"LWristYaw", -1.8238, 1.8238},      {"LHand", 0.0, 1.0},                 {"LHipYawPitch", -1.145303, 0.740810},
      {"LHipRoll", -0.379472, 0.790477},   {"LHipPitch", -1.535889, 0.484090},  {"LKneePitch", -0.092346, 2.112528},
      {"LAnklePitch", -1.189516, 0.922747}, {"LAnkleRoll", -0.397880, 0.769001}, {"RHipRoll", -0.790477, 0.379472},
      {"RHipPitch", -1.535889, 0.484090},  {"RKneePitch", -0.103083, 2.120198}, {"RAnklePitch", -1.186448, 0.932056},
      {"RAnkleRoll", -0.768992, 0.397935}, {"RShoulderPitch", -2.0857, 2.0857}, {"RShoulderRoll", -1.3265, 0.3142},
      {"RElbowYaw", -2.0857, 2.0857},      {"RElbowRoll", 0.0349, 1.5446},      {"RWristYaw", -1.8238, 1.8238},
      {"RHand", 0.0, 1.0}};
  for (const Range& r : kRanges) {
    m.attr((std::string(r.joint) + "_Min").c_str()) = r.min;
    m.attr((std::string(r.joint) + "_Max").c_str()) = r.max;
  }
}

void define_game_controller_constants(py::module_& m) {
  const std::vector<std::pair<const char*, int>> values = {
      {"MAX_NUM_PLAYERS", kMaxNumPlayers},
      {"TEAM_BLUE", 0}, {"TEAM_RED", 1}, {"TEAM_YELLOW", 2}, {"TEAM_BLACK", 3}, {"TEAM_WHITE", 4},
      {"TEAM_GREEN", 5}, {"TEAM_ORANGE", 6}, {"TEAM_PURPLE", 7}, {"TEAM_BROWN", 8}, {"TEAM_GRAY", 9},
      {"STATE_INITIAL", 0}, {"STATE_READY", 1}, {"STATE_SET", 2}, {"STATE_PLAYING", 3}, {"STATE_FINISHED", 4},
      {"STATE_STANDBY", 5}, // the GameController's since 2023; Touchline's referee with rules.standby_s
      {"GAME_PHASE_NORMAL", 0}, {"GAME_PHASE_PENALTYSHOOT", 1}, {"GAME_PHASE_OVERTIME", 2}, {"GAME_PHASE_TIMEOUT", 3},
      {"SET_PLAY_NONE", 0}, {"SET_PLAY_GOAL_KICK", 1}, {"SET_PLAY_PUSHING_FREE_KICK", 2},
      {"SET_PLAY_CORNER_KICK", 3}, {"SET_PLAY_KICK_IN", 4}, {"SET_PLAY_PENALTY_KICK", 5},
      {"PENALTY_NONE", 0}, {"PENALTY_SPL_ILLEGAL_BALL_CONTACT", 1}, {"PENALTY_SPL_PLAYER_PUSHING", 2},
      {"PENALTY_SPL_ILLEGAL_MOTION_IN_SET", 3}, {"PENALTY_SPL_INACTIVE_PLAYER", 4}, {"PENALTY_SPL_ILLEGAL_POSITION", 5},
      {"PENALTY_SPL_LEAVING_THE_FIELD", 6}, {"PENALTY_SPL_REQUEST_FOR_PICKUP", 7}, {"PENALTY_SPL_LOCAL_GAME_STUCK", 8},
      {"PENALTY_SPL_ILLEGAL_POSITION_IN_SET", 9}, {"PENALTY_SUBSTITUTE", 14}, {"PENALTY_MANUAL", 15},
      {"COMPETITION_PHASE_ROUNDROBIN", 0}, {"COMPETITION_PHASE_PLAYOFF", 1},
      {"COMPETITION_TYPE_NORMAL", 0},
      {"AUTO_CALIBRATION_PHASE_1", 0}, {"AUTO_CALIBRATION_PHASE_2_1", 1}, {"AUTO_CALIBRATION_PHASE_2_2", 2},
      {"AUTO_CALIBRATION_PHASE_2_3", 3}, {"AUTO_CALIBRATION_PHASE_2_4", 4}, {"AUTO_CALIBRATION_PHASE_2_5", 5},
      // Positioning roles (BehaviourSharedData.role).
      {"POSITIONING_NONE", 0}, {"POSITIONING_AGAINST_KICKING_TEAM_SUPPORTER", 10},
      {"POSITIONING_AGAINST_KICKING_TEAM_DEFENDER", 11}, {"POSITIONING_AGAINST_KICKING_TEAM_UPFIELDER", 12},
      {"POSITIONING_FIND_BALL_FINDER", 20}, {"POSITIONING_AGAINST_DRIBBLE_TEAM_RIGHT_SUPPORTER", 30},
      {"POSITIONING_AGAINST_DRIBBLE_TEAM_SHOOTER", 31}, {"POSITIONING_AGAINST_DRIBBLE_TEAM_LEFT_SUPPORTER", 32},
      {"POSITIONING_AGAINST_DRIBBLE_TEAM_SWEEPER", 33},
      // The NAO V6's cameras (pixels).
      {"TOP_IMAGE_ROWS", 960}, {"TOP_IMAGE_COLS", 1280}, {"BOT_IMAGE_ROWS", 480}, {"BOT_IMAGE_COLS", 640},
      {"ROBOTS_PER_TEAM", kRobotsPerTeam}};
  for (const auto& [name, value] : values) m.attr(name) = value;
  m.attr("IMAGE_HFOV") = 1.0641; // rad, the NAO V6 camera's horizontal field of view (60.97 degrees)
}

} // namespace

void set_field_constants(py::module_& m, const robot::localisation::FieldMap& f) {
  // Integers, as their C preprocessor constants are (Python code divides them with /).
  auto mm = [](float v) { return static_cast<int>(std::lround(v)); };
  // No separate penalty area (the 2011 field): its role is the goal box's.
  const float area_length = f.penalty_area_length_mm > 0 ? f.penalty_area_length_mm : f.goal_box_length_mm;
  const float area_width = f.penalty_area_width_mm > 0 ? f.penalty_area_width_mm : f.goal_box_width_mm;
  m.attr("FIELD_LINE_WIDTH") = mm(f.line_width_mm);
  m.attr("FIELD_LENGTH") = mm(f.length_mm);
  m.attr("FIELD_WIDTH") = mm(f.width_mm);
  m.attr("FIELD_LENGTH_OFFSET") = mm(f.border_mm);
  m.attr("FIELD_WIDTH_OFFSET") = mm(f.border_mm);
  m.attr("OFFNAO_FIELD_LENGTH_OFFSET") = mm(f.border_mm + 30);
  m.attr("OFFNAO_FIELD_WIDTH_OFFSET") = mm(f.border_mm + 30);
  m.attr("FULL_FIELD_LENGTH") = mm(f.length_mm + 2 * f.border_mm);
  m.attr("FULL_FIELD_WIDTH") = mm(f.width_mm + 2 * f.border_mm);
  m.attr("OFFNAO_FULL_FIELD_LENGTH") = mm(f.length_mm + 2 * (f.border_mm + 30));
  m.attr("OFFNAO_FULL_FIELD_WIDTH") = mm(f.width_mm + 2 * (f.border_mm + 30));
  m.attr("GOAL_BOX_LENGTH") = mm(f.goal_box_length_mm);
  m.attr("GOAL_BOX_WIDTH") = mm(f.goal_box_width_mm);
  m.attr("PENALTY_AREA_LENGTH") = mm(area_length);
  m.attr("PENALTY_AREA_WIDTH") = mm(area_width);
  m.attr("PENALTY_CROSS_DIMENSIONS") = 100;
  m.attr("DIST_GOAL_LINE_TO_PENALTY_CROSS") = mm(f.penalty_mark_distance_mm);
  m.attr("PENALTY_CROSS_ABS_X") = mm(f.length_mm / 2 - f.penalty_mark_distance_mm);
  m.attr("CENTER_CIRCLE_DIAMETER") = mm(f.centre_circle_diameter_mm);
  m.attr("GOAL_POST_DIAMETER") = mm(f.goal_post_diameter_mm);
  m.attr("GOAL_BAR_DIAMETER") = 100;
  m.attr("GOAL_POST_HEIGHT") = 800;
  m.attr("GOAL_WIDTH") = mm(f.goal_width_mm);
  m.attr("BALL_RADIUS") = mm(f.ball_diameter_mm / 2);
  m.attr("GOAL_POST_ABS_X") = mm(f.length_mm / 2);
  m.attr("GOAL_POST_ABS_Y") = mm(f.goal_width_mm / 2);
  // Set-play spots: a goal kick from the goal box's front corners, a corner kick from the corner.
  m.attr("GOAL_KICK_ABS_X") = mm(f.length_mm / 2 - f.goal_box_length_mm);
  m.attr("GOAL_KICK_ABS_Y") = mm(f.goal_box_width_mm / 2);
  m.attr("CORNER_KICK_ABS_X") = mm(f.length_mm / 2);
  m.attr("CORNER_KICK_ABS_Y") = mm(f.width_mm / 2);
}

void define_runswift_module(py::module_& m) {
  m.doc() = "Touchline's implementation of the robot module rUNSWift's behaviours import (mm, rad, us).";
  define_body(m);
  define_game_controller_constants(m);
  define_geometry(m);
  define_actions(m);
  define_blackboard(m);
  set_field_constants(m, robot::localisation::FieldMap{});
  m.attr("params") = py::dict();
  m.attr("team") = 0;
  m.attr("player") = 1;
}

} // namespace touchline::python::runswift
