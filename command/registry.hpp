#pragma once
// Every command, in the order docs/commands.md lists them.
#include <string_view>
#include <vector>

#include "command/command.hpp"

namespace tendril::command {

const std::vector<Command>& commands();
const Command* find(std::string_view name);  // nullptr when unknown
const Command& get(std::string_view name);   // throws std::logic_error when unknown (a programming error)

}  // namespace tendril::command
