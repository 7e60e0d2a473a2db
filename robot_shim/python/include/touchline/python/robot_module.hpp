#pragma once
// The Python `robot` module: the robot API as Python behaviour code sees it (read-only
// Blackboard views, ActionCommand types, game-state constants, geometry helpers), in the
// robot's units (mm, rad). The shim embeds it; tests and tools import the same bindings
// built as an extension module.
#include <pybind11/pybind11.h>

namespace touchline::python {

void define_robot_module(pybind11::module_& m);

} // namespace touchline::python
