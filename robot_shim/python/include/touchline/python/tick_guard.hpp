#pragma once
// TickGuard: interrupts Python code that runs too long, or that runs when the process is
// asked to stop. robot_shim embeds Python with its signal handlers off, and its own
// SIGTERM handler only sets a flag that nobody reads while Python runs, so a tick() that
// loops forever (`while True: pass`) or blocks (`time.sleep(1e9)`) could only be ended
// with SIGKILL, and hot reload never got the chance to load the fix.
//
// How: a POSIX timer aimed at the interpreter's main thread sends SIGUSR1 once the guarded
// code has run `timeout_us` of wall time, and every quarter of that after. SIGUSR1 goes to
// Python's own C-level handler, which wakes a blocking call (sleep, select, a lock) with
// EINTR and makes the interpreter run the Python-level handler installed here at its next
// bytecode; that handler raises touchline.TickTimeout in the guarded code, or
// touchline.Stopping once request_stop() was called. Both derive from BaseException, like
// KeyboardInterrupt, so that `except Exception:` in a behaviour does not swallow them; a
// behaviour that swallows them anyway is interrupted again a quarter timeout later.
//
// Nothing here acts on code that has not run past its bound: a tick that stays within it
// sees no signal, so a match stays deterministic. Time the process spends stopped
// (SIGSTOP ... SIGCONT) does not count: SIGCONT gives the guarded code a fresh timeout.
//
// Works on the interpreter's main thread only (where Python runs signal handlers, and
// where robot_shim runs its behaviour); a TickGuard on any other thread guards nothing.
#include <cstdint>

namespace pybind11 {
class error_already_set;
}

namespace touchline::python {

/// Sets up the timer and the handlers (SIGUSR1 in Python, SIGCONT): once per process, on
/// the interpreter's main thread with the GIL held; later calls do nothing. Throws
/// std::runtime_error when the timer cannot be made.
void install_tick_guard();

/// While alive, the Python code this thread runs is interrupted (touchline.TickTimeout)
/// once it has run `timeout_us` of wall time, and at once with touchline.Stopping after
/// request_stop(). timeout_us <= 0: only the stop request interrupts. Not nestable.
class TickGuard {
 public:
  explicit TickGuard(int64_t timeout_us);
  ~TickGuard();
  TickGuard(const TickGuard&) = delete;
  TickGuard& operator=(const TickGuard&) = delete;

 private:
  bool armed_ = false;
};

/// Asks guarded Python code to stop (touchline.Stopping), now and from then on.
/// Async-signal-safe: for a SIGTERM handler.
void request_stop() noexcept;
bool stop_requested() noexcept;

/// Whether `error` is the TickTimeout or the Stopping raised by a TickGuard.
bool is_tick_timeout(const pybind11::error_already_set& error);
bool is_stopping(const pybind11::error_already_set& error);

} // namespace touchline::python
