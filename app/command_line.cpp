// The parser of `tendril SUBCOMMAND ...` (CLI11): every subcommand's --help,
// --version, and one exit status for every usage error.
#include "command_line.hpp"

#include <lua.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <iostream>

#include "command.hpp"
#include "io/huge_pages.hpp"

namespace tendril::app {

namespace {

const char* const kExitStatuses =
    "Exit status: 0 done, 1 the scene failed (its error names file and line), 2 usage error,\n"
    "3 the last m:run{} did not converge (run --strict).";

std::string version_text() {
  return std::string("tendril ") + TENDRIL_VERSION + " (" + LUA_RELEASE + ", CLI11 " + CLI11_VERSION +
         (started_with_huge_pages() ? std::string(", ") + kMemoryTunables : std::string()) + ")";
}

}  // namespace

CLI::Option* add_integer(CLI::App& cli, const std::string& name, std::int64_t& value, std::int64_t min,
                         std::int64_t max, const std::string& help) {
  auto strict = [min, max](std::string& text) -> std::string {
    std::int64_t v = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, v);
    if (error == std::errc::result_out_of_range) return "'" + text + "' is too large for a 64-bit integer";
    if (error != std::errc() || stop != end) return "'" + text + "' is not a whole number";
    if (v < min) return "'" + text + "' is less than " + std::to_string(min);
    if (v > max) return "'" + text + "' is more than " + std::to_string(max);
    return "";
  };
  return cli.add_option(name, value, help)->check(CLI::Validator(strict, ""))->type_name("INT");
}

CLI::Option* add_scene(CLI::App& cli, std::string& scene) {
  return cli.add_option("scene", scene, "the Lua scene (docs/lua-api.md)")
      ->required()
      ->check(CLI::ExistingPath)
      ->type_name("SCENE.lua");
}

std::pair<std::string, std::string> split_param(const std::string& argument) {
  const auto eq = argument.find('=');
  if (eq == std::string::npos || eq == 0) throw UsageError("--param needs NAME=VALUE, got '" + argument + "'");
  return {argument.substr(0, eq), argument.substr(eq + 1)};
}

int run_command_line(int argc, char** argv) {
  CLI::App cli{"tendril: topology-driven form-finding of bending-active and textile-hybrid structures", "tendril"};
  cli.set_version_flag("--version", version_text());
  cli.require_subcommand(1);
  cli.footer(kExitStatuses);
  std::vector<std::pair<CLI::App*, std::function<int()>>> runs;
  for (const Command& c : commands()) {
    CLI::App* sub = cli.add_subcommand(c.name, c.summary);
    sub->footer(kExitStatuses);
    runs.push_back({sub, c.define(*sub)});
  }
  if (argc < 2) {
    std::cerr << cli.help();
    return kUsage;
  }
  const std::string first = argv[1];
  if (first[0] != '-' && std::none_of(runs.begin(), runs.end(), [&](auto& r) { return r.first->get_name() == first; })) {
    std::string known;
    for (auto& r : runs) known += (known.empty() ? "" : ", ") + r.first->get_name();
    std::fprintf(stderr, "tendril: no subcommand '%s' (the subcommands: %s)\nRun with --help for more information.\n",
                 first.c_str(), known.c_str());
    return kUsage;
  }
  try {
    cli.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return cli.exit(e);  // --help, --version
    std::cerr << "tendril";
    for (auto& r : runs)
      if (r.first->parsed()) std::cerr << " " << r.first->get_name();
    std::cerr << ": ";
    cli.exit(e, std::cout, std::cerr);
    return kUsage;
  }
  for (auto& [sub, run] : runs) {
    if (!sub->parsed()) continue;
    const std::string name = sub->get_name();
    try {
      return run();
    } catch (const UsageError& e) {
      std::fprintf(stderr, "tendril %s: %s\nRun with --help for more information.\n", name.c_str(), e.what());
      return kUsage;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tendril %s: %s\n", name.c_str(), e.what());
      return kSceneError;
    }
  }
  return kUsage;  // require_subcommand(1) makes this unreachable
}

}  // namespace tendril::app
