// touchline_bench: measures how fast the lockstep co-simulation runs and how close that is to
// what the LCM transport allows.
//
//  1. LCM round-trip floor: N forked responder processes (own lcm::LCM each) answer every ping
//     with its sequence number on their own pong channel; the parent times ping -> all N pongs.
//     The same over the match bus (bus_floor.cpp): the transport's own floor.
//  2. Lockstep real-time factor: sim_world plus N robot_shim processes walking for --duration
//     simulated seconds; the RTF is read from sim_world's --summary JSON.
//
// Run it through bench/run (or tools/netns) so that LCM multicast stays on a private loopback.
// Exit status: 0 ok, 1 a child or measurement failed, 2 bad options.
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <boost/program_options.hpp>
#include <lcm/lcm-cpp.hpp>

#include "bench.hpp"

namespace po = boost::program_options;
using namespace touchline::bench;

namespace {


double cap_rtf(double floor_us) { return floor_us > 0 ? kFramePeriodUs / floor_us : 0; }

/// The 8-robot lockstep RTF as a fraction of the 8-responder LCM cap that issue #14 asks for.
constexpr double kCapRatioGoal = 0.75;

std::string fixed(double x, int precision) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(precision) << x;
  return s.str();
}

void print_report(const Options& opt, long nproc, const std::vector<FloorResult>& floors,
                  const std::vector<FloorResult>& bus_floors, const std::vector<LockstepResult>& runs,
                  const AuthCost& auth) {
  std::ostream& out = std::cout;
  out << "\nTouchline lockstep benchmark  (" << nproc << " CPUs, " << opt.lcm_url << ")\n\n";
  out << "LCM round-trip floor: ping all responders, wait for every pong (" << opt.rounds << " rounds after "
      << opt.warmup << " warm-up)\n";
  out << "  responders   median us    p90 us    min us    max us   lost   cap at 1 exchange/frame\n";
  for (const auto& f : floors)
    out << std::setw(12) << f.responders << std::setw(12) << fixed(f.median_us, 1) << std::setw(10)
        << fixed(f.p90_us, 1) << std::setw(10) << fixed(f.min_us, 1) << std::setw(10) << fixed(f.max_us, 1)
        << std::setw(7) << f.lost_rounds << std::setw(12) << fixed(cap_rtf(f.median_us), 1) << "x real time\n";

  out << "\nMatch-bus round-trip floor: the same over the transport lockstep runs on (ping sent as the sense,\n"
         "pongs on the answers' port, tagged, each read in the caller's thread; bridge/lcm bus.hpp)\n";
  for (const auto& f : bus_floors)
    out << std::setw(12) << f.responders << std::setw(12) << fixed(f.median_us, 1) << std::setw(10)
        << fixed(f.p90_us, 1) << std::setw(10) << fixed(f.min_us, 1) << std::setw(10) << fixed(f.max_us, 1)
        << std::setw(7) << f.lost_rounds << std::setw(12) << fixed(cap_rtf(f.median_us), 1) << "x real time\n";

  out << "\nLockstep runs: walk forward=200 turn=0.3, " << opt.duration_s << " s simulated, median of "
      << opt.repeat << "\n";
  out << "  robots   RTF median   RTF runs                 match wall s   total wall s   transport cap   "
         "of cap\n";
  for (const auto& r : runs) {
    std::string each;
    for (const auto& run : r.runs) each += (each.empty() ? "" : " ") + fixed(run.rtf, 1);
    // The cap for n robots comes from the n-responder floor (n = 1 or 8 are measured).
    const FloorResult* f = nullptr;
    for (const auto& fl : floors)
      if (fl.responders == r.robots) f = &fl;
    const double cap = f ? cap_rtf(f->median_us) : 0;
    out << std::setw(8) << r.robots << std::setw(13) << fixed(r.median_rtf, 1) << "   " << std::left
        << std::setw(25) << each << std::right << std::setw(12) << fixed(r.median_sim_wall_s, 3)
        << std::setw(15) << fixed(r.median_total_wall_s, 3) << std::setw(15)
        << (cap > 0 ? fixed(cap, 1) + "x" : "-") << std::setw(8)
        << (cap > 0 ? fixed(100 * r.median_rtf / cap, 0) + "%" : "-") << "\n";
  }
  out << "  (transport cap = 33333 us per frame / n-responder round-trip median; match wall = sim_world's\n"
         "   own clock over the frame loop, total wall = spawn to last exit, including start-up and join)\n";
  for (const auto& f : floors)
    if (f.responders == 8)
      out << "\nImplied ceiling: 8-responder floor " << fixed(f.median_us, 1) << " us per frame -> lockstep cap "
          << fixed(cap_rtf(f.median_us), 1) << "x real time";
  for (const auto& r : runs)
    if (r.robots == 8) out << "; measured 8-robot RTF " << fixed(r.median_rtf, 1) << "x";
  // Issue #14's goal, from figures of this one run: the machine's load moves both alike.
  for (const auto& r : runs)
    for (const auto& f : floors)
      if (r.robots == 8 && f.responders == 8)
        out << "\n8 robots: RTF " << fixed(r.median_rtf, 1) << "x / LCM cap " << fixed(cap_rtf(f.median_us), 1)
            << "x measured in this run = " << fixed(r.median_rtf / cap_rtf(f.median_us), 2) << " of the cap (goal >= "
            << fixed(kCapRatioGoal, 2) << ")";
  for (const auto& r : runs)
    for (const auto& f : bus_floors)
      if (r.robots == 8 && f.responders == 8)
        out << "\n8 robots: RTF " << fixed(r.median_rtf, 1) << "x / match-bus cap " << fixed(cap_rtf(f.median_us), 1)
            << "x measured in this run = " << fixed(r.median_rtf / cap_rtf(f.median_us), 2)
            << " of the bus's own cap (the rest of the frame: world step, robot step, codec)";
  out << "\n\nBus authentication (HMAC-SHA-256 tag on every message), " << auth.robots << " robots, sense "
      << auth.sense_bytes << " B, answer " << auth.answer_bytes << " B:\n"
      << "  seal sense " << fixed(auth.seal_sense_us, 2) << " us, verify sense " << fixed(auth.verify_sense_us, 2)
      << " us, seal answer " << fixed(auth.seal_answer_us, 2) << " us, verify answer "
      << fixed(auth.verify_answer_us, 2) << " us\n"
      << "  per frame: " << fixed(auth.critical_path_us, 1) << " us on the round's critical path, "
      << fixed(auth.total_cpu_us, 1) << " us of CPU over all processes";
  for (const auto& f : floors)
    if (f.responders == auth.robots)
      out << "; " << fixed(100 * auth.critical_path_us / f.median_us, 1) << "% of the " << f.responders
          << "-responder round-trip floor measured above";
  out << "\n" << std::flush;
}

