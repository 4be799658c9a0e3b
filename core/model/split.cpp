// Rule 16: breaking a spline beam on a simple particle (thesis fig. 4.33),
// and the rest length of one beam edge (what a sliding joint moves, thesis
// 6.5.2). Rule 17 (a shared particle) is rule 5 then rule 16, in Lua.
#include <cmath>

#include "model/model.hpp"

namespace tendril {

std::pair<ParticleId, BlockId> Model::split_beam(BlockId b, ParticleId p) {
  require_block(b, "split");
  require_particle(p, "split");
  const Block& blk = blocks[b];
  if (blk.kind != BlockKind::Beam) throw ModelError("split: block " + std::to_string(b) + " is not a beam");
  if (particles.passive[p]) throw ModelError("split: particle " + std::to_string(p) + " is passive");
  const std::vector<BlockId> bs = blocks_of(p);
  if (bs.size() != 1 || bs[0] != b)
    throw ModelError("split: particle " + std::to_string(p) + " is " + state_name(state(p)) + " on " +
                     std::to_string(bs.size()) + " block(s); only a particle of beam " + std::to_string(b) +
                     " alone breaks it (explode it from the others first: rule 17)");
  const std::vector<Dart> ds = darts_of(p);
  if (ds.size() != 2 || map.alpha(1, ds[0]) != ds[1])
    throw ModelError("split: particle " + std::to_string(p) + " is an end of beam " + std::to_string(b) +
                     "; only interior particles break it");
  // The dart of p that starts the segment after p in path order.
  const std::vector<Dart> seg = path_darts(b);
  Dart out = kNoDart;
  for (std::size_t k = 0; k < seg.size(); ++k)
    if (dart_particle[seg[k]] == p && (k > 0 || blk.closed)) out = seg[k];
  if (out == kNoDart) throw ModelError("split: particle " + std::to_string(p) + " is not interior to beam " + std::to_string(b));
  const bool closed = blk.closed;
  ParticleId q = new_particle(particles.position[p]);
  particles.velocity[q] = particles.velocity[p];
  particles.lock[q] = particles.lock[p];
  particles.orientation[q] = particles.orientation[p];
  particles.angular_velocity[q] = particles.angular_velocity[p];
  remove_hinge(out);
  map.unlink(1, out);
  rehome_dart(out, q);  // rebinds the edge element; a Beam6 end keeps its global frame
  BlockId nb = b;
  if (closed) {
    blocks[b].closed = false;
    blocks[b].dart = out;  // the opened ring starts at q and ends at p
  } else {
    const Section section = blk.section;
    const std::uint8_t dofs = blk.dofs;
    const RestShape rest = blk.rest;
    nb = new_block(BlockKind::Beam, section, false);
    blocks[nb].dofs = dofs;
    blocks[nb].rest = rest;
    blocks[nb].dart = out;
    std::size_t moved = 0;
    Dart d = out;
    while (true) {
      const Dart e = map.alpha(0, d);
      dart_block[d] = nb;
      dart_block[e] = nb;
      moved += 2;
      const Dart next = map.alpha(1, e);
      if (next == e) break;
      d = next;
    }
    blocks[b].darts -= moved;
    blocks[nb].darts = moved;
  }
  return {q, nb};
}

void Model::set_rest_length(ParticleId a, ParticleId b, double length) {
  require_particle(a, "rest_length");
  require_particle(b, "rest_length");
  if (!(length > 0) || !std::isfinite(length))
    throw ModelError("rest_length: must be a finite number > 0, got " + std::to_string(length));
  Dart d = find_edge(a, b, BlockKind::Beam);
  if (d == kNoDart) d = find_edge(a, b, BlockKind::Cable);
  if (d == kNoDart) d = find_edge(a, b, BlockKind::Bar);
  if (d == kNoDart)
    throw ModelError("rest_length: particles " + std::to_string(a) + " and " + std::to_string(b) +
                     " are not consecutive on a beam, a cable or a bar");
  set_edge_rest_length(d, length);
  if (const ElementIndex e = dart_bar[d]; e != kNone) {
    unbind_bar(e);
    bars[e].rest_length = length;
    bind_bar(e);
  }
  refresh_beam6(d);
}

double Model::edge_rest_length(ParticleId a, ParticleId b) const {
  require_particle(a, "rest_length");
  require_particle(b, "rest_length");
  Dart d = find_edge(a, b, BlockKind::Beam);
  if (d == kNoDart) d = find_edge(a, b, BlockKind::Cable);
  if (d == kNoDart) d = find_edge(a, b, BlockKind::Bar);
  if (d == kNoDart)
    throw ModelError("rest_length: particles " + std::to_string(a) + " and " + std::to_string(b) +
                     " are not consecutive on a beam, a cable or a bar");
  return rest_length[d];
}

}  // namespace tendril
