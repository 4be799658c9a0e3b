#pragma once
// Replays a journal's trace (core/io/trace.hpp) on an empty model: each line
// is decoded by its command's declaration and applied through the session,
// so a replay checks every value exactly as a scene's call is checked.
#include <iosfwd>
#include <string>

#include "command/session.hpp"

namespace tendril::command {

// Throws ModelError naming the line at fault ("NAME:LINE: ...").
void replay(std::istream& in, const std::string& name, Session& s);

}  // namespace tendril::command

namespace tendril {

// The model and solver only (nothing recorded).
void replay_trace(std::istream& in, const std::string& name, Model& m, Solver& s);

}  // namespace tendril
