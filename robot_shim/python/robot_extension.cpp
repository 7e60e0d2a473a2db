// The `robot` module as a Python extension, for behaviour tests and host tools. The shim
// embeds the same bindings instead (python_behaviour.cpp).
#include "touchline/python/robot_module.hpp"

PYBIND11_MODULE(robot, m) { touchline::python::define_robot_module(m); }
