// touchline_sim: the single-robot simulator as a Python extension, for learning and skill
// evaluation (learning/touchline_rl). No transport: the world and the robot's own code
// (MotionAdapter, WalkCycle, localisation, the C++ behaviours) run in this process.
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "touchline/behaviour/registry.hpp"
#include "touchline/ini.hpp"
#include "touchline/learning/single_robot_sim.hpp"
#include "touchline/learning/tile_q.hpp"

namespace py = pybind11;
using namespace touchline;

namespace {

using Pose = std::tuple<float, float, float>;

learning::SingleRobotDef make_def(const std::string& world_config, const std::vector<std::string>& overrides,
                                  const std::string& walk_config, const std::string& kick_config,
                                  bool perfect_localisation) {
  learning::SingleRobotDef def;
  def.world = sim::load_world_config(world_config, overrides);
  // No field file: the in-process match gives the robot the world's field, overrides and all.
  def.robot = robot::load_robot_def({walk_config, kick_config, "", ""}, def.robot);
  def.robot.localisation.perfect = perfect_localisation;
  return def;
}

Pose as_tuple(const Pose2D& p) { return {p.x_mm, p.y_mm, p.theta_rad}; }
Pose2D as_pose(const Pose& p) { return {std::get<0>(p), std::get<1>(p), std::get<2>(p)}; }

std::vector<learning::WalkAction> as_actions(const std::vector<Pose>& commands) {
  std::vector<learning::WalkAction> actions;
  for (const Pose& c : commands) actions.push_back({std::get<0>(c), std::get<1>(c), std::get<2>(c)});
  return actions;
}

learning::EpisodeDef episode_def(double distance_mm, double heading_rad, int max_frames) {
  return {distance_mm, heading_rad, max_frames};
}

void define_tile_learning(py::module_& m);

} // namespace

void define_multi_robot(py::module_& m); // multi_robot_module.cpp

PYBIND11_MODULE(touchline_sim, m) {
  m.doc() = "One robot on a Touchline field, in process: the real walk, world and C++ behaviours.";
  py::register_exception<ConfigError>(m, "ConfigError", PyExc_ValueError);
  py::register_exception<behaviour::BehaviourError>(m, "BehaviourError", PyExc_ValueError);

  py::class_<learning::SingleRobotSim>(m, "SingleRobotSim")
      .def(py::init([](const std::string& world_config, const std::vector<std::string>& overrides,
                       const std::string& walk_config, bool perfect_localisation, const std::string& kick_config) {
             return std::make_unique<learning::SingleRobotSim>(
                 make_def(world_config, overrides, walk_config, kick_config, perfect_localisation));
           }), py::arg("world_config") = "", py::arg("overrides") = std::vector<std::string>{},
           py::arg("walk_config") = "", py::arg("perfect_localisation") = true, py::arg("kick_config") = "",
           "world_config: an .ini like config/spl2020.ini ('' = defaults), overrides 'section.key=value'; "
           "walk_config: a walk .ini ('' = the built-in walk); kick_config: a kick .ini like config/kick.ini "
           "('' = the built-in kick and dribble). Bad config: ValueError, one line.")
      .def(
          "reset",
          [](learning::SingleRobotSim& sim, uint64_t seed, const Pose& pose, std::optional<std::tuple<float, float>> ball,
             std::optional<std::string> behaviour, const behaviour::Params& params) {
            std::optional<Pose2D> ball_pose;
            if (ball) ball_pose = Pose2D{std::get<0>(*ball), std::get<1>(*ball), 0};
            std::optional<robot::BehaviourDef> driver;
            if (behaviour) driver = robot::BehaviourDef{*behaviour, params, {}};
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
        const robot::WalkDef& w = sim.def().robot.walk;
        return std::map<std::string, float>{{"max_forward_mm_s", w.max_forward_mm_s},
                                            {"max_backward_mm_s", w.max_backward_mm_s},
                                            {"max_left_mm_s", w.max_left_mm_s},
                                            {"max_turn_rad_s", w.max_turn_rad_s}};
      })
      .def_property_readonly("field", [](const learning::SingleRobotSim& sim) {
        const sim::FieldDef& f = sim.def().world.field;
        return std::map<std::string, float>{{"length_mm", f.length_mm}, {"width_mm", f.width_mm}};
      });
  define_tile_learning(m);
  define_multi_robot(m);
}

