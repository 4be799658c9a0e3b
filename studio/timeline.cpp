#include "timeline.hpp"

#include "command/replay.hpp"

#include <memory>
#include <sstream>

namespace tendril::studio {

JournalPoint point_of(const lua::Scene& s, std::string label) {
  return {s.trace.mark(), s.journal.entries.size(), s.solver.steps(), s.solver.residual(), std::move(label),
          s.solver.failed_steps().size()};
}

std::vector<std::string> lines_up_to(const lua::Scene& s, const JournalPoint& p) {
  return s.trace.lines_until(s.solver, p.mark, p.steps, p.failures);
}

bool is_production(const std::string& line) {
  return line.rfind("steps ", 0) != 0 && line != "failed_step" && line.rfind("#", 0) != 0;
}

std::vector<std::size_t> productions(const lua::Scene& s) {
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < s.trace.size(); ++k)
    if (is_production(s.trace.line(k))) out.push_back(k);
  return out;
}

void replay_lines(const std::vector<std::string>& lines, Model& m, Solver& solver) {
  std::stringstream in;
  for (const std::string& line : lines) in << line << '\n';
  replay_trace(in, "studio session", m, solver);
}

void restore(lua::Scene& s, const JournalPoint& p) {
  const std::vector<std::string> lines = lines_up_to(s, p);
  // The scene owns its model and solver by value (lua_scene.hpp); they are
  // rebuilt in place from its own journal, which replays bit for bit.
  std::destroy_at(&s.solver);
  std::destroy_at(&s.model);
  new (&s.model) Model();
  new (&s.solver) Solver(s.model);
  replay_lines(lines, s.model, s.solver);
  s.trace.rewind(p.mark);
  s.journal.entries.resize(p.journal);
  s.neighbours_built_at = {~0ull, 0};
}

}  // namespace tendril::studio
