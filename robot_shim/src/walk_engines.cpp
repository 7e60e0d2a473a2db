#include "touchline/robot/walk_engines.hpp"

#include "touchline/ini.hpp"
#include "touchline/robot/walk_cycle_engine.hpp"

namespace touchline::robot {

std::vector<std::string> walk_engine_names() { return {"walkcycle", "nao-joints"}; }

std::unique_ptr<WalkEngine> make_walk_engine(const WalkEngineDef& engine, const WalkDef& walk, const KickDef& kick) {
  if (engine.name == "walkcycle") return std::make_unique<WalkCycleEngine>(walk, kick);
  if (engine.name == "nao-joints") return std::make_unique<NaoJointWalk>(engine.nao_joints, walk, kick);
  std::string known;
  for (const std::string& name : walk_engine_names()) known += (known.empty() ? "" : ", ") + name;
  throw ConfigError("unknown walk engine '" + engine.name + "' (" + known + ")");
}

} // namespace touchline::robot
