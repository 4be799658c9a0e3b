#pragma once
// Places in a scene's journal (its replayable trace, io/trace.hpp): the
// model after any production, or at an equilibrium, rebuilt by replaying the
// trace up to there on an empty model. Undo, the timeline and branching from
// a snapshot are all this one operation.
#include <cstdint>
#include <string>
#include <vector>

#include "lua_scene.hpp"

namespace tendril::studio {

struct JournalPoint {
  Trace::Mark mark;          // the trace's lines up to here
  std::size_t journal = 0;   // entries of the assembly sequence up to here
  std::uint64_t steps = 0;   // solver steps (may lie after the mark's last line)
  double residual = 0;
  std::string label;
  std::size_t failures = 0;  // failed solver steps (Solver::failed_steps) up to here
};

JournalPoint point_of(const lua::Scene& s, std::string label);
// The trace up to p (the steps after its last line included).
std::vector<std::string> lines_up_to(const lua::Scene& s, const JournalPoint& p);
// The operation lines of the trace (everything but "steps", "failed_step"
// and comments):
// production k of the timeline is the k-th of them (1-based; 0 is empty).
std::vector<std::size_t> productions(const lua::Scene& s);
bool is_production(const std::string& trace_line);
// Replays lines onto an empty model and solver.
void replay_lines(const std::vector<std::string>& lines, Model& m, Solver& solver);
// The scene's model becomes the model at p; the journal after p is dropped.
// Handles the scene's Lua code holds to things made after p go stale.
void restore(lua::Scene& s, const JournalPoint& p);

}  // namespace tendril::studio
