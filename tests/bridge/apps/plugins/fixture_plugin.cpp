// A behaviour library as a team would build it, for test_behaviour_plugin: "Walk" walks at
// --param forward= mm/s with the chest LED showing team and player; "Nothing" makes nullptr;
// "NeedsData" needs the file --param file= in the data directory (api::data_path).
#include <filesystem>
#include <stdexcept>

#include "touchline/robot_api/plugin.hpp"

namespace {

namespace api = touchline::api;

class Walk : public api::Behaviour {
 public:
  Walk(float forward_mm_s, int32_t chest) : forward_mm_s_(forward_mm_s), chest_(chest) {}
  api::ActionCommand::All tick(const api::Blackboard&) override {
    api::ActionCommand::All request;
    request.body = api::ActionCommand::walk(forward_mm_s_, 0, 0);
    request.leds.chest = chest_;
    return request;
  }

 private:
  float forward_mm_s_;
  int32_t chest_;
};

std::unique_ptr<api::Behaviour> make(const api::PluginRequest& request) {
  const auto param = [&](const std::string& key) {
    const auto it = request.params.find(key);
    return it == request.params.end() ? std::string() : it->second;
  };
  const int32_t chest = request.team * 16 + request.player;
  if (request.name == "Walk") return std::make_unique<Walk>(param("forward").empty() ? 0.f : std::stof(param("forward")), chest);
  if (request.name == "Nothing") return nullptr;
  if (request.name == "NeedsData") {
    if (!std::filesystem::is_regular_file(api::data_path(param("file"))))
      throw std::invalid_argument("NeedsData: no " + api::data_path(param("file")));
    return std::make_unique<Walk>(0.f, chest);
  }
  throw std::invalid_argument("unknown behaviour '" + request.name + "'");
}

} // namespace

TOUCHLINE_BEHAVIOUR_PLUGIN(make)
