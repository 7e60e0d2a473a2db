// A shared library without the entry point (a team's library built without
// TOUCHLINE_BEHAVIOUR_PLUGIN).
extern "C" __attribute__((visibility("default"))) int not_a_behaviour_plugin() { return 1; }
