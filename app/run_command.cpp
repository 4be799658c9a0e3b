// `tendril run SCENE.lua`: runs a Lua scene.
#include <cstdio>
#include <limits>
#include <memory>

#include "agents_library.hpp"
#include "command.hpp"
#include "lua_host.hpp"

namespace tendril::app {

namespace {

struct RunArguments {
  std::string scene;
  SceneOptions options;
  std::vector<std::string> params;
  bool quiet = false, strict = false;
};

int run(RunArguments& a) {
  for (const std::string& p : a.params) {
    auto kv = split_param(p);
    for (const auto& [name, value] : a.options.params)
      if (name == kv.first) throw UsageError("--param " + name + " is given twice");
    a.options.params.push_back(std::move(kv));
  }
  a.options.progress = !a.quiet;
  a.options.preload = agents_library();
  SceneReport report;
  const int status = run_scene(a.scene, a.options, nullptr, &report);
  if (status != kOk) return status;
  if (a.strict && report.ran && !report.converged) {
    const std::string prefix = "not converged: ";
    std::string why = report.last_run;
    if (why.rfind(prefix, 0) == 0) why = why.substr(prefix.size());
    std::fprintf(stderr, "tendril run: --strict: the last m:run{} of %s did not converge: %s\n", a.scene.c_str(),
                 why.c_str());
    return kNotConverged;
  }
  return kOk;
}

}  // namespace

Command run_command() {
  return {"run", "runs a Lua scene (docs/lua-api.md)", [](CLI::App& cli) {
            auto a = std::make_shared<RunArguments>();
            constexpr auto kMax = std::numeric_limits<std::int64_t>::max();
            add_scene(cli, a->scene);
            cli.add_option("--out", a->options.out_dir, "directory of the scene's outputs, tendril.out(name)")
                ->type_name("DIR")
                ->capture_default_str();
            add_integer(cli, "--steps", a->options.max_steps, 0, kMax, "caps the steps of every run{} and step()");
            add_integer(cli, "--seed", a->options.seed, std::numeric_limits<std::int64_t>::min(), kMax,
                        "seeds math.random; tendril.seed reads it")
                ->capture_default_str();
            add_integer(cli, "--threads", a->options.threads, 1, 64,
                        "solver threads of every model (m:settings{threads} overrides); the numbers do not depend on it")
                ->capture_default_str();
            cli.add_option("--param", a->params, "a value for tendril.param(NAME, default) (repeatable)")
                ->type_name("NAME=VALUE")
                ->expected(1)
                ->take_all();
            auto* sandbox = cli.add_flag("--sandbox", a->options.sandbox,
                         "runs a scene that is not your own with limits: no os/io beyond --out, no binary chunks, "
                         "no package/require/debug, and the limits below (README, \"Safety\")");
            add_integer(cli, "--memory-limit", a->options.limits.memory_mb, 1, 1 << 20,
                        "--sandbox: the scene's Lua memory [MB]")
                ->needs(sandbox)
                ->capture_default_str();
            add_integer(cli, "--production-limit", a->options.limits.production_instructions, 1000, kMax,
                        "--sandbox: Lua instructions one rule application may take")
                ->needs(sandbox)
                ->capture_default_str();
            cli.add_option("--time-limit", a->options.limits.seconds, "--sandbox: wall time of the whole scene [s]")
                ->check(CLI::Range(0.001, 1e9))
                ->needs(sandbox)
                ->capture_default_str();
            cli.add_flag("--quiet", a->quiet, "no progress lines on stderr");
            cli.add_flag("--strict", a->strict, "exit status 3 when the last m:run{} did not converge");
            return [a] { return run(*a); };
          }};
}

}  // namespace tendril::app
