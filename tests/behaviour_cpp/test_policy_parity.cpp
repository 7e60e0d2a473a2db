// The learned walker picks the same action in both ports: the embedded Python
// (behaviour_py/skills/tile_policy.py, learned_go_to_pose.py, ball.py) and the C++ port
// compute the same features, the same Q values bit for bit and the same greedy action for
// thousands of states, tile edges included, on a policy of the trained policy's size with
// pseudo-random weights (the tests never depend on the trained weights).
#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "skills/policy_files.hpp"
#include "touchline/behaviour/skills/ball.hpp"
#include "touchline/behaviour/skills/learned_go_to_pose.hpp"
#include "touchline/behaviour/skills/tile_policy.hpp"
#include "touchline/python/robot_module.hpp"

PYBIND11_EMBEDDED_MODULE(robot, m) { touchline::python::define_robot_module(m); }

namespace py = pybind11;
using namespace touchline::behaviour::skills;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Deterministic uniform numbers (64-bit LCG), the same on every machine.
class Numbers {
 public:
  double uniform(double low, double high) {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;
    return low + (high - low) * static_cast<double>(state_ >> 11) / 9007199254740992.0;
  }

 private:
  uint64_t state_ = 42;
};

/// A policy file with the trained policy's shape (8 tilings of 10 x 16 x 16, 11 actions)
/// and pseudo-random weights in [-1, 1].
std::string randomPolicyText() {
  Numbers numbers;
  std::string text =
      "touchline-policy 1\nfeatures polar-log\ndistance_scale_mm 100\nmax_distance_mm 12000\ntilings 8\n"
      "tiles 10 16 16\nsuccess_distance_mm 50\nsuccess_heading_rad 0.17453\nactions 11\n";
  for (int a = 0; a < 11; ++a) text += "action " + std::to_string(30 * a) + " " + std::to_string(a - 5) + " 0.25\n";
  const int count = 8 * 11 * 16 * 16 * 11;
  text += "weights " + std::to_string(count) + "\n";
  char number[32];
  for (int i = 0; i < count; ++i) {
    std::snprintf(number, sizeof number, "%.9g%s", numbers.uniform(-1, 1), i % 8 == 7 ? "\n" : " ");
    text += number;
  }
  return text;
}

struct State {
  float robotX, robotY, robotTheta; ///< the Blackboard's pose: float, as both ports read it
  double x, y, theta;               ///< the target, field frame
};

/// Random states, and states on tile edges: targets straight ahead, behind, beside, on the
/// robot, far beyond max_distance_mm, and heading errors on the heading tiles' edges.
std::vector<State> states() {
  Numbers numbers;
  std::vector<State> all;
  for (int i = 0; i < 4000; ++i) {
    const auto robot = [&] {
      return State{static_cast<float>(numbers.uniform(-4500, 4500)), static_cast<float>(numbers.uniform(-3000, 3000)),
                   static_cast<float>(numbers.uniform(-kPi, kPi)), 0, 0, 0};
    };
    State s = robot();
    s.x = numbers.uniform(-4500, 4500);
    s.y = numbers.uniform(-3000, 3000);
    s.theta = numbers.uniform(-2 * kPi, 2 * kPi);
    all.push_back(s);
    s = robot();
    s.x = s.robotX + numbers.uniform(-300, 300); // near: the success tolerances
    s.y = s.robotY + numbers.uniform(-300, 300);
    s.theta = s.robotTheta + numbers.uniform(-0.5, 0.5);
    all.push_back(s);
  }
  for (int j = -16; j <= 16; ++j) {
    const double edge = j * kPi / 8; // heading tile edges (16 tiles) and bearings along the axes
    for (const double distance : {0.0, 1.0, 49.0, 50.0, 1000.0, 12000.0, 50000.0})
      all.push_back({0.f, 0.f, 0.f, distance * std::cos(edge), distance * std::sin(edge), edge});
    all.push_back({0.f, 0.f, static_cast<float>(edge), 1000.0, 0.0, 0.0});
  }
  return all;
}

