#pragma once
// The one validation of a command's arguments, for every entry point (Lua,
// journal replay, JSON messages, C++): types, live ids, finite numbers,
// ranges and choices. Throws ArgumentError naming the parameter.
#include "command/command.hpp"

namespace tendril::command {

void check_args(const Command& c, const Args& a, const Model& m);

// A bound as the messages and the listing show it ("%g").
std::string shown(double x);

// "name: 'param' why" for an ArgumentError of c.
std::string describe(const Command& c, const ArgumentError& e);

}  // namespace tendril::command
