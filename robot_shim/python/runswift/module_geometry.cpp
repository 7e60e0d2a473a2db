// AbsCoord, RRCoord and the Python-side helpers their code calls (say, floatArray_frompointer).
#include <iostream>

#include <pybind11/stl.h>

#include "touchline/python/runswift/module.hpp"
#include "touchline/python/runswift/types.hpp"

namespace py = pybind11;

namespace touchline::python::runswift {

namespace {

/// Their covariance converter's shape: a tuple of the three columns.
py::tuple columns(const Matrix3& m) {
  return py::make_tuple(py::make_tuple(m[0], m[3], m[6]), py::make_tuple(m[1], m[4], m[7]),
                        py::make_tuple(m[2], m[5], m[8]));
}

} // namespace

void define_geometry(py::module_& m) {
  py::class_<AbsCoord>(m, "AbsCoord", "field (or robot-relative cartesian) pose: x, y mm, theta rad")
      .def(py::init<>())
      .def(py::init([](float x, float y, float theta) { return AbsCoord{x, y, theta}; }))
      .def_property_readonly("x", [](const AbsCoord& c) { return c.x; })
      .def_property_readonly("y", [](const AbsCoord& c) { return c.y; })
      .def_property_readonly("theta", [](const AbsCoord& c) { return c.theta; })
      .def_readonly("weight", &AbsCoord::weight)
      .def_property_readonly("var", [](const AbsCoord& c) { return columns(c.var); })
      .def("__repr__", [](const AbsCoord& c) {
        return "AbsCoord(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ", " + std::to_string(c.theta) + ")";
      });
  py::class_<RRCoord>(m, "RRCoord", "robot-relative polar position: distance mm, heading rad (+ left)")
      .def(py::init<>())
      .def(py::init([](float distance, float heading, float orientation) {
             return RRCoord{distance, heading, orientation};
           }),
           py::arg("distance"), py::arg("heading") = 0.f, py::arg("orientation") = 0.f)
      .def_property_readonly("distance", [](const RRCoord& c) { return c.distance; })
      .def_property_readonly("heading", [](const RRCoord& c) { return c.heading; })
      .def_property_readonly("orientation", [](const RRCoord& c) { return c.orientation; })
      .def_property_readonly("var", [](const RRCoord& c) { return columns(c.var); })
      .def("__repr__", [](const RRCoord& c) {
        return "RRCoord(" + std::to_string(c.distance) + ", " + std::to_string(c.heading) + ")";
      });

  // On the robot a SWIG helper turned a C array into something indexable; ours are lists already.
  m.def("floatArray_frompointer", [](py::object array) { return array; }, py::arg("array"));
  // Text to speech on the robot: a line on the shim's stderr here.
  m.def(
      "say",
      [](const std::string& text) {
        const py::module_ self = py::module_::import(kModuleName);
        const int team = py::hasattr(self, "team") ? self.attr("team").cast<int>() : 0;
        const int player = py::hasattr(self, "player") ? self.attr("player").cast<int>() : 0;
        std::cerr << "robot_shim " << team << "/" << player << " says: " << text << std::endl;
      },
      py::arg("text"));
}

} // namespace touchline::python::runswift
