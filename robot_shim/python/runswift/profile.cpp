#include "touchline/python/runswift/profile.hpp"

#include <filesystem>
#include <iostream>
#include <sstream>

#include <pybind11/embed.h>

#include "touchline/ini.hpp"
#include "touchline/parse_number.hpp"
#include "touchline/python/runswift/module.hpp"

namespace py = pybind11;

namespace touchline::python::runswift {

namespace {

/// The LOG_PATH the last profile made (and removes when it goes): not the user's.
std::string& last_made_log_path() {
  static std::string path;
  return path;
}

std::string type_name(py::handle value) {
  if (value.is_none()) return "None";
  const py::handle type = py::type::handle_of(value);
  const auto module = type.attr("__module__").cast<std::string>();
  const auto name = type.attr("__qualname__").cast<std::string>();
  return module == "builtins" ? name : module + "." + name;
}

class RunswiftProfile final : public PythonProfile {
 public:
  explicit RunswiftProfile(RunswiftDef def)
      : def_(std::move(def)), builder_(def_.blackboard),
        converter_([this](const std::string& line) { warn(line); }, def_.walk) {}
  ~RunswiftProfile() override {
    std::error_code ec; // a log folder we made goes with us; one the user named stays
    if (!made_log_path_.empty()) std::filesystem::remove_all(made_log_path_, ec);
  }
  RunswiftProfile(const RunswiftProfile&) = delete;
  RunswiftProfile& operator=(const RunswiftProfile&) = delete;

  void prepare(const std::string& directory) override {
    // Through os.environ, which also sets the process environment their code may read.
    py::object environ = py::module_::import("os").attr("environ");
    environ["BEHAVIOUR_ROOT"] = directory;
    if (!environ.attr("pop")("RUNSWIFT_CHECKOUT_DIR", py::none()).is_none())
      warn("RUNSWIFT_CHECKOUT_DIR unset for the behaviour: their Simulation module would replace sys.path");
    // Their robot runs their code in Python 2.7 (PythonSkill); the one Python 2 builtin it
    // uses that Python 3 moved (reduce, in util/MathUtil.py) is put back where it was.
    py::module_ builtins = py::module_::import("builtins");
    if (!py::hasattr(builtins, "reduce")) builtins.attr("reduce") = py::module_::import("functools").attr("reduce");
    // Their Log module lists LOG_PATH and writes to its newest folder.
    const std::string log_path = environ.contains("LOG_PATH") ? environ["LOG_PATH"].cast<std::string>() : "";
    const bool fresh = log_path.empty() || !std::filesystem::is_directory(log_path);
    if (fresh && !log_path.empty() && log_path != last_made_log_path())
      warn("LOG_PATH " + log_path + " is not a folder: their Log module gets a fresh one");
    if (fresh) {
      // Their Log module writes to the newest folder under LOG_PATH.
      const std::string root = py::module_::import("tempfile").attr("mkdtemp")("", "touchline-runswift-").cast<std::string>();
      py::module_::import("os").attr("makedirs")(root + "/0", py::arg("exist_ok") = true);
      environ["LOG_PATH"] = root;
      made_log_path_ = last_made_log_path() = root;
    }
  }

  py::module_ robot_module() override {
    py::module_ m = py::module_::import(kModuleName);
    set_field_constants(m, def_.field);
    return m;
  }

  bool module_required() const override { return false; }

  py::object argument(const api::Blackboard& blackboard) override { return py::cast(builder_.build(blackboard)); }

  api::ActionCommand::All request(py::handle result, const api::Blackboard& blackboard) override {
    if (!py::isinstance<BehaviourRequest>(result))
      throw RequestError("tick() returned " + type_name(result) + ", expected robot.BehaviourRequest");
    const auto& request = result.cast<const BehaviourRequest&>();
    api::ActionCommand::All all = converter_.convert(request, blackboard.utime);
    builder_.remember(request);
    if (def_.broadcast_period_us > 0 && (last_broadcast_us_ < 0 || blackboard.utime < last_broadcast_us_ ||
                                         blackboard.utime - last_broadcast_us_ >= def_.broadcast_period_us)) {
      all.teamMessage = encode_broadcast(builder_.own_broadcast(blackboard));
      last_broadcast_us_ = blackboard.utime;
    }
    return all;
  }

  void on_error() override { converter_.reset(); }

 private:
  void warn(const std::string& line) {
    std::ostream& log = def_.log ? *def_.log : std::cerr;
    std::ostringstream out; // one write: robots sharing a terminal do not interleave
    out << def_.name << ": " << line << "\n";
    log << out.str() << std::flush;
  }

  RunswiftDef def_;
  BlackboardBuilder builder_;
  RequestConverter converter_;
  int64_t last_broadcast_us_ = -1;
  std::string made_log_path_; ///< the LOG_PATH folder we made ("": the user's)
};

} // namespace

void apply_params(const std::map<std::string, std::string>& params, RunswiftDef& def) {
  for (const auto& [key, value] : params) {
    if (key == "skill" || key == "headskill" || key == "positioning") {
      if (value.empty()) throw ConfigError("--param " + key + " needs a name");
      (key == "skill" ? def.blackboard.skill : key == "headskill" ? def.blackboard.headskill : def.blackboard.positioning) =
          value;
    } else if (key == "broadcast_ms") {
      const auto ms = parse_number<int64_t>(value);
      if (!ms || *ms < 0 || *ms > 60000) throw ConfigError("--param broadcast_ms must be 0..60000 (got '" + value + "')");
      def.broadcast_period_us = *ms * 1000;
    } else if (key == "players_per_team") {
      const auto n = parse_number<int>(value);
      if (!n || *n < 1 || *n > kMaxNumPlayers)
        throw ConfigError("--param players_per_team must be 1..7 (got '" + value + "')");
      def.blackboard.players_per_team = *n;
    } else {
      throw ConfigError("--param " + key + ": the runswift behaviour takes skill, headskill, positioning, "
                        "broadcast_ms, players_per_team");
    }
  }
}

std::shared_ptr<PythonProfile> make_profile(RunswiftDef def) { return std::make_shared<RunswiftProfile>(std::move(def)); }

} // namespace touchline::python::runswift
