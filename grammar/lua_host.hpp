#pragma once
// Runs scenes in real Lua 5.4 with the `tendril` module (docs/lua-api.md).
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tendril {

struct SceneOptions {
  std::string out_dir = "out";        // tendril.out(name) resolves here
  std::int64_t max_steps = -1;        // caps every run{}; -1: no cap
  std::int64_t seed = 1;              // math.randomseed and tendril.seed
  bool progress = true;               // progress lines on stderr for long runs
  // Lua chunks (name, source) run before the scene, after the rule library:
  // the layers above the grammar (agents) hand themselves in here.
  std::vector<std::pair<std::string, std::string>> preload;
  // --param NAME=VALUE pairs, read by tendril.param(name, default).
  std::vector<std::pair<std::string, std::string>> params;
};

// Runs the scene file. Returns 0 on success; on a Lua error returns 1 after
// printing the message (file:line) and a traceback to stderr, or storing
// them in *error when it is given.
int run_scene(const std::string& path, const SceneOptions& options, std::string* error = nullptr);

}  // namespace tendril