class PolicyParity : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!Py_IsInitialized()) interpreter_ = std::make_unique<py::scoped_interpreter>(false, 0, nullptr, false);
    py::module_::import("sys").attr("path").attr("insert")(0, TOUCHLINE_BEHAVIOUR_PY);
  }
  static std::unique_ptr<py::scoped_interpreter> interpreter_;
};
std::unique_ptr<py::scoped_interpreter> PolicyParity::interpreter_;

} // namespace

TEST_F(PolicyParity, SameFeaturesQAndActionForEveryState) {
  const touchline::behaviour::test::TestDataDir data;
  const auto path = data.path() / "random.policy";
  touchline::behaviour::test::writePolicy(path, randomPolicyText());
  const TilePolicy cpp = loadPolicy(path.string());
  const py::object python = py::module_::import("skills.tile_policy").attr("loadPolicy")(path.string());
  const py::object relativeTargetPy = py::module_::import("skills.learned_go_to_pose").attr("relativeTarget");
  const py::object AbsCoord = py::module_::import("robot").attr("AbsCoord");

  int differences = 0, actions = 0;
  for (const State& s : states()) {
    const RelativeTarget t = relativeTarget({s.robotX, s.robotY, s.robotTheta}, s.x, s.y, s.theta);
    const auto tPy = relativeTargetPy(AbsCoord(s.robotX, s.robotY, s.robotTheta), s.x, s.y, s.theta)
                         .cast<std::vector<double>>();
    const auto indicesPy = python.attr("cellIndices")(t.x, t.y, t.theta).cast<std::vector<size_t>>();
    const auto qPy = python.attr("values")(t.x, t.y, t.theta).cast<std::vector<double>>();
    const auto actionPy = python.attr("greedyAction")(t.x, t.y, t.theta).cast<size_t>();
    const bool arrivedPy = python.attr("arrived")(t.x, t.y, t.theta).cast<bool>();
    const bool same = tPy == std::vector<double>{t.x, t.y, t.theta} && indicesPy == cpp.cellIndices(t.x, t.y, t.theta) &&
                      qPy == cpp.values(t.x, t.y, t.theta) && actionPy == cpp.greedyAction(t.x, t.y, t.theta) &&
                      arrivedPy == cpp.arrived(t.x, t.y, t.theta);
    if (!same && ++differences <= 5)
      ADD_FAILURE() << "robot (" << s.robotX << ", " << s.robotY << ", " << s.robotTheta << "), target (" << s.x
                    << ", " << s.y << ", " << s.theta << "): the ports differ";
    actions += 1;
  }
  EXPECT_EQ(differences, 0) << differences << " of " << actions << " states differ";
}

TEST_F(PolicyParity, SameTargetBehindTheBall) {
  const py::object pointBehindBallPy = py::module_::import("skills.ball").attr("pointBehindBall");
  const py::object AbsCoord = py::module_::import("robot").attr("AbsCoord");
  Numbers numbers;
  int differences = 0;
  for (int i = 0; i < 2000; ++i) {
    const touchline::api::AbsCoord ball{static_cast<float>(numbers.uniform(-4500, 4500)),
                                        static_cast<float>(numbers.uniform(-3000, 3000)), 0.f};
    const float goalX = i % 2 ? 3000.f : -3000.f, behind = i % 3 ? 200.f : 0.5f;
    const FieldPose cpp = pointBehindBallExact(ball, goalX, 0.f, behind);
    const auto python = pointBehindBallPy(AbsCoord(ball.x, ball.y, 0.f), double{goalX}, 0.0, double{behind})
                            .cast<std::vector<double>>();
    if (python != std::vector<double>{cpp.x, cpp.y, cpp.theta} && ++differences <= 5)
      ADD_FAILURE() << "ball (" << ball.x << ", " << ball.y << "): the ports differ";
  }
  EXPECT_EQ(differences, 0);
}
