#include "model/journal.hpp"

#include <algorithm>
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
  std::string out = "#  step  time  rule  arguments  created  deleted  changed\n";
  std::size_t n = 0;
  for (const JournalEntry& e : entries) {
    char head[96];
    std::snprintf(head, sizeof head, "%zu\t%llu\t%.6g\t", ++n, static_cast<unsigned long long>(e.step), e.time);
    const ChangeSet& c = e.changes;
    const std::string created = join(ids("p", c.created_particles), ids("b", c.created_blocks));
    const std::string deleted = join(ids("p", c.deleted_particles), ids("b", c.deleted_blocks));
    // Blocks that were there before and after: grown, connected, disconnected.
    std::vector<std::uint32_t> kept;
    for (std::uint32_t b : c.changed_blocks)
      if (std::find(c.created_blocks.begin(), c.created_blocks.end(), b) == c.created_blocks.end() &&
          std::find(c.deleted_blocks.begin(), c.deleted_blocks.end(), b) == c.deleted_blocks.end())
        kept.push_back(b);
    const std::string changed = ids("b", kept);
    out += head + e.rule + "\t" + (e.args.empty() ? "-" : e.args) + "\t" + (created.empty() ? "-" : created) + "\t" +
           (deleted.empty() ? "-" : deleted) + "\t" + (changed.empty() ? "-" : changed) + "\n";
  }
  return out;
}

}  // namespace tendril
