#pragma once
// A subcommand of `tendril`. Each lives in app/NAME_command.cpp and defines
// `Command NAME_command()`; app/CMakeLists.txt generates the list of them,
// so adding a subcommand is adding a file.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tendril::app {

// The exit status of every subcommand (README, "Command line").
enum Exit : int { kOk = 0, kSceneError = 1, kUsage = 2, kNotConverged = 3 };

struct Command {
  std::string name;
  std::string summary;  // one line in `tendril --help`
  // Declares the subcommand's options on `cli`; returns what runs it once
  // the command line parsed. What it runs returns an Exit.
  std::function<std::function<int()>(CLI::App& cli)> define;
};

std::vector<Command> commands();  // command_list.cpp, generated

// A usage error found after parsing (a --param the scene does not declare):
// reported like a parse error, exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// An integer option that takes decimal digits in [min, max] only: "1x",
// "0x10", "1e3" and 99999999999999999999 are usage errors, never a
// truncated or saturated value.
CLI::Option* add_integer(CLI::App& cli, const std::string& name, std::int64_t& value, std::int64_t min,
                         std::int64_t max, const std::string& help);
// The scene file, a required positional argument that must exist.
CLI::Option* add_scene(CLI::App& cli, std::string& scene);

// --param NAME=VALUE split at its first '='; throws UsageError naming the
// argument when it has no name or no '='.
std::pair<std::string, std::string> split_param(const std::string& argument);

}  // namespace tendril::app
