#include "physics/hinge_chunks.hpp"

#include <iterator>

#include "physics/equal_blocks.hpp"

namespace tendril {

namespace {
// The distinct chunks of a hinge's ends, at most three.
int chunks_of(const Hinge& h, std::uint32_t shift, std::uint32_t (&out)[3]) {
  int n = 0;
  for (ParticleId p : {h.i, h.j, h.k}) {
    const std::uint32_t c = p >> shift;
    bool seen = false;
    for (int s = 0; s < n; ++s) seen |= out[s] == c;
    if (!seen) out[n++] = c;
  }
  return n;
}
}  // namespace

void HingeChunks::derive(const Model& m, std::uint32_t shift, std::size_t n_chunks) {
  const Hinge* hinges = m.hinges.awake_begin();
  const std::uint32_t n = std::uint32_t(m.hinges.awake_end() - hinges);
  begin.assign(n_chunks + 1, 0);
  std::uint32_t at_chunk[3];
  for (std::uint32_t e = 0; e < n; ++e) {
    const int c = chunks_of(hinges[e], shift, at_chunk);
    for (int s = 0; s < c; ++s) ++begin[at_chunk[s] + 1];
  }
  for (std::size_t c = 0; c < n_chunks; ++c) begin[c + 1] += begin[c];
  const std::uint32_t items = begin[n_chunks];
  hinge.resize(items);
  i.resize(items);
  j.resize(items);
  k.resize(items);
  EI.resize(items);
  rest.resize(items);
  std::vector<std::uint32_t> next(begin.begin(), begin.end() - 1);
  for (std::uint32_t e = 0; e < n; ++e) {
    const Hinge& h = hinges[e];
    const int c = chunks_of(h, shift, at_chunk);
    for (int s = 0; s < c; ++s) {
      const std::uint32_t at = next[at_chunk[s]]++;
      hinge[at] = e;
      i[at] = h.i, j[at] = h.j, k[at] = h.k;
      EI[at] = h.EI;
      rest[at] = h.rest_curvature;
    }
  }
  block_begin.assign(n_chunks, 0);
  same.clear();
  for (std::size_t c = 0; c < n_chunks; ++c) {
    block_begin[c] = std::uint32_t(same.size());
    mark_equal_blocks(begin[c], begin[c + 1], kBlock, [&](std::uint32_t e, std::uint32_t f) {
      return same_bits(EI[e], EI[f]) && same_bits(rest[e], rest[f]);
    }, std::back_inserter(same));
  }
  model_ = &m;
  revision_ = m.revision;
  capacity_ = m.particles.capacity();
  shift_ = shift;
}

}  // namespace tendril
