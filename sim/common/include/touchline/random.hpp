#pragma once
// Random draws every model shares. Not std:: distributions: their algorithms differ between
// standard libraries, and a seed must give the same match everywhere.
#include <cstdint>
#include <random>

namespace touchline {

/// Uniform in [0, 1) from the top 53 bits of one draw.
inline double uniform01(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

} // namespace touchline