void write_json(const std::string& path, const Options& opt, long nproc, const std::vector<FloorResult>& floors,
                const std::vector<FloorResult>& bus_floors, const std::vector<LockstepResult>& runs,
                const AuthCost& auth) {
  std::ofstream out(path);
  if (!out) throw BenchError("cannot write " + path);
  out << std::setprecision(6) << "{\n";
  for (const auto& r : runs) {
    const std::string n = std::to_string(r.robots);
    out << "  \"rtf_lockstep_" << n << "\": " << r.median_rtf << ",\n";
    out << "  \"rtf_lockstep_runs_" << n << "\": [";
    for (size_t i = 0; i < r.runs.size(); ++i) out << (i ? ", " : "") << r.runs[i].rtf;
    out << "],\n";
    out << "  \"match_wall_s_" << n << "\": " << r.median_sim_wall_s << ",\n";
    out << "  \"total_wall_s_" << n << "\": " << r.median_total_wall_s << ",\n";
    long missed = 0;
    for (const auto& run : r.runs) missed += run.frames_missed;
    out << "  \"frames_missed_" << n << "\": " << missed << ",\n";
  }
  for (const auto& r : runs)
    for (const auto& f : floors)
      if (r.robots == f.responders && f.median_us > 0)
        out << "  \"rtf_cap_ratio_" << r.robots << "\": " << r.median_rtf / cap_rtf(f.median_us) << ",\n";
  for (const auto& f : floors) {
    const std::string n = std::to_string(f.responders);
    out << "  \"lcm_floor_us_" << n << "\": " << f.median_us << ",\n";
    out << "  \"lcm_floor_p90_us_" << n << "\": " << f.p90_us << ",\n";
    out << "  \"lcm_floor_lost_rounds_" << n << "\": " << f.lost_rounds << ",\n";
    out << "  \"lockstep_cap_rtf_" << n << "\": " << cap_rtf(f.median_us) << ",\n";
  }
  for (const auto& f : bus_floors) {
    const std::string n = std::to_string(f.responders);
    out << "  \"bus_floor_us_" << n << "\": " << f.median_us << ",\n";
    out << "  \"bus_cap_rtf_" << n << "\": " << cap_rtf(f.median_us) << ",\n";
    for (const auto& r : runs)
      if (r.robots == f.responders && f.median_us > 0)
        out << "  \"rtf_bus_cap_ratio_" << n << "\": " << r.median_rtf / cap_rtf(f.median_us) << ",\n";
  }
  std::string url;  // JSON-escape the URL (quotes and backslashes only; it is ASCII)
  for (char c : opt.lcm_url) {
    if (c == '"' || c == '\\') url += '\\';
    url += c;
  }
  out << "  \"auth_critical_path_us_" << auth.robots << "\": " << auth.critical_path_us << ",\n"
      << "  \"auth_total_cpu_us_" << auth.robots << "\": " << auth.total_cpu_us << ",\n";
  out << "  \"duration_s\": " << opt.duration_s << ",\n"
      << "  \"repeats\": " << opt.repeat << ",\n"
      << "  \"rounds\": " << opt.rounds << ",\n"
      << "  \"warmup_rounds\": " << opt.warmup << ",\n"
      << "  \"nproc\": " << nproc << ",\n"
      << "  \"lcm_url\": \"" << url << "\"\n}\n";
  if (!out.flush()) throw BenchError("cannot write " + path);
}

