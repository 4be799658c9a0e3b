#pragma once
// A command as a JSON message, for the studio's protocol and any front end:
//   {"command": "cable", "args": {"a": 3, "b": 4, "EA": 1e6, ...}}
// ids, counts and indices as integers, flags as booleans, vectors as
// [x, y, z], lists as arrays; an optional argument is left out.
#include <nlohmann/json.hpp>

#include <utility>

#include "command/command.hpp"

namespace tendril::command {

nlohmann::json to_json(const Command& c, const Args& a);
// The command and its arguments (types and keys only: apply() checks the
// values). Throws CommandError naming the argument at fault, ModelError for
// a message without a known command.
std::pair<const Command*, Args> from_json(const nlohmann::json& message);
nlohmann::json result_json(const Result& r);
// Every declaration: [{name, summary, kind, lua, journal, returns, params:
// [{name, type, doc, min, max, above, choices, optional}]}].
nlohmann::json declarations_json();

}  // namespace tendril::command
