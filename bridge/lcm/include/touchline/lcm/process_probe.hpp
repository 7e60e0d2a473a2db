#pragma once
// Whether a process still runs on this machine, read from /proc. The world's lockstep waits
// longer for a robot whose robot_shim still runs (a busy machine, a debugger's breakpoint)
// than for one whose shim is gone, so that load does not change the match.
#include <string_view>

namespace touchline::transport {

/// True when process `pid` exists on this machine, has not exited (a zombie, not yet reaped,
/// has), and its command name (/proc/PID/comm: the program's file name, cut to 15
/// characters) is `name`, cut likewise. A stopped or traced process runs. False for a pid
/// <= 0 and wherever /proc cannot tell.
bool process_runs(int pid, std::string_view name);

} // namespace touchline::transport
