// tendril command line: `tendril run scene.lua [--out DIR] [--steps N] [--seed S] [--quiet]`.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "lua_host.hpp"

namespace {

const char* const kUsage =
    "usage: tendril run SCENE.lua [--out DIR] [--steps N] [--seed S] [--quiet]\n"
    "\n"
    "  run      runs a Lua scene (docs/lua-api.md)\n"
    "  --out    directory for the scene's outputs, tendril.out(name) (default: out)\n"
    "  --steps  caps the steps of every run{} and step() of the scene\n"
    "  --seed   seeds math.random and tendril.seed (default: 1)\n"
    "  --quiet  no progress lines on stderr\n";

bool parse_int(const std::string& s, long long& out) {
  char* end = nullptr;
  out = std::strtoll(s.c_str(), &end, 10);
  return !s.empty() && end && *end == '\0';
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string command = argv[1];
  if (command != "run") {
    std::fprintf(stderr, "tendril: unknown command '%s'\n\n%s", command.c_str(), kUsage);
    return 2;
  }
  tendril::SceneOptions options;
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
