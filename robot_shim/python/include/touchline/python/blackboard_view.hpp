#pragma once
// robot.Blackboard and its parts (robot.MotionBlackboard, ...): read-only views of the
// robot's Blackboard as behaviour code reads it every tick. Plain CPython types with one C
// getter per field, not pybind11 classes: reading a field costs a C call (tens of ns)
// instead of pybind11's dispatch (hundreds), and a part (blackboard.localisation) is made
// once per view, not on every access. What Python sees is as before: the same names and
// values, nothing writable, nested values (robotPos, request, ...) fresh copies on every
// read, robot.Blackboard() an empty board.
#include <pybind11/pybind11.h>

#include "touchline/robot_api/blackboard.hpp"

namespace touchline::python {

/// Adds robot.Blackboard, its part types and TeamMessage to `m` (after the enums and
/// AbsCoord, RRCoord, ActionCommand types they hand out are defined).
void define_blackboard_views(pybind11::module_& m);

/// A robot.Blackboard viewing `blackboard` itself (no copy): valid while `blackboard` lives,
/// i.e. for the tick it is handed to. Needs define_blackboard_views in this interpreter.
pybind11::object blackboard_view(const api::Blackboard& blackboard);

} // namespace touchline::python
