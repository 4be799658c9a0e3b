#pragma once
// A command as one line of the replayable journal (core/io/trace.hpp):
// its name, then each argument it carries in declaration order — ids and
// counts in decimal, numbers exact ("%a"), flags 0 or 1, lists and paths to
// the end of the line; keyed commands as KEY=VALUE.
#include <sstream>
#include <string>

#include "command/command.hpp"

namespace tendril::command {

std::string encode(const Command& c, const Args& a);
// The arguments of c from the words after its name. Throws ArgumentError
// naming the parameter whose word is missing or malformed.
Args decode(const Command& c, std::istringstream& words);

}  // namespace tendril::command
