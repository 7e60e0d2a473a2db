#pragma once
// RobotDef: everything that makes one robot, in one place, before the robot exists (as
// Box2D's b2BodyDef describes a body): who it is, how it walks, kicks and points its
// camera, where its beliefs come from, which behaviour it runs and how that is timed.
// Every maker of a robot (robot_shim, the in-process match, learning's SingleRobotSim, the
// tests) fills one, load_robot_def() reading the parts that live in INI files, and hands
// it to Robot. The behaviour object itself is made by the caller from `behaviour`
// (behaviour_cpp's registry, the Python runtime, a test's own): this library sits below
// both and knows no behaviour.
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "touchline/frame.hpp"
#include "touchline/robot/adapters.hpp"
#include "touchline/robot/head_def.hpp"
#include "touchline/robot/kick_generator.hpp"
#include "touchline/robot/localisation/localiser.hpp"
#include "touchline/robot/motion_adapter.hpp"
#include "touchline/robot/walk_cycle.hpp"
#include "touchline/robot/walk_engines.hpp"

namespace touchline::robot {

/// How the robot runs its behaviour.
struct BehaviourTimingDef {
  /// Charge the behaviour's CPU time to simulated time, as on the robot, where a
  /// behaviour that overruns its 33.3 ms frame misses camera frames: after a tick that
  /// used `cpu` microseconds the behaviour next runs behaviour_frames_used(cpu) frames
  /// later. The previous request stays in force meanwhile; motion ticks every frame.
  bool charge_cpu = false;
  /// The clock a tick is measured with, microseconds: this thread's CPU time (tests
  /// inject their own).
  CpuClock cpu_clock = thread_cpu_us;
};

/// Where the robot's beliefs about its pose and the ball come from.
struct LocalisationModeDef {
  localisation::LocalisationDef filters; ///< the field the robot knows (default SPL 2011), the filters' noise models
  bool perfect = false;                  ///< the robot's pose from the truth (the ball still from the camera)
};

/// Which behaviour the robot runs. Only named here: whoever makes the robot turns it into
/// an api::Behaviour (robot_shim: behaviour_cpp's registry or the Python runtime).
struct BehaviourDef {
  /// A C++ behaviour of behaviour_cpp's registry ("stand", "goto", "GoToBall", ...), or
  /// "py" / "py:MODULE" for the Python behaviour (MODULE.tick(blackboard); "py" imports
  /// the module `behaviour`), "runswift" for a rUNSWift behaviour folder's behaviour.py
  /// (the rUNSWift profile of the Python runtime).
  std::string name = "stand";
  std::map<std::string, std::string> params; ///< key -> value, strings as --param key=value gives them
  std::string python_dir;                    ///< Python only: the module's folder (first on sys.path)
};

/// The module a Python behaviour imports: "py", "runswift" -> "behaviour", "py:MODULE" -> MODULE;
/// nothing for a C++ behaviour. Throws ConfigError "py:MODULE needs a module name" for "py:".
std::optional<std::string> python_module(const BehaviourDef& behaviour);

/// "NAME k=v k=v" (params in key order): what behaviour.skill on the Blackboard, and so
/// every snapshot, records as running.
std::string describe(const BehaviourDef& behaviour);

struct RobotDef {
  RobotId id{0, 1};                  ///< team (0 or 1) and player number (1..7)
  WalkDef walk;                      ///< the gait: [walk] of config/walk.ini
  WalkEngineDef engine;              ///< which walk engine runs the gait (--walk-engine): walkcycle, nao-joints
  KickDef kick;                      ///< kick and dribble swings: [kick], [dribble] of config/kick.ini
  HeadDef head;                      ///< the head that points the camera: [head] of config/head.ini
  LocalisationModeDef localisation;  ///< the field it knows ([field] of the world's config), filters or the truth
  BehaviourDef behaviour;            ///< what runs on it
  BehaviourTimingDef timing;         ///< how the behaviour's CPU time counts
};

/// The INI files a robot is described by. "" for any: that part is left as it is.
struct RobotConfigFiles {
  std::string walk;  ///< [walk], e.g. config/walk.ini
  std::string kick;  ///< [kick] and [dribble], e.g. config/kick.ini
  std::string field; ///< the world's config (e.g. config/spl2020.ini): its [field], other sections skipped
  std::string head;  ///< [head], e.g. config/head.ini
};

/// `def` with each file `files` names read into its part (walk, kick, the field the
/// localisation knows, the head) by that part's own loader; keys a file leaves out keep their
/// built-in default. Throws ConfigError, one line naming the file ("config/walk.ini:
/// walk.period_s must be in [0.02, 10] (got -1)").
RobotDef load_robot_def(const RobotConfigFiles& files, RobotDef def = {});

} // namespace touchline::robot
