// touchline_sim.MultiRobotSim: a whole refereed match, every robot driven from Python, for
// the multi-agent environment (touchline_rl.multi_agent). Actions in, observations out as
// numpy arrays, one call each per frame, so the Python side does no per-robot calls.
#include <map>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "touchline/ini.hpp"
#include "touchline/learning/multi_robot_sim.hpp"
#include "touchline/learning/observation.hpp"

namespace py = pybind11;
using namespace touchline;

namespace {

constexpr py::ssize_t kActionElements = 5;

learning::MultiRobotDef make_def(const std::string& world_config, const std::vector<std::string>& overrides,
                                 const std::string& walk_config, const std::string& kick_config,
                                 bool perfect_localisation) {
  learning::MultiRobotDef def;
  def.world = sim::load_world_config(world_config, overrides);
  def.robot = robot::load_robot_def({walk_config, kick_config, "", ""}, def.robot);
  def.robot.localisation.perfect = perfect_localisation;
  return def;
}

void step(learning::MultiRobotSim& sim, const py::array_t<float, py::array::c_style | py::array::forcecast>& actions) {
  const auto n = static_cast<py::ssize_t>(sim.robots().size());
  if (actions.ndim() != 2 || actions.shape(0) != n || actions.shape(1) != kActionElements)
    throw std::invalid_argument("MultiRobotSim.step: actions must be shaped (" + std::to_string(n) + ", 5)");
  const auto a = actions.unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i)
    sim.set_action(static_cast<size_t>(i), {a(i, 0), a(i, 1), a(i, 2), a(i, 3), a(i, 4)});
  sim.step();
}

py::array_t<float> observations(const learning::MultiRobotSim& sim) {
  const auto n = static_cast<py::ssize_t>(sim.robots().size());
  py::array_t<float> out({n, static_cast<py::ssize_t>(sim.observation_size())});
  for (py::ssize_t i = 0; i < n; ++i) sim.observe(static_cast<size_t>(i), out.mutable_data(i, 0));
  return out;
}

py::dict game(const learning::MultiRobotSim& sim) {
  const GameInfo g = sim.game();
  py::dict d;
  d["state"] = static_cast<int>(g.state); // api::GameState's numbers: 0 INITIAL .. 3 PLAYING, 4 FINISHED, 5 STANDBY
  d["score"] = py::make_tuple(g.score[0], g.score[1]);
  d["secs_remaining"] = g.secs_remaining;
  d["first_half"] = g.first_half;
  d["kickoff_team"] = g.kickoff_team;
  return d;
}

/// Ground truth after the last frame: the ball (x, y mm, world frame) and per robot
/// (x, y mm, theta rad, penalised, fallen) in robots() order.
py::tuple truth(const learning::MultiRobotSim& sim) {
  const sim::TruthFrame t = sim.truth();
  const auto n = static_cast<py::ssize_t>(sim.robots().size());
  py::array_t<float> robots({n, py::ssize_t{5}});
  auto r = robots.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const RobotId& id = sim.robots()[static_cast<size_t>(i)];
    for (const auto& robot : t.robots) {
      if (!(robot.truth.id == id)) continue;
      r(i, 0) = robot.truth.body.x_mm;
      r(i, 1) = robot.truth.body.y_mm;
      r(i, 2) = robot.truth.body.theta_rad;
      r(i, 3) = robot.penalised ? 1.f : 0.f;
      r(i, 4) = robot.fallen ? 1.f : 0.f;
    }
  }
  return py::make_tuple(py::make_tuple(t.ball.x_mm, t.ball.y_mm), robots);
}

} // namespace

void define_multi_robot(py::module_& m) {
  py::class_<learning::MultiRobotSim>(m, "MultiRobotSim")
      .def(py::init([](const std::string& world_config, const std::vector<std::string>& overrides,
                       const std::string& walk_config, bool perfect_localisation, const std::string& kick_config) {
             return std::make_unique<learning::MultiRobotSim>(
                 make_def(world_config, overrides, walk_config, kick_config, perfect_localisation));
           }), py::arg("world_config") = "", py::arg("overrides") = std::vector<std::string>{},
           py::arg("walk_config") = "", py::arg("perfect_localisation") = false, py::arg("kick_config") = "",
           "A refereed match of 2 x match.team_size robots, all driven from Python. world_config: an .ini like "
           "config/spl2020.ini ('' = defaults), overrides 'section.key=value'; walk_config, kick_config: as "
           "SingleRobotSim's. Bad config: ValueError, one line.")
      .def("reset", &learning::MultiRobotSim::reset, py::arg("seed"),
           "A new match seeded with seed, every robot at its initial pose, standing.")
      .def("step", &step, py::arg("actions"),
           "One camera frame (1/30 s); actions (n_robots, 5) float: forward mm/s, left mm/s, turn rad/s, "
           "kick power (> 0: kick instead of walking), head yaw rad; robot API units.")
      .def("observations", &observations, "(n_robots, observation_size) float32: each robot's Blackboard as "
                                          "learning/core/include/touchline/learning/observation.hpp lists.")
      .def_property_readonly("game", &game, "The referee's game: state, score, secs_remaining, first_half, kickoff_team.")
      .def("truth", &truth, "((ball x, y mm), robots (n, 5): x mm, y mm, theta rad, penalised, fallen), world frame.")
      .def_property_readonly("robots", [](const learning::MultiRobotSim& sim) {
        std::vector<std::pair<int, int>> ids;
        for (const RobotId& id : sim.robots()) ids.emplace_back(id.team, id.player);
        return ids;
      }, "(team, player) per robot, the order of every array.")
      .def_property_readonly("observation_names", [](const learning::MultiRobotSim& sim) {
        return learning::observation_names(sim.def().world.match.team_size);
      })
      .def_property_readonly("game_over", &learning::MultiRobotSim::game_over, "The referee ended the match.")
      .def_property_readonly("out_of_time", &learning::MultiRobotSim::out_of_time,
                             "match.duration_s ran out before the referee ended the match.")
      .def_property_readonly("frame", &learning::MultiRobotSim::frame, "Camera frames since reset.")
      .def("state_hash", &learning::MultiRobotSim::state_hash, "Equal for bit-identical worlds.")
      .def_property_readonly("walk_limits", [](const learning::MultiRobotSim& sim) {
        const robot::WalkDef& w = sim.def().robot.walk;
        return std::map<std::string, float>{{"max_forward_mm_s", w.max_forward_mm_s},
                                            {"max_backward_mm_s", w.max_backward_mm_s},
                                            {"max_left_mm_s", w.max_left_mm_s},
                                            {"max_turn_rad_s", w.max_turn_rad_s},
                                            {"max_head_yaw_rad", sim.def().robot.head.max_yaw_rad}};
      })
      .def_property_readonly("field", [](const learning::MultiRobotSim& sim) {
        const sim::FieldDef& f = sim.def().world.field;
        return std::map<std::string, float>{{"length_mm", f.length_mm}, {"width_mm", f.width_mm},
                                            {"border_mm", f.border_mm}};
      });
}
