#include "physics/hinge_chunks.hpp"

#include <algorithm>

#include "physics/bar_chunks.hpp"
#include "physics/chunk_items.hpp"
#include "physics/equal_blocks.hpp"

namespace tendril {

namespace {
// The distinct chunks of a hinge's ends, at most three.
int chunks_of(ParticleId a, ParticleId b, ParticleId c, std::uint32_t shift, std::uint32_t (&out)[3]) {
  int n = 0;
  for (ParticleId p : {a, b, c}) {
    const std::uint32_t chunk = p >> shift;
    bool seen = false;
    for (int s = 0; s < n; ++s) seen |= out[s] == chunk;
    if (!seen) out[n++] = chunk;
  }
  return n;
}
int chunks_of(const Hinge& h, std::uint32_t shift, std::uint32_t (&out)[3]) { return chunks_of(h.i, h.j, h.k, shift, out); }
}  // namespace

bool HingeChunks::current(const Model& m, std::uint32_t shift) const {
  const EditList& edits = m.hinges.edits;
  return model_ == &m && revision_ == m.revision && capacity_ == m.particles.capacity() && shift_ == shift &&
         edits.clean_since(revision_);
}

std::size_t HingeChunks::item_count() const {
  std::size_t n = 0;
  for (std::size_t c = 0; c < begin.size(); ++c) n += end[c] - begin[c];
  return n;
}

void HingeChunks::update(Model& m, std::uint32_t shift, std::size_t n_chunks) {
  if (current(m, shift)) return;
  const EditList& edits = m.hinges.edits;
  const bool patchable = model_ == &m && shift_ == shift && edits.lists_since(revision_);
  if (!(patchable && patch(m, n_chunks))) derive(m, shift, n_chunks);
  m.hinges.edits.restart(m.revision);
}

void HingeChunks::put(const Hinge& h, std::uint32_t e, std::uint32_t at) {
  hinge[at] = e;
  i[at] = h.i, j[at] = h.j, k[at] = h.k;
  EI[at] = h.EI;
  rest[at] = h.rest_curvature;
  place_of[e] = at;
}

void HingeChunks::mark_blocks(std::uint32_t c) {
  mark_equal_blocks(begin[c], end[c], kBlock, [&](std::uint32_t e, std::uint32_t f) {
    return same_bits(EI[e], EI[f]) && same_bits(rest[e], rest[f]);
  }, same.begin() + block_begin[c]);
}

void HingeChunks::derive(const Model& m, std::uint32_t shift, std::size_t n_chunks) {
  const Hinge* hinges = m.hinges.awake_begin();
  const std::uint32_t n = std::uint32_t(m.hinges.awake_end() - hinges);
  std::vector<std::uint32_t> count(n_chunks, 0);
  std::uint32_t at_chunk[3];
  for (std::uint32_t e = 0; e < n; ++e) {
    const int c = chunks_of(hinges[e], shift, at_chunk);
    for (int s = 0; s < c; ++s) ++count[at_chunk[s]];
  }
  begin.resize(n_chunks);
  end.resize(n_chunks);
  limit.resize(n_chunks);
  block_begin.resize(n_chunks);
  std::uint32_t items = 0, blocks = 0;
  for (std::size_t c = 0; c < n_chunks; ++c) {
    begin[c] = end[c] = items;
    limit[c] = items + count[c] + BarChunks::room(count[c]);
    block_begin[c] = blocks;
    items = limit[c];
    blocks += (limit[c] - begin[c] + kBlock - 1) / kBlock;
  }
  hinge.assign(items, kNone);
  i.resize(items);
  j.resize(items);
  k.resize(items);
  EI.resize(items);
  rest.resize(items);
  place_of.resize(n);
  for (std::uint32_t e = 0; e < n; ++e) {
    const int c = chunks_of(hinges[e], shift, at_chunk);
    for (int s = 0; s < c; ++s) put(hinges[e], e, end[at_chunk[s]]++);
  }
  same.assign(blocks, 0);
  for (std::uint32_t c = 0; c < n_chunks; ++c) mark_blocks(c);
  model_ = &m;
  revision_ = m.revision;
  capacity_ = m.particles.capacity();
  shift_ = shift;
  ++derivations;
}

// As BarChunks::patch: every touched hinge leaves the chunks of its old
// ends (where it was awake) and joins those of its ends now (where it is
// awake); each chunk touched is written again in model order. False when
// a chunk outgrew its room.
bool HingeChunks::patch(const Model& m, std::size_t n_chunks) {
  if (n_chunks < begin.size()) return false;
  while (begin.size() < n_chunks) append_empty_chunk();
  const std::size_t old_awake = place_of.size(), new_awake = m.hinges.awake;
  if (!m.hinges.edits.touched(old_awake, new_awake, touched_)) return false;
  const Hinge* hinges = m.hinges.awake_begin();
  affected_.clear();
  std::uint32_t at_chunk[3];
  for (std::uint32_t e : touched_) {
    if (e < old_awake) {
      const std::uint32_t at = place_of[e];
      const int n = chunks_of(i[at], j[at], k[at], shift_, at_chunk);
      affected_.insert(affected_.end(), at_chunk, at_chunk + n);
    }
    if (e < new_awake) {
      const int n = chunks_of(hinges[e], shift_, at_chunk);
      affected_.insert(affected_.end(), at_chunk, at_chunk + n);
    }
  }
  std::sort(affected_.begin(), affected_.end());
  affected_.erase(std::unique(affected_.begin(), affected_.end()), affected_.end());
  place_of.resize(new_awake);
  for (std::uint32_t c : affected_) {
    chunk_items(begin[c], end[c], [&](std::uint32_t at) { return hinge[at]; }, touched_, new_awake,
                [&](std::uint32_t e) {
                  const Hinge& h = hinges[e];
                  return (h.i >> shift_) == c || (h.j >> shift_) == c || (h.k >> shift_) == c;
                }, items_);
    if (items_.size() > limit[c] - begin[c]) return false;
    end[c] = begin[c];
    for (std::uint32_t e : items_) put(hinges[e], e, end[c]++);
    std::fill(hinge.begin() + end[c], hinge.begin() + limit[c], kNone);
    mark_blocks(c);
  }
  revision_ = m.revision;
  capacity_ = m.particles.capacity();
  ++patches;
  return true;
}

void HingeChunks::append_empty_chunk() {
  const std::uint32_t at = std::uint32_t(hinge.size()), room = BarChunks::room(0);
  begin.push_back(at);
  end.push_back(at);
  limit.push_back(at + room);
  block_begin.push_back(std::uint32_t(same.size()));
  hinge.resize(at + room, kNone);
  for (auto* column : {&i, &j, &k}) column->resize(at + room);
  EI.resize(at + room);
  rest.resize(at + room);
  same.resize(same.size() + (room + kBlock - 1) / kBlock, 0);
}

}  // namespace tendril
