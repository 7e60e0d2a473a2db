#include "touchline/python/python_behaviour.hpp"

#include <sys/stat.h>

#include <chrono>
#include <initializer_list>
#include <iostream>
#include <sstream>

#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include "touchline/python/blackboard_view.hpp"
#include "touchline/python/python_profile.hpp"
#include "touchline/python/robot_module.hpp"
#include "touchline/python/tick_guard.hpp"

namespace py = pybind11;

// `import robot` inside the shim: the same bindings as the extension module, built in.
// Built-in modules come before sys.path, so a robot.py or robot.so there never shadows it.
PYBIND11_EMBEDDED_MODULE(robot, m) { touchline::python::define_robot_module(m); }

namespace touchline::python {

namespace AC = api::ActionCommand;

api::ActionCommand::All error_request() {
  AC::All request;
  request.body = AC::stand();
  request.leds.chest = kErrorChestLed;
  return request;
}

namespace {

/// The PythonBehaviour whose modules and robot.params are in sys.modules and `robot` now.
PythonBehaviour* g_active = nullptr;

/// sys.modules's keys (a frozenset) while its version tag is `version`: robots swapping in
/// turn find sys.modules as the last one left it, so a swap need not copy every name (~10 %
/// of a 4 v 4 match's CPU did). Replaced when the tag differs; never changed in place.
struct ModuleNames {
  py::object names;
  uint64_t version = 0;
};
ModuleNames g_names_without_robots;

int64_t to_ns(const timespec& t) { return static_cast<int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec; }

/// Whether a sys.modules entry was loaded from under `prefix` (a directory ending in '/').
/// String prefixes suffice: modules found through our sys.path entry carry its spelling.
bool loaded_from(py::handle module, const std::string& prefix) {
  auto under = [&](py::handle path) {
    return py::isinstance<py::str>(path) && path.cast<std::string>().compare(0, prefix.size(), prefix) == 0;
  };
  try {
    if (py::hasattr(module, "__file__") && under(module.attr("__file__"))) return true;
    if (py::hasattr(module, "__path__")) // packages, namespace packages included
      for (py::handle entry : module.attr("__path__"))
        if (under(entry)) return true;
  } catch (const py::error_already_set&) {
    // not a module we know how to read: not ours
  }
  return false;
}

/// A dict's version tag (CPython 3.11: a global counter's value, new at every change of
/// the dict), or 0 where there is none to read.
uint64_t dict_version(py::handle dict) {
#if PY_VERSION_HEX >= 0x030B0000 && PY_VERSION_HEX < 0x030C0000
  return reinterpret_cast<PyDictObject*>(dict.ptr())->ma_version_tag;
#else
  (void)dict;
  return 0;
#endif
}

/// Names of the sys.modules entries loaded from under `prefix`.
py::list module_names_under(const py::module_& sys, const std::string& prefix) {
  py::list names;
  for (auto [name, module] : py::dict(sys.attr("modules")))
    if (loaded_from(module, prefix)) names.append(name);
  return names;
}

std::string type_name(py::handle value) {
  if (value.is_none()) return "None";
  const py::handle type = py::type::handle_of(value);
  const auto qualname = type.attr("__qualname__").cast<std::string>();
  const auto module = type.attr("__module__").cast<std::string>();
  return module == "builtins" ? qualname : module + "." + qualname;
}

/// Touchline's own: the robot API module, the const Blackboard, a robot.All back.
class TouchlineProfile final : public PythonProfile {
 public:
  py::module_ robot_module() override { return py::module_::import("robot"); }
  py::object argument(const api::Blackboard& blackboard) override {
    return blackboard_view(blackboard);
  }
  AC::All request(py::handle result, const api::Blackboard&) override {
    if (!py::isinstance<AC::All>(result))
      throw RequestError("tick() returned " + type_name(result) + ", expected robot.All");
    return result.cast<AC::All>();
  }
};

} // namespace

std::shared_ptr<PythonProfile> touchline_profile() { return std::make_shared<TouchlineProfile>(); }

bool PythonBehaviour::FileStamp::operator==(const FileStamp& other) const {
  return mtime_ns == other.mtime_ns && ctime_ns == other.ctime_ns && size == other.size;
}

PythonBehaviour::Files PythonBehaviour::scan_python_files(const std::filesystem::path& directory) {
  namespace fs = std::filesystem;
  Files files;
  std::error_code ec;
  fs::recursive_directory_iterator it(directory, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const fs::path& path = it->path();
    const std::string name = path.filename().string();
    std::error_code type_ec;
    if (it->is_directory(type_ec)) {
      if (name == "__pycache__" || name.front() == '.') it.disable_recursion_pending();
      continue;
    }
    struct stat st {};
    if (path.extension() != ".py" || name.front() == '.' || ::stat(path.c_str(), &st) != 0) continue;
    files[path.string()] = {to_ns(st.st_mtim), to_ns(st.st_ctim), static_cast<uintmax_t>(st.st_size)};
  }
  return files;
}

/// The interpreter objects one PythonBehaviour holds. Hidden, like pybind11's own types.
struct __attribute__((visibility("hidden"))) PythonBehaviour::Python {
  py::module_ sys, robot, traceback, importlib;
  py::dict params;         ///< robot.params while this behaviour runs
  py::object team, player; ///< robot.team and robot.player while this behaviour runs
  py::str directory;       ///< the directory, first on sys.path while this behaviour runs
  py::dict stashed;        ///< this behaviour's modules while another PythonBehaviour runs
  /// While it runs: the names it brought back, and every name in sys.modules as it did.
  /// Its modules are among those and the names added since, so stash() need not look at
  /// every module of the process (a scan of them all cost ~0.5 ms a swap, with numpy loaded).
  /// The modules it brought back (name -> module); sys.modules's keys as they were are
  /// these, "robot" and `names_before` (the keys before it came in, a shared frozenset).
  py::dict restored;
  py::object names_before;
  /// Whether taking `restored` back out leaves exactly `names_before` ("robot" among them,
  /// none of `restored`'s names): then stash() keeps the shared snapshot current.
  bool names_before_kept = false;
  /// sys.modules's version tag after activate(): unchanged at stash(), the modules to take
  /// out are exactly those brought back (no set of every name needed, the common case).
  uint64_t modules_version = 0;
  py::object module, tick; ///< null while the module failed to load

