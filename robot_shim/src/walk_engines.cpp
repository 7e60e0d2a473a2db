#include "touchline/robot/walk_engines.hpp"

#include "touchline/ini.hpp"
#include "touchline/robot/walk_cycle_engine.hpp"
#ifdef TOUCHLINE_HAVE_RUNSWIFT
#include "touchline/robot/runswift_walk.hpp"
#endif

namespace touchline::robot {

std::vector<std::string> walk_engine_names() {
#ifdef TOUCHLINE_HAVE_RUNSWIFT
  return {"walkcycle", "nao-joints", "runswift"};
#else
  return {"walkcycle", "nao-joints"};
#endif
}

std::unique_ptr<WalkEngine> make_walk_engine(const WalkEngineDef& engine, const WalkDef& walk, const KickDef& kick) {
  if (engine.name == "walkcycle") return std::make_unique<WalkCycleEngine>(walk, kick);
  if (engine.name == "nao-joints") return std::make_unique<NaoJointWalk>(engine.nao_joints, walk, kick);
#ifdef TOUCHLINE_HAVE_RUNSWIFT
  if (engine.name == "runswift") return make_runswift_walk({engine.runswift_config});
#endif
  std::string known;
  for (const std::string& name : walk_engine_names()) known += (known.empty() ? "" : ", ") + name;
  throw ConfigError("unknown walk engine '" + engine.name + "' (" + known + ")");
}

} // namespace touchline::robot
