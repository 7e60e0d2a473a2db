#pragma once
// Every program's --version: "sim_world 0.9.0". The number is the VERSION file at the
// source root (CMake's project() reads it), the one source the Python tools read too.
#include <string>

#include <boost/program_options.hpp>

namespace touchline {

/// The project's version, e.g. "0.9.0".
const char* version();

/// True, after printing "<program> <version>" to stdout, when --version was given. The
/// option itself is one line in each program's add_options: ("version", kVersionHelp).
bool version_requested(const boost::program_options::variables_map& vm, const std::string& program);

constexpr const char* kVersionHelp = "print the program's name and version and exit";

} // namespace touchline
