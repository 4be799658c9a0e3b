#pragma once
// `tendril SUBCOMMAND ...`: parses the command line, runs the subcommand and
// returns its exit status (app/command.hpp).
namespace tendril::app {
int run_command_line(int argc, char** argv);
}
