#include "model/journal.hpp"

#include <cstdio>

namespace tendril {

namespace {
std::string ids(const char* prefix, const std::vector<std::uint32_t>& v) {
  std::string out;
  for (std::uint32_t id : v) out += (out.empty() ? "" : " ") + std::string(prefix) + std::to_string(id);
  return out;
}

std::string join(const std::string& a, const std::string& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return a + " " + b;
}
}  // namespace

std::string Journal::assembly_sequence() const {
  std::string out = "#  step  time  rule  arguments  created  deleted\n";
  std::size_t n = 0;
  for (const JournalEntry& e : entries) {
    if (e.changes.empty()) continue;  // moves and settings are in the trace, not the assembly
    char head[96];
    std::snprintf(head, sizeof head, "%zu\t%llu\t%.6g\t", ++n, static_cast<unsigned long long>(e.step), e.time);
    const std::string created = join(ids("p", e.changes.created_particles), ids("b", e.changes.created_blocks));
    const std::string deleted = join(ids("p", e.changes.deleted_particles), ids("b", e.changes.deleted_blocks));
    out += head + e.rule + "\t" + (e.args.empty() ? "-" : e.args) + "\t" + (created.empty() ? "-" : created) + "\t" +
           (deleted.empty() ? "-" : deleted) + "\n";
  }
  return out;
}

}  // namespace tendril
