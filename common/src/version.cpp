#include "touchline/version.hpp"

#include <iostream>

namespace touchline {

const char* version() { return TOUCHLINE_VERSION; }

bool version_requested(const boost::program_options::variables_map& vm, const std::string& program) {
  if (!vm.count("version")) return false;
  std::cout << program << " " << version() << "\n";
  return true;
}

} // namespace touchline
