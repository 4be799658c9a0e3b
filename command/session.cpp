#include "command/session.hpp"

#include <algorithm>
#include <optional>

#include "command/check.hpp"
#include "command/journal_line.hpp"
#include "command/registry.hpp"
#include "physics/solver.hpp"

namespace tendril::command {

namespace {

[[noreturn]] void refuse(const Command& c, const ArgumentError& e) {
  throw CommandError(c, e.param, describe(c, e), e.what());
}

}  // namespace

Result apply(Session& s, const Command& c, Args args, const std::string& description) {
  try {
    check_args(c, args, s.model);
  } catch (const ArgumentError& e) {
    refuse(c, e);
  }
  const bool production = c.effect == Effect::Topology && s.journal && s.model.changes == nullptr;
  std::optional<Entry> entry;
  if (production) entry.emplace(s, c.name, description);
  Target target{s.model, s.solver};
  Result r;
  try {
    r = c.apply(target, args);
  } catch (const ArgumentError& e) {
    refuse(c, e);
  }
  if (c.effect == Effect::Steps) return r;
  // The line carries exactly what its decoder reads back (goal, formulation).
  if (c.on_line)
    for (std::size_t k = 0; k < args.size(); ++k)
      if (c.params[k].optional) args[k].given = c.on_line(args, k);
  const std::string line = encode(c, args);
  if (s.trace) s.trace->record(s.solver, line);
  if (entry) {
    if (description.empty()) entry->describe(line.substr(std::min(line.size(), std::string(c.name).size() + 1)));
    entry->done();
  }
  return r;
}

Result apply(Session& s, std::string_view name, Args args, const std::string& description) {
  return apply(s, get(name), std::move(args), description);
}

void record(Session& s, const Command& c, const Args& args) {
  if (s.trace) s.trace->record(s.solver, encode(c, args));
}

void record(Session& s, std::string_view name, const Args& args) { record(s, get(name), args); }

Entry::Entry(Session& s, std::string name, std::string description)
    : session_(s), owner_(s.journal && s.model.changes == nullptr) {
  if (!owner_) return;
  entry_.step = s.solver.steps();
  entry_.time = s.solver.time();
  entry_.rule = std::move(name);
  entry_.args = std::move(description);
  s.model.changes = &entry_.changes;
}

Entry::~Entry() {
  if (!owner_) return;
  session_.model.changes = nullptr;
  if (done_) session_.journal->entries.push_back(std::move(entry_));
}

}  // namespace tendril::command
