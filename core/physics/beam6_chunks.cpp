#include "physics/beam6_chunks.hpp"

#include <algorithm>

#include "physics/bar_chunks.hpp"
#include "physics/chunk_items.hpp"

namespace tendril {

namespace {
// The distinct chunks of an element's ends: i's, then j's.
int chunks_of(ParticleId i, ParticleId j, std::uint32_t shift, std::uint32_t (&out)[2]) {
  out[0] = i >> shift;
  out[1] = j >> shift;
  return out[1] == out[0] ? 1 : 2;
}
}  // namespace

std::size_t Beam6Chunks::entry_count() const {
  std::size_t n = 0;
  for (std::size_t c = 0; c < begin.size(); ++c) n += end[c] - begin[c];
  return n;
}

void Beam6Chunks::update(const Beam6Plan& from, std::uint32_t shift, std::size_t n_chunks) {
  const bool same_chunks = shift == shift_ && n_chunks >= begin.size() && derivations + patches > 0;
  if (same_chunks && from_values_ == from.values()) {
    while (begin.size() < n_chunks) append_empty_chunk();  // new particles past the last chunk: no element there
    return;
  }
  if (!(same_chunks && from_values_ == from.patched_from() && patch(from, n_chunks))) derive(from, shift, n_chunks);
  from_values_ = from.values();
}

void Beam6Chunks::put(const Beam6Plan& from, std::uint32_t e, std::uint32_t at) {
  plan.copy_entry(from, e, at);
  place_of_[e] = at;
}

void Beam6Chunks::derive(const Beam6Plan& from, std::uint32_t shift, std::size_t n_chunks) {
  const std::uint32_t n = std::uint32_t(from.i.size());
  std::vector<std::uint32_t> count(n_chunks, 0);
  std::uint32_t at_chunk[2];
  for (std::uint32_t e = 0; e < n; ++e) {
    const int c = chunks_of(from.i[e], from.j[e], shift, at_chunk);
    for (int s = 0; s < c; ++s) ++count[at_chunk[s]];
  }
  begin.resize(n_chunks);
  end.resize(n_chunks);
  limit.resize(n_chunks);
  std::uint32_t entries = 0;
  for (std::size_t c = 0; c < n_chunks; ++c) {
    begin[c] = end[c] = entries;
    limit[c] = entries + count[c] + BarChunks::room(count[c]);
    entries = limit[c];
  }
  plan.resize(0);
  plan.resize(entries);
  place_of_.resize(n);
  for (std::uint32_t e = 0; e < n; ++e) {
    const int c = chunks_of(from.i[e], from.j[e], shift, at_chunk);
    for (int s = 0; s < c; ++s) put(from, e, end[at_chunk[s]]++);
  }
  for (std::size_t c = 0; c < n_chunks; ++c) plan.find_runs(begin[c], end[c]);
  shift_ = shift;
  ++derivations;
}

// As HingeChunks::patch: every element the plan wrote leaves the chunks of
// its old ends and joins those of its ends now (where it is still in the
// plan); each chunk touched is written again in model order. False when a
// chunk outgrew its room.
bool Beam6Chunks::patch(const Beam6Plan& from, std::size_t n_chunks) {
  while (begin.size() < n_chunks) append_empty_chunk();
  const std::vector<std::uint32_t>& touched = from.patched();
  const std::size_t old_n = place_of_.size(), new_n = from.i.size();
  affected_.clear();
  std::uint32_t at_chunk[2];
  for (std::uint32_t e : touched) {
    if (e < old_n) {
      const std::uint32_t at = place_of_[e];
      const int n = chunks_of(plan.i[at], plan.j[at], shift_, at_chunk);
      affected_.insert(affected_.end(), at_chunk, at_chunk + n);
    }
    if (e < new_n) {
      const int n = chunks_of(from.i[e], from.j[e], shift_, at_chunk);
      affected_.insert(affected_.end(), at_chunk, at_chunk + n);
    }
  }
  std::sort(affected_.begin(), affected_.end());
  affected_.erase(std::unique(affected_.begin(), affected_.end()), affected_.end());
  place_of_.resize(new_n);
  for (std::uint32_t c : affected_) {
    chunk_items(begin[c], end[c], [&](std::uint32_t at) { return plan.elements[at]; }, touched, new_n,
                [&](std::uint32_t e) { return (from.i[e] >> shift_) == c || (from.j[e] >> shift_) == c; }, items_);
    if (items_.size() > limit[c] - begin[c]) return false;
    end[c] = begin[c];
    for (std::uint32_t e : items_) put(from, e, end[c]++);
    std::fill(plan.elements.begin() + end[c], plan.elements.begin() + limit[c], kNone);
    plan.find_runs(begin[c], end[c]);
  }
  ++patches;
  return true;
}

void Beam6Chunks::append_empty_chunk() {
  const std::uint32_t at = std::uint32_t(plan.i.size()), room = BarChunks::room(0);
  begin.push_back(at);
  end.push_back(at);
  limit.push_back(at + room);
  plan.resize(at + room);
}

}  // namespace tendril
