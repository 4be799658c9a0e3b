#pragma once
// The journal (DESIGN principle 3): every production with its step, time,
// rule, arguments and the ids it created and deleted, in order. Printed, it is
// the chronological assembly sequence of thesis 6.2 and 6.3.1.
#include <cstdint>
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tendril {

struct JournalEntry {
  std::uint64_t step = 0;
  double time = 0;
  std::string rule;
  std::string args;
  ChangeSet changes;
};

struct Journal {
  std::vector<JournalEntry> entries;
  // One line per production (every rule applied and every topological
  // operation, whether it created something or not): step, time, rule,
  // arguments, created, deleted, and the blocks it changed that were there
  // before and after (a beam grown, blocks connected or disconnected).
  std::string assembly_sequence() const;
};

}  // namespace tendril