namespace {

void define_tile_learning(py::module_& m) {
  py::class_<learning::TileCodingDef>(m, "TileCodingDef")
      .def(py::init<>())
      .def_readwrite("distance_scale_mm", &learning::TileCodingDef::distance_scale_mm)
      .def_readwrite("max_distance_mm", &learning::TileCodingDef::max_distance_mm)
      .def_readwrite("tilings", &learning::TileCodingDef::tilings)
      .def_readwrite("tiles_distance", &learning::TileCodingDef::tiles_distance)
      .def_readwrite("tiles_bearing", &learning::TileCodingDef::tiles_bearing)
      .def_readwrite("tiles_heading", &learning::TileCodingDef::tiles_heading);

  py::class_<learning::TileCoding>(m, "TileCoding")
      .def(py::init<const learning::TileCodingDef&>())
      .def("cells", &learning::TileCoding::cells)
      .def("active", [](const learning::TileCoding& coding, double x, double y, double heading) {
        std::vector<int> cells(static_cast<size_t>(coding.def().tilings));
        coding.active(x, y, heading, cells.data());
        return cells;
      }, "The K active cells for a robot-relative target (x mm, y mm, heading error rad).");

  py::class_<learning::TileQ>(m, "TileQ")
      .def(py::init([](const learning::TileCodingDef& coding, const std::vector<Pose>& commands) {
             return std::make_unique<learning::TileQ>(coding, as_actions(commands));
           }),
           py::arg("coding"), py::arg("actions"), "actions: [(forward mm/s, left mm/s, turn rad/s), ...]")
      .def_property_readonly("weights", [](py::object self) {
        auto& q = self.cast<learning::TileQ&>();
        // A view, not a copy: writing it (np.copyto) loads weights; the TileQ stays alive with it.
        return py::array_t<float>({q.weights().size()}, {sizeof(float)}, q.weights().data(), self);
      })
      .def_property_readonly("tilings", [](const learning::TileQ& q) { return q.coding().def().tilings; })
      .def_property_readonly("actions", [](const learning::TileQ& q) {
        std::vector<Pose> actions;
        for (const auto& a : q.actions()) actions.emplace_back(a.forward_mm_s, a.left_mm_s, a.turn_rad_s);
        return actions;
      })
      .def_property_readonly("coding", [](const learning::TileQ& q) { return q.coding().def(); })
      .def("greedy", py::overload_cast<double, double, double>(&learning::TileQ::greedy, py::const_),
           "The greedy action for a robot-relative target (ties: lowest index).")
      .def("values", [](const learning::TileQ& q, double x, double y, double heading) {
        std::vector<int> cells(static_cast<size_t>(q.coding().def().tilings));
        q.coding().active(x, y, heading, cells.data());
        std::vector<double> values;
        for (int a = 0; a < q.action_count(); ++a) values.push_back(q.value(cells, a));
        return values;
      });

  py::class_<learning::SarsaLambdaDef>(m, "SarsaLambdaDef")
      .def(py::init<>())
      .def_readwrite("alpha", &learning::SarsaLambdaDef::alpha)
      .def_readwrite("lambda_", &learning::SarsaLambdaDef::lambda)
      .def_readwrite("gamma", &learning::SarsaLambdaDef::gamma)
      .def_readwrite("trace_cutoff", &learning::SarsaLambdaDef::trace_cutoff);

  py::class_<learning::SarsaLambda>(m, "SarsaLambda")
      .def(py::init<learning::TileQ&, const learning::SarsaLambdaDef&, uint64_t>(), py::keep_alive<1, 2>(),
           py::arg("q"), py::arg("definition"), py::arg("seed"))
      .def("episode",
           [](learning::SarsaLambda& learner, learning::SingleRobotSim& sim, const Pose& start, const Pose& target,
              double epsilon, double distance_mm, double heading_rad, int max_frames, uint64_t sim_seed) {
             const auto r = learner.episode(sim, as_pose(start), as_pose(target), epsilon,
                                            episode_def(distance_mm, heading_rad, max_frames), sim_seed);
             return std::make_pair(r.frames, r.success);
           },
           py::arg("sim"), py::arg("start"), py::arg("target"), py::arg("epsilon"), py::arg("success_distance_mm"),
           py::arg("success_heading_rad"), py::arg("max_frames"), py::arg("sim_seed"),
           "One learning episode; returns (frames, reached).")
      .def("set_alpha", &learning::SarsaLambda::set_alpha, "A new step size from now on.");

  m.def("greedy_episode",
        [](const learning::TileQ& q, learning::SingleRobotSim& sim, const Pose& start, const Pose& target,
           double distance_mm, double heading_rad, int max_frames, uint64_t sim_seed) {
          const auto r = learning::greedy_episode(q, sim, as_pose(start), as_pose(target),
                                                  episode_def(distance_mm, heading_rad, max_frames), sim_seed);
          return std::make_pair(r.frames, r.success);
        },
        py::arg("q"), py::arg("sim"), py::arg("start"), py::arg("target"), py::arg("success_distance_mm"),
        py::arg("success_heading_rad"), py::arg("max_frames"), py::arg("sim_seed"),
        "The greedy policy's episode, nothing learned; returns (frames, reached).");
}

} // namespace
