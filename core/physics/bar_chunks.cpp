#include "physics/bar_chunks.hpp"

#include <algorithm>

#include "physics/equal_blocks.hpp"

namespace tendril {

std::uint32_t BarChunks::chunk_shift_for(std::size_t capacity) {
  std::uint32_t s = 10;
  while (s < 14 && (std::size_t(1) << (s + 1)) * 16 <= capacity) ++s;
  return s;
}

void BarChunks::derive(const Model& m) {
  const Particles& P = m.particles;
  shift = chunk_shift_for(P.capacity());
  const std::size_t n_chunks = (P.capacity() >> shift) + 1;
  chunks.assign(n_chunks, Chunk{});
  // Particles: a counting sort of `integrated` by chunk (stable).
  std::vector<std::uint32_t> at(n_chunks + 1, 0);
  for (ParticleId p : P.integrated.raw()) ++at[(p >> shift) + 1];
  for (std::size_t c = 0; c < n_chunks; ++c) at[c + 1] += at[c];
  for (std::size_t c = 0; c < n_chunks; ++c) chunks[c].particles_begin = at[c], chunks[c].particles_end = at[c + 1];
  particles.resize(P.integrated.size());
  for (ParticleId p : P.integrated.raw()) particles[at[p >> shift]++] = p;
  // Bars: per chunk, its interior bars then its crossing ones, each in the
  // model's order.
  const std::size_t n_bars = m.bars.awake;
  const Bar* bars = m.bars.awake_begin();
  std::vector<std::uint32_t> interior(n_chunks + 1, 0), crossing(n_chunks + 1, 0);
  for (std::size_t e = 0; e < n_bars; ++e) {
    const ParticleId a = std::min(bars[e].i, bars[e].j), b = std::max(bars[e].i, bars[e].j);
    ++((a >> shift) == (b >> shift) ? interior : crossing)[(a >> shift) + 1];
  }
  std::uint32_t bar = 0, slot = 0;
  for (std::size_t c = 0; c < n_chunks; ++c) {
    Chunk& ch = chunks[c];
    ch.bars_begin = bar;
    ch.crossing_begin = bar + interior[c + 1];
    ch.bars_end = ch.crossing_begin + crossing[c + 1];
    ch.slot_begin = slot;
    interior[c + 1] = ch.bars_begin;  // now: the next free place of each kind
    crossing[c + 1] = ch.crossing_begin;
    bar = ch.bars_end;
    slot += ch.bars_end - ch.crossing_begin;
  }
  i.resize(n_bars);
  j.resize(n_bars);
  k.resize(n_bars);
  rest.resize(n_bars);
  prestress.resize(n_bars);
  cable.resize(n_bars);
  for (std::size_t e = 0; e < n_bars; ++e) {
    const Bar& b = bars[e];
    const ParticleId lo = std::min(b.i, b.j), hi = std::max(b.i, b.j);
    const std::size_t c = lo >> shift;
    const std::uint32_t at_bar = ((hi >> shift) == c ? interior : crossing)[c + 1]++;
    i[at_bar] = lo;
    j[at_bar] = hi;
    k[at_bar] = b.EA / b.rest_length;
    rest[at_bar] = b.rest_length;
    prestress[at_bar] = b.prestress;
    cable[at_bar] = b.tension_only;
    chunks[c].cables |= b.tension_only;
  }
  // Blocks whose bars share their constants, bit for bit.
  same.clear();
  for (Chunk& ch : chunks) {
    ch.block_begin = std::uint32_t(same.size());
    mark_equal_blocks(ch.bars_begin, ch.bars_end, kBlock, [&](std::uint32_t e, std::uint32_t f) {
      return same_bits(k[e], k[f]) && same_bits(rest[e], rest[f]) && same_bits(prestress[e], prestress[f]) &&
             cable[e] == cable[f];
    }, same);
  }
  // Inboxes: the crossing bars by the chunk of j, in slot order.
  std::vector<std::uint32_t> in(n_chunks + 1, 0);
  for (std::size_t c = 0; c < n_chunks; ++c)
    for (std::uint32_t e = chunks[c].crossing_begin; e < chunks[c].bars_end; ++e) ++in[(j[e] >> shift) + 1];
  for (std::size_t c = 0; c < n_chunks; ++c) in[c + 1] += in[c];
  for (std::size_t c = 0; c < n_chunks; ++c) {
    chunks[c].inbox_begin = in[c];
    chunks[c].inbox_end = in[c + 1];
    chunks[c].first_source = std::uint32_t(c);
  }
  inbox_particle.resize(slot);
  inbox_slot.resize(slot);
  for (std::size_t c = 0; c < n_chunks; ++c)
    for (std::uint32_t e = chunks[c].crossing_begin; e < chunks[c].bars_end; ++e) {
      const std::size_t target = j[e] >> shift;
      const std::uint32_t at_in = in[target]++;
      inbox_particle[at_in] = j[e];
      inbox_slot[at_in] = chunks[c].slot_begin + (e - chunks[c].crossing_begin);
      chunks[target].first_source = std::min(chunks[target].first_source, std::uint32_t(c));
    }
  slot_force.resize(slot);
  slot_stiffness.resize(slot);
  model_ = &m;
  revision_ = m.revision;
  capacity_ = P.capacity();
}

}  // namespace tendril