  /// After the interpreter has gone, handles must be dropped without touching it.
  void abandon() {
    for (py::object* o : std::initializer_list<py::object*>{&sys, &robot, &traceback, &importlib, &params,
                                                            &stashed, &restored, &names_before, &module, &tick,
                                                            &team, &player, &directory})
      o->release();
  }
};

PythonBehaviour::PythonBehaviour(PythonBehaviourDef def) : def_(std::move(def)) {
  if (!Py_IsInitialized())
    throw PythonBehaviourError("the Python behaviour needs a running interpreter (pybind11::scoped_interpreter)");
  std::error_code ec;
  const auto directory = std::filesystem::canonical(def_.directory, ec);
  if (ec || !std::filesystem::is_directory(directory))
    throw PythonBehaviourError("python dir '" + def_.directory.string() + "' is not a directory");
  def_.directory = directory;
  prefix_ = directory.string() + "/";
  if (def_.module.empty()) throw PythonBehaviourError("empty Python module name");
  if (!def_.profile) def_.profile = touchline_profile();

  py_ = std::make_unique<Python>();
  try {
    py_->sys = py::module_::import("sys");
    def_.profile->prepare(def_.directory.string());
    py_->robot = def_.profile->robot_module();
    py_->traceback = py::module_::import("traceback");
    py_->importlib = py::module_::import("importlib.machinery");
    // No .pyc from us: its freshness check uses whole seconds, so a second edit within
    // the same second (of the same size) would load the stale bytecode on reload.
    py_->sys.attr("dont_write_bytecode") = true;
    for (const auto& [key, value] : def_.params) py_->params[py::str(key)] = py::str(value);
    py_->team = py::int_(def_.team);
    py_->player = py::int_(def_.player);
    py_->directory = py::str(def_.directory.string());
    activate();
    // The module must come from the directory, not from anywhere else on sys.path.
    if (!module_present() && def_.profile->module_required())
      throw PythonBehaviourError("no Python module '" + def_.module + "' in " + def_.directory.string());
  } catch (const py::error_already_set& e) {
    leave();
    throw PythonBehaviourError(std::string("cannot start the Python behaviour: ") + e.what());
  } catch (...) {
    leave();
    throw;
  }

  files_ = scan_python_files(def_.directory);
  next_check_us_ = now_us() + def_.reload_check_interval_us;
  try {
    install_tick_guard();
    const TickGuard guard(def_.tick_timeout_us); // a module that hangs at import
    healthy_ = load(/*starting=*/true);
  } catch (const py::error_already_set& e) { // touchline.Stopping: the shim is stopping anyway
    leave();
    throw PythonBehaviourError(std::string("cannot start the Python behaviour: ") + e.what());
  } catch (const std::runtime_error& e) {
    leave();
    throw PythonBehaviourError(std::string("cannot start the Python behaviour: ") + e.what());
  }
  if (py_->module && !py_->tick) { // imported cleanly but cannot be ticked: a usage error
    leave();
    throw PythonBehaviourError("Python module '" + def_.module + "' has no tick(blackboard) function");
  }
  if (healthy_) check_params();
}

void PythonBehaviour::check_params() {
  // A module's optional check_params(params) judges robot.params before the match, as a C++
  // behaviour's factory does: a wrong parameter is a usage error now, not a standing robot.
  if (!py::hasattr(py_->module, "check_params") || !PyCallable_Check(py_->module.attr("check_params").ptr()))
    return;
  try {
    const TickGuard guard(def_.tick_timeout_us);
    py_->module.attr("check_params")(py_->params);
  } catch (const py::error_already_set& e) {
    leave();
    if (is_stopping(e)) throw PythonBehaviourError("stopped while checking the Python behaviour's parameters");
    if (is_tick_timeout(e)) throw PythonBehaviourError("Python module '" + def_.module + "': check_params() timed out");
    // The exception's own message is the user's line (e.g. "Team: unknown parameter 'x'").
    std::string message = py::str(e.value());
    message = message.substr(0, message.find('\n'));
    throw PythonBehaviourError(message.empty() ? "Python module '" + def_.module + "': check_params() raised " +
                                                     std::string(py::str(e.type().attr("__name__")))
                                               : message);
  } catch (const std::runtime_error& e) { // the tick guard could not be set up
    leave();
    throw PythonBehaviourError(std::string("cannot check the Python behaviour's parameters: ") + e.what());
  }
}

PythonBehaviour::~PythonBehaviour() {
  if (!Py_IsInitialized()) { // destroyed after the interpreter: nothing left to tidy
    py_->abandon();
    g_names_without_robots.names.release();
    if (g_active == this) g_active = nullptr;
    return;
  }
  try {
    leave();
  } catch (const std::exception&) {
    if (g_active == this) g_active = nullptr; // tidying failed; never throw from here
  }
}

void PythonBehaviour::activate() {
  if (g_active == this) return;
  if (g_active) g_active->stash();
  py::dict modules = py_->sys.attr("modules");
  const uint64_t version_before = dict_version(modules);
  if (version_before == 0 || version_before != g_names_without_robots.version || !g_names_without_robots.names) {
    g_names_without_robots.names = py::reinterpret_steal<py::object>(PyFrozenSet_New(modules.ptr()));
    if (!g_names_without_robots.names) throw py::error_already_set();
    g_names_without_robots.version = version_before;
  }
  py_->names_before = g_names_without_robots.names;
  // Whether none of its names were there and "robot" was: sizes tell, without a lookup each.
  const Py_ssize_t size_before = PyDict_GET_SIZE(modules.ptr());
  for (auto [name, module] : py_->stashed) modules[name] = module;
  const Py_ssize_t size_restored = PyDict_GET_SIZE(modules.ptr());
  modules["robot"] = py_->robot; // this behaviour's framework's `robot`
  py_->names_before_kept = size_restored - size_before == PyDict_GET_SIZE(py_->stashed.ptr()) &&
                           PyDict_GET_SIZE(modules.ptr()) == size_restored;
  py_->restored = std::move(py_->stashed);
  py_->stashed = py::dict();
  py_->robot.attr("params") = py_->params;
  py_->robot.attr("team") = py_->team;
  py_->robot.attr("player") = py_->player;
  // First on sys.path, so that a reload finds this directory's modules before others'.
  py::list path = py_->sys.attr("path");
  const py::str& dir = py_->directory;
  // Most often it is first and nowhere else already (robots of one directory in turn).
  PyObject* first = PyList_GET_SIZE(path.ptr()) > 0 ? PyList_GET_ITEM(path.ptr(), 0) : nullptr;
  const bool placed = first && PyUnicode_Check(first) && PyUnicode_Compare(first, dir.ptr()) == 0 &&
                      PySequence_Count(path.ptr(), dir.ptr()) == 1;
  if (PyErr_Occurred()) throw py::error_already_set();
  if (!placed) {
    while (path.contains(dir)) path.attr("remove")(dir);
    path.insert(0, dir);
  }
  py_->modules_version = dict_version(modules);
  g_active = this;
}

void PythonBehaviour::stash() {
  py::dict modules = py_->sys.attr("modules");
  // Its modules: those it brought back and those loaded since (imports, reloads) from its directory.
  const uint64_t version = dict_version(modules);
  if (version != 0 && version == py_->modules_version) { // untouched since activate()
    for (auto [name, module] : py_->restored)
      if (PyDict_DelItem(modules.ptr(), name.ptr()) != 0) throw py::error_already_set();
    py_->stashed = std::move(py_->restored);
    // sys.modules holds `names_before` again: the next robot to come in need not copy them.
    if (py_->names_before_kept && py_->names_before.is(g_names_without_robots.names))
      g_names_without_robots.version = dict_version(modules);
  } else {
    py::list candidates(py_->restored.attr("keys")());
    py::set at_activate(py_->names_before);
    for (auto item : py_->restored) at_activate.add(item.first);
    at_activate.add(py::str("robot"));
    for (py::handle name : py::set(modules).attr("difference")(at_activate)) candidates.append(name);
    for (py::handle name : candidates)
      if (modules.contains(name) && loaded_from(modules[name], prefix_))
        py_->stashed[name] = modules.attr("pop")(name);
  }
  py_->restored = py::dict();
  py_->names_before = py::object();
  g_active = nullptr;
}

void PythonBehaviour::leave() {
  if (g_active == this) stash();
  g_names_without_robots = ModuleNames{}; // none held past the last robot (nor the interpreter)
  py_->stashed = py::dict();
  py::list path = py_->sys.attr("path");
  const py::str dir(def_.directory.string());
  if (path.contains(dir)) path.attr("remove")(dir);
}

int64_t PythonBehaviour::now_us() const {
  if (def_.wall_clock_us) return def_.wall_clock_us();
  using namespace std::chrono;
  return duration_cast<microseconds>(steady_clock::now().time_since_epoch()).count();
}

bool PythonBehaviour::module_present() const {
  const std::string top = def_.module.substr(0, def_.module.find('.'));
  py::list search_path;
  search_path.append(py::str(def_.directory.string()));
  return !py_->importlib.attr("PathFinder").attr("find_spec")(top, search_path).is_none();
}

bool PythonBehaviour::load(bool starting) {
  py_->module = py::object();
  py_->tick = py::object();
  if (!def_.profile->module_required() && !module_present()) { // one line instead of a traceback
    report_once("no " + def_.module + ".py (nor package " + def_.module + "/) in " + def_.directory.string(), nullptr);
    return false;
  }
  try {
    // Through the C API, which cuts importlib's own frames from the traceback.
    py_->module = py::module_::import(def_.module.c_str());
  } catch (const py::error_already_set& e) {
    if (is_stopping(e)) throw; // not the module's fault
    report_once("importing " + def_.module + " failed", &e);
    return false;
  }
  if (py::hasattr(py_->module, "tick") && PyCallable_Check(py_->module.attr("tick").ptr())) {
    py_->tick = py_->module.attr("tick");
  } else {
    if (!starting) report_once("module '" + def_.module + "' has no tick(blackboard) function", nullptr);
    return false; // at start the constructor throws instead
  }
  ++loads_;
  return true;
}

void PythonBehaviour::check_files() {
  auto files = scan_python_files(def_.directory);
  if (files == files_) return;
  std::string changed;
  auto note = [&](const std::string& path) {
    changed += (changed.empty() ? "" : ", ") + std::filesystem::path(path).lexically_relative(def_.directory).string();
  };
  for (const auto& [path, stamp] : files)
    if (auto old = files_.find(path); old == files_.end() || !(old->second == stamp)) note(path);
  for (const auto& [path, stamp] : files_)
    if (!files.count(path)) note(path);
  files_ = std::move(files);

  // Drop every module loaded from the directory, so that edited helpers reload too.
  py::dict modules = py_->sys.attr("modules");
  for (py::handle name : module_names_under(py_->sys, prefix_)) modules.attr("pop")(name);
  py::module_::import("importlib").attr("invalidate_caches")(); // new files must be found
  reported_ = false;
  timed_out_ = false;
  healthy_ = load(/*starting=*/false);
  if (healthy_) log_lines("reloaded " + def_.module + " (changed: " + changed + ")\n");
}

api::ActionCommand::All PythonBehaviour::tick(const api::Blackboard& blackboard) {
  if (stop_requested()) { // the shim is stopping: no more Python
    healthy_ = false;
    return error_request();
  }
  try {
    activate();
    const TickGuard guard(def_.tick_timeout_us);
    if (now_us() >= next_check_us_) {
      next_check_us_ = now_us() + def_.reload_check_interval_us;
      check_files();
    }
    if (!py_->tick || timed_out_) {
      healthy_ = false;
      return error_request();
    }
    const py::object result = py_->tick(def_.profile->argument(blackboard));
    AC::All request = def_.profile->request(result, blackboard);
    healthy_ = true;
    return request;
  } catch (const RequestError& e) {
    report_once(e.what(), nullptr);
  } catch (const py::error_already_set& e) {
    if (is_stopping(e)) { // asked to stop, not the behaviour's fault: nothing to report
      healthy_ = false;
      return error_request();
    }
    if (is_tick_timeout(e)) {
      timed_out_ = true;
      report_once("tick() timed out, not called again until the files change", &e);
    } else {
      report_once("tick() raised", &e);
    }
  } catch (const std::exception& e) {
    report_once(std::string("Python behaviour failed: ") + e.what(), nullptr);
  } catch (...) { // whatever it was, the robot stands and the shim plays on
    report_once("Python behaviour failed", nullptr);
  }
  healthy_ = false;
  try {
    def_.profile->on_error();
  } catch (...) { // nothing a profile does on the way to standing may stop the robot
  }
  return error_request();
}

void PythonBehaviour::report_once(const std::string& what, const py::error_already_set* error) {
  if (reported_) return;
  reported_ = true;
  std::string text = what + " (standing, chest LED magenta until fixed)";
  if (error) {
    text += ":\n";
    try {
      for (py::handle line : py_->traceback.attr("format_exception")(error->type(), error->value(),
                                                                      error->trace() ? error->trace() : py::none()))
        text += line.cast<std::string>();
    } catch (const py::error_already_set&) {
      text += std::string(error->what()) + "\n";
    }
  } else {
    text += "\n";
  }
  log_lines(text);
}

void PythonBehaviour::log_lines(const std::string& text) {
  std::ostream& log = def_.log ? *def_.log : std::cerr;
  std::ostringstream out; // one write, so that robots sharing a terminal do not interleave lines
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) out << def_.name << ": " << line << "\n";
  log << out.str() << std::flush;
}

} // namespace touchline::python
