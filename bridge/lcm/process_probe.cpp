#include "touchline/lcm/process_probe.hpp"

#include <cstddef>
#include <fstream>
#include <iterator>
#include <string>

namespace touchline::transport {

namespace {

/// The kernel keeps a command name's first 15 characters (TASK_COMM_LEN less its NUL).
constexpr std::size_t kCommLength = 15;

} // namespace

bool process_runs(int pid, std::string_view name) {
  if (pid <= 0) return false;
  // "PID (COMM) STATE ...": COMM may hold spaces and parentheses, so it ends at the last ')'.
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  const std::string line((std::istreambuf_iterator<char>(stat)), std::istreambuf_iterator<char>());
  const std::size_t open = line.find('('), close = line.rfind(')');
  if (open == std::string::npos || close == std::string::npos || close < open || close + 2 >= line.size())
    return false;
  const char state = line[close + 2];
  const bool exited = state == 'Z' || state == 'X' || state == 'x';
  return !exited && std::string_view(line).substr(open + 1, close - open - 1) == name.substr(0, kCommLength);
}

} // namespace touchline::transport