/// The build folder this executable sits in (<build>/bench/touchline_bench), or "".
std::string default_bin_dir() {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "";
  std::string exe(buf, static_cast<size_t>(n));
  for (int i = 0; i < 2; ++i) {
    const size_t slash = exe.rfind('/');
    if (slash == std::string::npos) return "";
    exe.resize(slash);
  }
  return exe;
}

} // namespace

int main(int argc, char** argv) {
  Options opt;
  std::vector<std::string> bin_dirs;
  std::vector<int> responders = {1, 8};
  po::options_description options(
      "touchline_bench: LCM round-trip floor and lockstep real-time factor, 1 and 8 robots.\n"
      "Run it through bench/run (a private network namespace; LCM stays on loopback).\n"
      "Usage: touchline_bench [options]\nOptions");
  options.add_options()
    ("help,h", "print this help and exit")
    ("bin-dir", po::value(&bin_dirs), "build folder holding bin/sim_world and bin/robot_shim (the last one "
                                      "given wins; default: the build folder of this executable)")
    ("duration", po::value(&opt.duration_s)->default_value(opt.duration_s), "simulated seconds per lockstep run")
    ("repeat", po::value(&opt.repeat)->default_value(opt.repeat), "lockstep runs per configuration (median reported)")
    ("rounds", po::value(&opt.rounds)->default_value(opt.rounds), "timed LCM round trips per responder count")
    ("warmup", po::value(&opt.warmup)->default_value(opt.warmup), "untimed LCM round trips first")
    ("run-timeout", po::value(&opt.run_timeout_s), "wall seconds a lockstep run may take before it is killed "
                                                   "(default: 10 + duration, i.e. 10x a run at 10x real time, "
                                                   "plus start-up)")
    ("lcm-url", po::value(&opt.lcm_url)->default_value(opt.lcm_url), "LCM provider URL (keep ttl=0)")
    ("json", po::value(&opt.json_path), "write the figures as JSON to this path")
    ("keep-logs", "keep the children's logs and summaries (printed folder) after a successful run")
    ("responders", po::value(&responders)->multitoken(),
     "responder counts for the LCM round-trip floor (default 1 8; with --floor-only any of 1..64)")
    ("floor-only", "measure the LCM round-trip floor only and print it as one JSON line per responder count "
                   "(bench/cost_growth's LCM cap)");

  try {
    po::variables_map vm;
    const po::positional_options_description no_positionals;  // any bare word is an error
    po::store(po::command_line_parser(argc, argv).options(options).positional(no_positionals).run(), vm);
    if (vm.count("help")) {
      std::cout << options << "\n";
      return 0;
    }
    po::notify(vm);
    opt.bin_dir = bin_dirs.empty() ? default_bin_dir() : bin_dirs.back();
    opt.keep_logs = vm.count("keep-logs") > 0;
    if (opt.bin_dir.empty()) throw po::error("--bin-dir is required (cannot locate this executable)");
    if (!(opt.duration_s > 0 && opt.duration_s <= 86400)) throw po::error("--duration must be in (0, 86400]");
    if (opt.repeat < 1) throw po::error("--repeat must be >= 1");
    if (opt.rounds < 1) throw po::error("--rounds must be >= 1");
    if (opt.warmup < 0) throw po::error("--warmup must be >= 0");
    if (vm.count("run-timeout") && !(opt.run_timeout_s > 0)) throw po::error("--run-timeout must be > 0");
    if (opt.lcm_url.empty()) throw po::error("--lcm-url must not be empty");
    for (int n : responders)
      if (n < 1 || n > 64) throw po::error("--responders must be 1..64");
    if (!vm.count("floor-only") && responders != std::vector<int>{1, 8})
      throw po::error("--responders other than 1 8 needs --floor-only (the report compares 1 and 8 robots)");
    if (vm.count("floor-only")) {
      if (std::getenv("TOUCHLINE_IN_NETNS") == nullptr)
        std::cerr << "touchline_bench: warning: not inside tools/netns; LCM traffic uses this host's loopback\n";
      try {
        for (int n : responders) {
          const FloorResult f = measure_floor(opt, n);
          std::cout << "{\"responders\": " << n << ", \"median_us\": " << f.median_us << ", \"p90_us\": "
                    << f.p90_us << ", \"lost_rounds\": " << f.lost_rounds << ", \"cap_rtf\": "
                    << cap_rtf(f.median_us) << "}" << std::endl;
        }
      } catch (const std::exception& e) {
        std::cerr << "touchline_bench: " << e.what() << "\n";
        return kFailure;
      }
      return 0;
    }
  } catch (const po::error& e) {
    std::cerr << "touchline_bench: " << e.what() << " (see --help)\n";
    return kUsageError;
  }
  const double run_timeout_s = opt.run_timeout_s > 0 ? opt.run_timeout_s : 10 + opt.duration_s;
  const long nproc = sysconf(_SC_NPROCESSORS_ONLN);

  try {
    std::string dir;
    for (const char* rel : {"/bin/sim_world", "/bin/robot_shim"}) {
      const std::string path = opt.bin_dir + rel;
      if (access(path.c_str(), X_OK) != 0)
        throw BenchError(path + " is missing or not executable (build sim_world and robot_shim, or pass --bin-dir)");
    }
    if (std::getenv("TOUCHLINE_IN_NETNS") == nullptr)
      std::cerr << "touchline_bench: warning: not inside tools/netns; LCM traffic uses this host's loopback\n";

    std::vector<FloorResult> floors;
    for (int n : {1, 8}) {
      std::cerr << "touchline_bench: LCM round trip, " << n << " responder(s)...\n";
      floors.push_back(measure_floor(opt, n));
    }
    std::vector<FloorResult> bus_floors;
    for (int n : {1, 8}) {
      std::cerr << "touchline_bench: match-bus round trip, " << n << " responder(s)...\n";
      bus_floors.push_back(measure_bus_floor(opt, n));
    }
    // Children's logs and sim_world summaries; kept when something fails (or with --keep-logs).
    std::string tmpl = (std::getenv("TMPDIR") ? std::string(std::getenv("TMPDIR")) : "/tmp") + "/touchline_bench.XXXXXX";
    if (mkdtemp(tmpl.data()) == nullptr) throw BenchError(std::string("mkdtemp failed: ") + std::strerror(errno));
    dir = tmpl;
    std::vector<LockstepResult> runs;
    for (int n : {1, 8}) {
      std::cerr << "touchline_bench: lockstep, " << n << " robot(s), " << opt.repeat << " x " << opt.duration_s
                << " s simulated...\n";
      runs.push_back(measure_lockstep(opt, n, dir, run_timeout_s));
    }
    const AuthCost auth = measure_auth_cost(8, 20000);
    print_report(opt, nproc, floors, bus_floors, runs, auth);
    if (!opt.json_path.empty()) {
      write_json(opt.json_path, opt, nproc, floors, bus_floors, runs, auth);
      std::cout << "wrote " << opt.json_path << "\n";
    }
    if (opt.keep_logs) {
      std::cout << "logs in " << dir << "\n";
    } else {
      std::error_code ec;  // logs and summaries only; a failure to remove them is not a failure
      std::filesystem::remove_all(dir, ec);
    }
  } catch (const BenchError& e) {
    std::cerr << "touchline_bench: " << e.what() << "\n";
    return kFailure;
  } catch (const std::exception& e) {
    std::cerr << "touchline_bench: " << e.what() << "\n";
    return kFailure;
  }
  return 0;
}

