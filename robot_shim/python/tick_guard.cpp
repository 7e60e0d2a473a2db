#include "touchline/python/tick_guard.hpp"

#include <pthread.h>
#include <signal.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <pybind11/embed.h>

namespace py = pybind11;

namespace touchline::python {

namespace {

/// Sent by the timer (and by request_stop) to the interpreter's main thread. Python's
/// own handler receives it; ours (below) runs as Python code.
constexpr int kInterruptSignal = SIGUSR1;

// Shared with signal handlers: lock-free atomics only.
std::atomic<bool> g_installed{false};
std::atomic<bool> g_stop{false};
std::atomic<bool> g_guarding{false};        ///< a TickGuard is alive
std::atomic<int64_t> g_timeout_ns{0};       ///< its timeout (0: none)
std::atomic<int64_t> g_deadline_ns{0};      ///< when its code is overdue (monotonic)
static_assert(std::atomic<int64_t>::is_always_lock_free, "used from signal handlers");

pid_t g_main_tid = 0;        ///< the interpreter's main thread (the timer's target)
pthread_t g_main_thread{};
timer_t g_timer{};
PyObject* g_timeout_type = nullptr; ///< touchline.TickTimeout, owned for the process
PyObject* g_stopping_type = nullptr; ///< touchline.Stopping

int64_t now_ns() noexcept { // clock_gettime is async-signal-safe
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec;
}

timespec to_timespec(int64_t ns) { return timespec{static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)}; }

/// First expiry after `first_ns`, then every quarter timeout (at least 1 ms): a behaviour
/// that swallows the exception is interrupted again. 0 disarms.
void set_timer(int64_t first_ns, int64_t period_ns) noexcept { // timer_settime is async-signal-safe
  itimerspec spec{};
  spec.it_value = to_timespec(first_ns);
  spec.it_interval = to_timespec(first_ns > 0 ? period_ns : 0);
  timer_settime(g_timer, 0, &spec, nullptr);
}

int64_t period_of(int64_t timeout_ns) { return timeout_ns / 4 > 1000000 ? timeout_ns / 4 : 1000000; }

/// SIGCONT: the process was stopped; the guarded code gets a fresh timeout from now.
void on_continue(int) {
  const int saved_errno = errno;
  const int64_t timeout = g_timeout_ns.load();
  if (g_guarding.load() && timeout > 0) {
    g_deadline_ns.store(now_ns() + timeout);
    set_timer(timeout, period_of(timeout));
  }
  errno = saved_errno;
}

/// The Python-level handler of kInterruptSignal: runs between bytecodes of whatever Python
/// code the main thread runs, and raises there if that code is guarded and overdue or
/// asked to stop. Called late (after the guard ended) it does nothing.
void on_interrupt(int, py::object /*frame*/) {
  if (!g_guarding.load()) return;
  if (g_stop.load()) {
    PyErr_SetString(g_stopping_type, "robot_shim is stopping (SIGTERM or SIGINT)");
    throw py::error_already_set();
  }
  const int64_t timeout = g_timeout_ns.load();
  const int64_t now = now_ns();
  if (timeout <= 0 || now < g_deadline_ns.load()) return;
  g_deadline_ns.store(now + period_of(timeout)); // again a quarter timeout later, if swallowed
  PyErr_SetString(g_timeout_type, ("ran longer than " + std::to_string(timeout / 1000000) +
                                   " ms of wall time (robot_shim --tick-timeout-ms); interrupted")
                                      .c_str());
  throw py::error_already_set();
}

/// At interpreter shutdown: Python restores SIGUSR1's default action (termination), so
/// the timer must never fire again, and the exception types are gone. A later interpreter
/// installs afresh.
void uninstall() {
  g_installed.store(false);
  g_guarding.store(false);
  timer_delete(g_timer);
  g_timeout_type = g_stopping_type = nullptr;
}

bool on_interpreter_main_thread() {
  const auto main_ident = py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
  return main_ident == PyThread_get_thread_ident();
}

bool is_guarding_thread() {
  thread_local const pid_t tid = static_cast<pid_t>(syscall(SYS_gettid)); // one system call per thread
  return g_installed.load() && tid == g_main_tid;
}

} // namespace

void install_tick_guard() {
  if (g_installed.load() || !on_interpreter_main_thread()) return;
  g_timeout_type = PyErr_NewExceptionWithDoc(
      "touchline.TickTimeout", "Raised in Python code that ran longer than robot_shim --tick-timeout-ms.",
      PyExc_BaseException, nullptr);
  g_stopping_type = PyErr_NewExceptionWithDoc("touchline.Stopping", "Raised in Python code when robot_shim stops.",
                                              PyExc_BaseException, nullptr);
  if (!g_timeout_type || !g_stopping_type) throw py::error_already_set();

  g_main_tid = static_cast<pid_t>(syscall(SYS_gettid));
  g_main_thread = pthread_self();
  sigevent event{};
  event.sigev_notify = SIGEV_THREAD_ID; // to this thread, not to whichever the kernel picks
  event.sigev_signo = kInterruptSignal;
  event._sigev_un._tid = g_main_tid;
  if (timer_create(CLOCK_MONOTONIC, &event, &g_timer) != 0)
    throw std::runtime_error(std::string("cannot create the tick timer: ") + std::strerror(errno));

  // Python's handler for the signal: the interpreter then calls on_interrupt as Python code.
  py::module_::import("signal").attr("signal")(kInterruptSignal, py::cpp_function(&on_interrupt));
  struct sigaction action {};
  action.sa_handler = on_continue;
  action.sa_flags = SA_RESTART;
  sigemptyset(&action.sa_mask);
  sigaction(SIGCONT, &action, nullptr);
  Py_AtExit(&uninstall);
  g_installed.store(true);
}

TickGuard::TickGuard(int64_t timeout_us) {
  if (!is_guarding_thread()) return;
  armed_ = true;
  const int64_t timeout = timeout_us > 0 ? timeout_us * 1000 : 0;
  g_timeout_ns.store(timeout);
  g_deadline_ns.store(now_ns() + timeout);
  g_guarding.store(true);
  if (timeout > 0) set_timer(timeout, period_of(timeout));
  // A stop asked for just before the guard: interrupt at once rather than after the timeout.
  if (g_stop.load()) pthread_kill(g_main_thread, kInterruptSignal);
}

TickGuard::~TickGuard() {
  if (!armed_) return;
  g_guarding.store(false);
  set_timer(0, 0);
}

void request_stop() noexcept {
  g_stop.store(true);
  // pthread_kill is async-signal-safe; the signal wakes the main thread if Python blocks.
  if (g_installed.load() && g_guarding.load()) pthread_kill(g_main_thread, kInterruptSignal);
}

bool stop_requested() noexcept { return g_stop.load(); }

bool is_tick_timeout(const py::error_already_set& error) {
  return g_timeout_type && error.matches(g_timeout_type);
}

bool is_stopping(const py::error_already_set& error) { return g_stopping_type && error.matches(g_stopping_type); }

} // namespace touchline::python
