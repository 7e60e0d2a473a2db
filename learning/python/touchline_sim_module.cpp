// touchline_sim: the single-robot simulator as a Python extension, for learning and skill
// evaluation (learning/touchline_rl). No transport: the world and the robot's own code
// (MotionAdapter, WalkCycle, localisation, the C++ behaviours) run in this process.
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "touchline/behaviour/registry.hpp"
#include "touchline/ini.hpp"
#include "touchline/learning/single_robot_sim.hpp"

namespace py = pybind11;
using namespace touchline;

namespace {

using Pose = std::tuple<float, float, float>;

learning::SingleRobotDef make_def(const std::string& world_config, const std::vector<std::string>& overrides,
                                  const std::string& walk_config, bool perfect_localisation) {
  learning::SingleRobotDef def;
  def.world = sim::load_world_config(world_config, overrides);
  if (!walk_config.empty()) def.walk = robot::load_walk_def(walk_config);
  def.perfect_localisation = perfect_localisation;
  return def;
}

Pose as_tuple(const Pose2D& p) { return {p.x_mm, p.y_mm, p.theta_rad}; }

} // namespace

PYBIND11_MODULE(touchline_sim, m) {
  m.doc() = "One robot on a Touchline field, in process: the real walk, world and C++ behaviours.";
  py::register_exception<ConfigError>(m, "ConfigError", PyExc_ValueError);
  py::register_exception<behaviour::BehaviourError>(m, "BehaviourError", PyExc_ValueError);

  py::class_<learning::SingleRobotSim>(m, "SingleRobotSim")
      .def(py::init([](const std::string& world_config, const std::vector<std::string>& overrides,
                       const std::string& walk_config, bool perfect_localisation) {
             return std::make_unique<learning::SingleRobotSim>(
                 make_def(world_config, overrides, walk_config, perfect_localisation));
           }), py::arg("world_config") = "", py::arg("overrides") = std::vector<std::string>{},
           py::arg("walk_config") = "", py::arg("perfect_localisation") = true,
           "world_config: an .ini like config/spl2020.ini ('' = defaults), overrides 'section.key=value'; "
           "walk_config: a walk .ini ('' = the built-in walk). Bad config: ValueError, one line.")
      .def(
          "reset",
          [](learning::SingleRobotSim& sim, uint64_t seed, const Pose& pose, std::optional<std::tuple<float, float>> ball,
             std::optional<std::string> behaviour, const behaviour::Params& params) {
            std::optional<Pose2D> ball_pose;
            if (ball) ball_pose = Pose2D{std::get<0>(*ball), std::get<1>(*ball), 0};
            std::unique_ptr<api::Behaviour> driver;
            if (behaviour) driver = behaviour::make_behaviour(*behaviour, params);
            sim.reset(seed, {std::get<0>(pose), std::get<1>(pose), std::get<2>(pose)}, ball_pose, std::move(driver));
          },
          py::arg("seed"), py::arg("pose"), py::arg("ball") = py::none(), py::arg("behaviour") = py::none(),
          py::arg("params") = behaviour::Params{},
          "New episode: the robot at pose (x mm, y mm, theta rad; field frame) with the walk at rest, the ball at "
          "(x, y) or in a corner. behaviour: a C++ behaviour name (robot_shim --behaviour) that drives the robot; "
          "None: step(forward, left, turn) does.")
      .def(
          "step",
          [](learning::SingleRobotSim& sim, float forward, float left, float turn) {
            sim.step(api::ActionCommand::walk(forward, left, turn));
          },
          py::arg("forward"), py::arg("left"), py::arg("turn"),
          "One camera frame (1/30 s) walking at forward, left (mm/s) and turn (rad/s); the walk applies its limits.")
      .def("step_behaviour", &learning::SingleRobotSim::step_behaviour, "One camera frame, the behaviour deciding.")
      .def_property_readonly("pose", [](const learning::SingleRobotSim& sim) { return as_tuple(sim.pose()); },
                             "True body pose (x mm, y mm, theta rad), field frame.")
      .def_property_readonly("ball",
                             [](const learning::SingleRobotSim& sim) {
                               const sim::BallTruth b = sim.ball();
                               return std::make_tuple(b.x_mm, b.y_mm);
                             })
      .def_property_readonly("walk_velocity",
                             [](const learning::SingleRobotSim& sim) {
                               const robot::WalkRequest& v = sim.walk_velocity();
                               return std::make_tuple(v.forward_mm_s, v.left_mm_s, v.turn_rad_s);
                             },
                             "What the walk executes now: forward, left (mm/s), turn (rad/s).")
      .def_property_readonly("frame", &learning::SingleRobotSim::frame, "Camera frames since reset.")
      .def_property_readonly("time_s", &learning::SingleRobotSim::time_s, "Simulated seconds since reset.")
      .def("state_hash", &learning::SingleRobotSim::state_hash, "Equal for bit-identical worlds.")
      .def_property_readonly("walk_limits", [](const learning::SingleRobotSim& sim) {
        const robot::WalkDef& w = sim.def().walk;
        return std::map<std::string, float>{{"max_forward_mm_s", w.max_forward_mm_s},
                                            {"max_backward_mm_s", w.max_backward_mm_s},
                                            {"max_left_mm_s", w.max_left_mm_s},
                                            {"max_turn_rad_s", w.max_turn_rad_s}};
      })
      .def_property_readonly("field", [](const learning::SingleRobotSim& sim) {
        const sim::FieldDef& f = sim.def().world.field;
        return std::map<std::string, float>{{"length_mm", f.length_mm}, {"width_mm", f.width_mm}};
      });
}
