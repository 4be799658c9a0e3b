// tendril command line: `tendril run scene.lua [--out DIR] [--steps N] [--seed S] [--quiet]`.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "io/model_xml.hpp"
#include "io/obj.hpp"
#include "io/trace.hpp"
#include "agents_library.hpp"
#include "lua_host.hpp"

int run_sweep(int argc, char** argv);  // sweep_command.cpp

namespace {

const char* const kUsage =
    "usage: tendril run SCENE.lua [--out DIR] [--steps N] [--seed S] [--param NAME=VALUE]... [--quiet]\n"
    "       tendril replay JOURNAL [--out DIR]\n"
    "       tendril sweep SCENE.lua --param NAME=V1,V2,... --seeds A..B [--jobs N] [--out DIR] [--steps N]\n"
    "       tendril validate [--csv FILE] [--plots DIR] [--quick] [--case NAME]\n"
    "\n"
    "  run      runs a Lua scene (docs/lua-api.md)\n"
    "  replay   rebuilds a model from a journal written by m:save_journal (docs/rules.md),\n"
    "           prints its assembly sequence and writes DIR/model.xml and DIR/model.obj\n"
    "  sweep    runs a scene for every combination of parameters and seeds in N processes;\n"
    "           one CSV row per run in DIR/sweep.csv, each run's outputs in DIR/run-K\n"
    "  validate runs every validation case with each integrator and resolution, prints\n"
    "           error, steps and wall time, fails if a default is outside its tolerance\n"
    "  --out    directory for the scene's outputs, tendril.out(name) (default: out)\n"
    "  --steps  caps the steps of every run{} and step() of the scene\n"
    "  --seed   seeds math.random and tendril.seed (default: 1)\n"
    "  --param  a value for tendril.param(NAME, default) in the scene (repeatable)\n"
    "  --quiet  no progress lines on stderr\n";

bool parse_int(const std::string& s, long long& out) {
  char* end = nullptr;
  out = std::strtoll(s.c_str(), &end, 10);
  return !s.empty() && end && *end == '\0';
}

int replay(int argc, char** argv) {
  std::string journal, out = "out";
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) out = argv[++i];
    else if (journal.empty() && arg[0] != '-') journal = arg;
    else {
      std::fprintf(stderr, "tendril: replay: unexpected argument '%s'\n\n%s", arg.c_str(), kUsage);
      return 2;
    }
  }
  if (journal.empty()) {
    std::fprintf(stderr, "tendril: replay needs a journal file\n\n%s", kUsage);
    return 2;
  }
  try {
    std::istringstream in(tendril::read_input_file(journal));
    tendril::Model model;
    tendril::Solver solver(model);
    tendril::replay_trace(in, journal, model, solver);
    std::filesystem::create_directories(out);
    tendril::save_model_xml(model, solver.settings, out + "/model.xml");
    tendril::save_obj(model, out + "/model.obj");
    in.clear();
    in.seekg(0);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("# ", 0) == 0) std::printf("%s\n", line.c_str() + 2);
    std::printf("replayed %llu steps: %zu particles, %zu blocks -> %s/model.xml\n",
                static_cast<unsigned long long>(solver.steps()), model.particle_count(), model.block_count(),
                out.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tendril: replay: %s\n", e.what());
    return 1;
  }
}

}  // namespace

int run_validate(int argc, char** argv);  // validate_command.cpp

int main(int argc, char** argv) {
  tendril::clean_up_outputs_on_signals();
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string command = argv[1];
  if (command == "replay") return replay(argc, argv);
  if (command == "sweep") {
    try {
      return run_sweep(argc, argv);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tendril: sweep: %s\n", e.what());
      return 1;
    }
  }
  if (command == "validate") return run_validate(argc, argv);
  if (command != "run") {
    std::fprintf(stderr, "tendril: unknown command '%s'\n\n%s", command.c_str(), kUsage);
    return 2;
  }
  tendril::SceneOptions options;
  options.preload = tendril::agents_library();
  std::string scene;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "tendril: %s needs a value\n", name);
        std::exit(2);
      }
      return argv[++i];
    };
    long long n = 0;
    if (arg == "--out") {
      options.out_dir = value("--out");
    } else if (arg == "--steps") {
      if (!parse_int(value("--steps"), n) || n < 0) {
        std::fprintf(stderr, "tendril: --steps needs a non-negative integer\n");
        return 2;
      }
      options.max_steps = n;
    } else if (arg == "--seed") {
      if (!parse_int(value("--seed"), n)) {
        std::fprintf(stderr, "tendril: --seed needs an integer\n");
        return 2;
      }
      options.seed = n;
    } else if (arg == "--param") {
      const std::string kv = value("--param");
      const auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0) {
        std::fprintf(stderr, "tendril: --param needs NAME=VALUE, got '%s'\n", kv.c_str());
        return 2;
      }
      options.params.push_back({kv.substr(0, eq), kv.substr(eq + 1)});
    } else if (arg == "--quiet") {
      options.progress = false;
    } else if (!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "tendril: unknown option '%s'\n\n%s", arg.c_str(), kUsage);
      return 2;
    } else if (scene.empty()) {
      scene = arg;
    } else {
      std::fprintf(stderr, "tendril: one scene at a time (got '%s' and '%s')\n", scene.c_str(), arg.c_str());
      return 2;
    }
  }
  if (scene.empty()) {
    std::fprintf(stderr, "tendril: run needs a scene file\n\n%s", kUsage);
    return 2;
  }
  return tendril::run_scene(scene, options);
}
