#include "command/replay.hpp"

#include <istream>
#include <sstream>

#include "command/journal_line.hpp"
#include "command/registry.hpp"
#include "command/check.hpp"
#include "physics/solver.hpp"

namespace tendril::command {

void replay(std::istream& in, const std::string& name, Session& s) {
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    // Format 1 was written while Leapfrog was the default integrator, so its
    // steps are Leapfrog's and its model's setting too ("auto" since format 2).
    if (number == 1 && line.rfind("# tendril journal 1:", 0) == 0) s.solver.settings.integrator = Integrator::Leapfrog;
    if (line.empty() || line[0] == '#') continue;
    const std::string where = name + ":" + std::to_string(number);
    std::istringstream words(line);
    std::string op;
    words >> op;
    const Command* c = find(op);
    if (!c) throw ModelError(where + ": unknown operation '" + op + "'");
    try {
      Args args;
      try {
        args = decode(*c, words);
      } catch (const ArgumentError& e) {
        throw CommandError(*c, e.param, describe(*c, e), e.what());
      }
      apply(s, *c, std::move(args));
    } catch (const NumericalError&) {
      throw;
    } catch (const ModelError& e) {
      const std::string what = e.what();
      if (what.rfind(name + ":", 0) == 0) throw;
      throw ModelError(where + ": " + what);
    }
  }
}

}  // namespace tendril::command

namespace tendril {

void replay_trace(std::istream& in, const std::string& name, Model& m, Solver& s) {
  command::Session session{m, s};
  command::replay(in, name, session);
}

}  // namespace tendril
