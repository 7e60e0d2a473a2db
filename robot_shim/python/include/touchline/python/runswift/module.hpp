#pragma once
// The `robot` module rUNSWift's behaviour code imports, in pybind11: its classes, enums
// (Python IntEnums, so that they index lists as their integers do), constants and
// functions, bound to the structs of types.hpp. Embedded in the shim under the name
// touchline_runswift_robot; the rUNSWift profile puts it in sys.modules as `robot` for
// its behaviour alone.
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include "touchline/robot/localisation/field_map.hpp"

namespace touchline::python::runswift {

/// The name the module is embedded under.
constexpr const char* kModuleName = "touchline_runswift_robot";

void define_runswift_module(pybind11::module_& m);

/// Sets FIELD_LENGTH, GOAL_BOX_WIDTH, BALL_RADIUS, ... on `m` from `field` (mm).
void set_field_constants(pybind11::module_& m, const robot::localisation::FieldMap& field);

/// A Python enum.IntEnum `name` on `m` with `members` (name, value).
pybind11::object int_enum(pybind11::module_& m, const char* name, const std::vector<std::pair<const char*, int>>& members);

// The parts of define_runswift_module, one file each.
void define_geometry(pybind11::module_& m);
void define_actions(pybind11::module_& m);
void define_blackboard(pybind11::module_& m);
void define_constants(pybind11::module_& m);

} // namespace touchline::python::runswift
