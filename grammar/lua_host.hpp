#pragma once
// Runs scenes in real Lua 5.4 with the `tendril` module (docs/lua-api.md).
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

struct lua_State;

namespace tendril {

// A scene is a program: it may do whatever its user may (README, "Safety").
// --sandbox runs one that is not the user's own with these limits
// (lua_sandbox.hpp): no os or io beyond its output folder (reads also beside
// the scene), no binary chunks, no package, require or debug.
struct SandboxLimits {
  std::int64_t memory_mb = 1024;                        // Lua's heap
  std::int64_t production_instructions = 100'000'000;   // Lua VM instructions per rule application
  double seconds = 3600;                                // wall time of the whole scene
};

struct SceneOptions {
  std::string out_dir = "out";        // tendril.out(name) resolves here
  std::int64_t max_steps = -1;        // caps every run{}; -1: no cap
  std::int64_t seed = 1;              // math.randomseed and tendril.seed
  bool progress = true;               // progress lines on stderr for long runs
  std::int64_t threads = 1;           // --threads: solver threads of every model (m:settings{threads} overrides)
  // Lua chunks (name, source) run before the scene, after the rule library:
  // the layers above the grammar (agents) hand themselves in here.
  std::vector<std::pair<std::string, std::string>> preload;
  // --param NAME=VALUE pairs, read by tendril.param(name, default).
  std::vector<std::pair<std::string, std::string>> params;
  bool sandbox = false;  // --sandbox, with `limits`
  SandboxLimits limits;
  // Runs the scene only up to its first m:run{} or m:step(), to read the
  // parameters it declares (`tendril params`, and sweep before it starts).
  bool declarations_only = false;
  // A front end that watches the scene (the studio) hooks in here. after_step
  // runs after every solver step the scene takes (run{} and step()), with the
  // stepping model's userdata at stack index 1; after_scene runs once the
  // scene's chunk returned, with the Lua state still open. Both run on the
  // thread that runs the scene, so the model is only ever touched by it.
  // after_step returns true when it changed the model: a run{} at
  // equilibrium then goes on.
  std::function<bool(lua_State*)> after_step;
  std::function<void(lua_State*)> after_scene;
};

// What a scene declared and how its runs ended, for the command line.
struct SceneReport {
  struct Param {
    std::string name;
    std::string default_value;  // as the scene wrote it; a number as %.14g
  };
  std::vector<Param> params;  // every tendril.param(name, default), in order
  bool stepped = false;       // the scene called m:run{} or m:step()
  bool ran = false;           // the scene called m:run{}
  bool converged = true;      // the last m:run{} converged
  std::string verdict = "none";  // its verdict (physics/run_verdict.hpp)
  std::string last_run;       // how the last m:run{} ended, in words
  std::string usage_error;    // set when the scene was given a --param it does not take
};

// Runs the scene file. Returns 0 on success; on a Lua error returns 1 after
// printing the message (file:line) and a traceback to stderr, or storing
// them in *error when it is given; returns 2 when a --param names nothing the
// scene declares (tendril.param) or gives a number parameter a word. *report,
// when given, receives the declarations and the last run's outcome.
int run_scene(const std::string& path, const SceneOptions& options, std::string* error = nullptr,
              SceneReport* report = nullptr);

}  // namespace tendril
