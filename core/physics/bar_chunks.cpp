#include "physics/bar_chunks.hpp"

#include <algorithm>

#include "physics/equal_blocks.hpp"

namespace tendril {

std::uint32_t BarChunks::chunk_shift_for(std::size_t capacity) {
  std::uint32_t s = 10;
  while (s < 14 && (std::size_t(1) << (s + 1)) * 16 <= capacity) ++s;
  return s;
}

bool BarChunks::current(const Model& m) const {
  const EditList& edits = m.bars.edits;
  return model_ == &m && revision_ == m.revision && capacity_ == m.particles.capacity() &&
         edits.clean_since(revision_);
}

std::size_t BarChunks::bar_count() const {
  std::size_t n = 0;
  for (const Chunk& c : chunks) n += c.bars_end - c.bars_begin;
  return n;
}

std::size_t BarChunks::crossing_count() const {
  std::size_t n = 0;
  for (const Chunk& c : chunks) n += c.bars_end - c.crossing_begin;
  return n;
}

void BarChunks::update(Model& m) {
  if (current(m)) return;
  const EditList& edits = m.bars.edits;
  const bool patchable = model_ == &m && shift == chunk_shift_for(m.particles.capacity()) &&
                         edits.lists_since(revision_);
  if (!(patchable && patch(m))) derive(m);
  m.bars.edits.restart(m.revision);
}

// Model bar e (b) at place `at`: ends ordered, k = EA / L (eq. 3.32).
void BarChunks::put(const Bar& b, std::uint32_t e, std::uint32_t at) {
  i[at] = std::min(b.i, b.j);
  j[at] = std::max(b.i, b.j);
  k[at] = b.EA / b.rest_length;
  rest[at] = b.rest_length;
  prestress[at] = b.prestress;
  cable[at] = b.tension_only;
  model_bar[at] = e;
  place_of[e] = at;
}

void BarChunks::mark_blocks(const Chunk& ch) {
  mark_equal_blocks(ch.bars_begin, ch.bars_end, kBlock, [&](std::uint32_t e, std::uint32_t f) {
    return same_bits(k[e], k[f]) && same_bits(rest[e], rest[f]) && same_bits(prestress[e], prestress[f]) &&
           cable[e] == cable[f];
  }, same.begin() + ch.block_begin);
}

void BarChunks::derive(const Model& m) {
  const Particles& P = m.particles;
  shift = chunk_shift_for(P.capacity());
  const std::size_t n_chunks = (P.capacity() >> shift) + 1;
  chunks.assign(n_chunks, Chunk{});
  derive_particles(m);
  // Bars: per chunk, its interior bars then its crossing ones, each in the
  // model's order, then its room.
  const std::size_t n_bars = m.bars.awake;
  const Bar* bars = m.bars.awake_begin();
  std::vector<std::uint32_t> interior(n_chunks + 1, 0), crossing(n_chunks + 1, 0);
  for (std::size_t e = 0; e < n_bars; ++e) {
    const ParticleId a = std::min(bars[e].i, bars[e].j), b = std::max(bars[e].i, bars[e].j);
    ++((a >> shift) == (b >> shift) ? interior : crossing)[(a >> shift) + 1];
  }
  std::uint32_t bar = 0, slot = 0, blocks = 0;
  for (std::size_t c = 0; c < n_chunks; ++c) {
    Chunk& ch = chunks[c];
    ch.bars_begin = bar;
    ch.crossing_begin = bar + interior[c + 1];
    ch.bars_end = ch.crossing_begin + crossing[c + 1];
    ch.bars_limit = ch.bars_end + room(ch.bars_end - ch.bars_begin);
    ch.slot_begin = slot;
    ch.slot_limit = slot + crossing[c + 1] + room(crossing[c + 1]);
    ch.block_begin = blocks;
    interior[c + 1] = ch.bars_begin;  // now: the next free place of each kind
    crossing[c + 1] = ch.crossing_begin;
    bar = ch.bars_limit;
    slot = ch.slot_limit;
    blocks += (ch.bars_limit - ch.bars_begin + kBlock - 1) / kBlock;
  }
  i.resize(bar);
  j.resize(bar);
  k.resize(bar);
  rest.resize(bar);
  prestress.resize(bar);
  cable.resize(bar);
  model_bar.assign(bar, kNone);
  place_of.resize(n_bars);
  for (std::size_t e = 0; e < n_bars; ++e) {
    const Bar& b = bars[e];
    const ParticleId lo = std::min(b.i, b.j), hi = std::max(b.i, b.j);
    const std::size_t c = lo >> shift;
    put(b, std::uint32_t(e), ((hi >> shift) == c ? interior : crossing)[c + 1]++);
    chunks[c].cables |= b.tension_only;
  }
  // Blocks whose bars share their constants, bit for bit.
  same.assign(blocks, 0);
  for (const Chunk& ch : chunks) mark_blocks(ch);
  slot_force.resize(slot);
  slot_stiffness.resize(slot);
  derive_inboxes();
  model_ = &m;
  revision_ = m.revision;
  capacity_ = P.capacity();
  ++derivations;
}

// Every model bar an edit touched leaves its old place (where it was
// awake) and joins its chunk again (where it is awake now); the chunks
// touched are written again from the model in model order. False when a
// chunk outgrew its room (then the copy is derived afresh).
bool BarChunks::patch(const Model& m) {
  // New particles past the last chunk: empty chunks after the others.
  const std::size_t n_chunks = (m.particles.capacity() >> shift) + 1;
  if (n_chunks < chunks.size()) return false;
  while (chunks.size() < n_chunks) append_empty_chunk();
  const std::size_t old_awake = place_of.size(), new_awake = m.bars.awake;
  if (!m.bars.edits.touched(old_awake, new_awake, touched_)) return false;
  const Bar* bars = m.bars.awake_begin();
  affected_.clear();
  joining_.clear();
  for (std::uint32_t e : touched_) {
    if (e < old_awake) {
      const std::uint32_t at = place_of[e];
      model_bar[at] = kNone;
      affected_.push_back(i[at] >> shift);
    }
    if (e < new_awake) {
      const std::uint32_t c = std::min(bars[e].i, bars[e].j) >> shift;
      joining_.push_back({c, e});
      affected_.push_back(c);
    }
  }
  std::sort(affected_.begin(), affected_.end());
  affected_.erase(std::unique(affected_.begin(), affected_.end()), affected_.end());
  std::sort(joining_.begin(), joining_.end());
  place_of.resize(new_awake);
  std::size_t next = 0;
  for (std::uint32_t c : affected_) {
    Chunk& ch = chunks[c];
    interior_.clear();
    crossing_.clear();
    for (std::uint32_t at = ch.bars_begin; at < ch.bars_end; ++at)
      if (model_bar[at] != kNone) (at < ch.crossing_begin ? interior_ : crossing_).push_back(model_bar[at]);
    const std::size_t old_interior = interior_.size(), old_crossing = crossing_.size();
    for (; next < joining_.size() && joining_[next].first == c; ++next) {
      const std::uint32_t e = joining_[next].second;
      const bool crosses = (std::max(bars[e].i, bars[e].j) >> shift) != c;
      (crosses ? crossing_ : interior_).push_back(e);
    }
    // Both runs are in model order already: merge them.
    std::inplace_merge(interior_.begin(), interior_.begin() + std::ptrdiff_t(old_interior), interior_.end());
    std::inplace_merge(crossing_.begin(), crossing_.begin() + std::ptrdiff_t(old_crossing), crossing_.end());
    if (interior_.size() + crossing_.size() > ch.bars_limit - ch.bars_begin ||
        crossing_.size() > ch.slot_limit - ch.slot_begin)
      return false;
    std::uint32_t at = ch.bars_begin;
    ch.cables = false;
    for (std::uint32_t e : interior_) put(bars[e], e, at++), ch.cables |= bars[e].tension_only;
    ch.crossing_begin = at;
    for (std::uint32_t e : crossing_) put(bars[e], e, at++), ch.cables |= bars[e].tension_only;
    ch.bars_end = at;
    std::fill(model_bar.begin() + at, model_bar.begin() + ch.bars_limit, kNone);
    mark_blocks(ch);
  }
  derive_particles(m);
  derive_inboxes();
  revision_ = m.revision;
  capacity_ = m.particles.capacity();
  ++patches;
  return true;
}

void BarChunks::append_empty_chunk() {
  Chunk ch;
  ch.bars_begin = ch.crossing_begin = ch.bars_end = std::uint32_t(i.size());
  ch.bars_limit = ch.bars_end + room(0);
  ch.slot_begin = std::uint32_t(slot_force.size());
  ch.slot_limit = ch.slot_begin + room(0);
  ch.block_begin = std::uint32_t(same.size());
  chunks.push_back(ch);
  for (auto* column : {&i, &j}) column->resize(ch.bars_limit);
  for (auto* column : {&k, &rest, &prestress}) column->resize(ch.bars_limit);
  cable.resize(ch.bars_limit);
  model_bar.resize(ch.bars_limit, kNone);
  same.resize(ch.block_begin + (room(0) + kBlock - 1) / kBlock, 0);
  slot_force.resize(ch.slot_limit);
  slot_stiffness.resize(ch.slot_limit);
}

// The integrated particles: a counting sort of `integrated` by chunk (stable).
void BarChunks::derive_particles(const Model& m) {
  const Particles& P = m.particles;
  const std::size_t n_chunks = chunks.size();
  std::vector<std::uint32_t> at(n_chunks + 1, 0);
  for (ParticleId p : P.integrated.raw()) ++at[(p >> shift) + 1];
  for (std::size_t c = 0; c < n_chunks; ++c) at[c + 1] += at[c];
  for (std::size_t c = 0; c < n_chunks; ++c) chunks[c].particles_begin = at[c], chunks[c].particles_end = at[c + 1];
  particles.resize(P.integrated.size());
  for (ParticleId p : P.integrated.raw()) particles[at[p >> shift]++] = p;
}

// Inboxes: the crossing bars by the chunk of j, in slot order.
void BarChunks::derive_inboxes() {
  const std::size_t n_chunks = chunks.size();
  std::vector<std::uint32_t> in(n_chunks + 1, 0);
  for (std::size_t c = 0; c < n_chunks; ++c)
    for (std::uint32_t e = chunks[c].crossing_begin; e < chunks[c].bars_end; ++e) ++in[(j[e] >> shift) + 1];
  for (std::size_t c = 0; c < n_chunks; ++c) in[c + 1] += in[c];
  for (std::size_t c = 0; c < n_chunks; ++c) {
    chunks[c].inbox_begin = in[c];
    chunks[c].inbox_end = in[c + 1];
    chunks[c].first_source = std::uint32_t(c);
  }
  inbox_particle.resize(in[n_chunks]);
  inbox_slot.resize(in[n_chunks]);
  for (std::size_t c = 0; c < n_chunks; ++c)
    for (std::uint32_t e = chunks[c].crossing_begin; e < chunks[c].bars_end; ++e) {
      const std::size_t target = j[e] >> shift;
      const std::uint32_t at_in = in[target]++;
      inbox_particle[at_in] = j[e];
      inbox_slot[at_in] = chunks[c].slot_begin + (e - chunks[c].crossing_begin);
      chunks[target].first_source = std::min(chunks[target].first_source, std::uint32_t(c));
    }
}

}  // namespace tendril
