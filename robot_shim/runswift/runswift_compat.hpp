#pragma once
// What runswift_walk.cpp needs from the compatibility library: their walk's options, with
// their own defaults (their populate_options, built from the clone) and, optionally, one
// of their option files on top. Boost only: nothing of theirs in this header.
#include <string>

#include <boost/program_options/variables_map.hpp>

namespace touchline::robot::runswift {

/// Their options, defaults first, then `config_file` ("" for none). Throws
/// touchline::ConfigError "<file>: <why>" when the file cannot be read or parsed.
boost::program_options::variables_map options(const std::string& config_file);

} // namespace touchline::robot::runswift
