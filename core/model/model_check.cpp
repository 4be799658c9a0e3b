// The invariants every production must leave intact (DESIGN principle 2):
// map validity, embeddings, block bookkeeping, and element buffers that equal
// what a rebuild from the map would produce.
#include <cmath>
#include <sstream>

#include "model/model.hpp"

namespace tendril {

namespace {
bool near(double a, double b) { return std::abs(a - b) <= 1e-9 * (1 + std::abs(a) + std::abs(b)); }
}  // namespace

std::string Model::check_dart(Dart d) const {
  const BlockId b = dart_block[d];
  const ParticleId p = dart_particle[d];
  // 0-embedding: a vertex orbit carries one particle.
  for (int i = 1; i < 3; ++i)
    if (dart_particle[map.alpha(i, d)] != p) return "dart " + std::to_string(d) + ": vertex orbit embeds two particles";
  if (map.is_free(0, d)) return "dart " + std::to_string(d) + " has no alpha0 (an edge needs two ends)";
  Dart other = map.alpha(0, d);
  if (dart_particle[other] == p) return "dart " + std::to_string(d) + ": edge from particle " + std::to_string(p) + " to itself";
  if (!near(rest_length[d], rest_length[other])) return "dart " + std::to_string(d) + ": rest length differs across its edge";
  // Elements: one bar per edge, one hinge per interior beam vertex.
  ElementIndex e = dart_bar[d];
  if (e == kNone || e >= bars.size()) return "dart " + std::to_string(d) + " has no bar";
  const Bar& bar = bars[e];
  if (dart_bar[bar.dart] != e || (bar.dart != d && bar.dart != other && map.alpha(2, bar.dart) != d &&
                                  map.alpha(2, bar.dart) != other))
    return "bar " + std::to_string(e) + " does not point back to its edge";
  ParticleId bi = dart_particle[bar.dart], bj = dart_particle[map.alpha(0, bar.dart)];
  if (bar.i != bi || bar.j != bj) return "bar " + std::to_string(e) + " has stale particles";
  const Block& blk = blocks[b];
  if (!near(bar.rest_length, rest_length[d]) || bar.EA != blk.section.EA || bar.prestress != blk.section.prestress ||
      bar.line_mass != blk.section.line_mass || bar.tension_only != (blk.kind == BlockKind::Cable))
    return "bar " + std::to_string(e) + " parameters differ from its block and edge";
  const bool interior = blk.kind == BlockKind::Beam && !map.is_free(1, d);
  ElementIndex h = dart_hinge[d];
  if (interior != (h != kNone)) return "dart " + std::to_string(d) + (interior ? " lacks its hinge" : " has a stray hinge");
  if (interior) {
    if (h >= hinges.size()) return "dart " + std::to_string(d) + ": hinge index out of range";
    const Hinge& hg = hinges[h];
    if (hg.dart != d && hg.dart != map.alpha(1, d)) return "hinge " + std::to_string(h) + " does not point back";
    Dart hd = hg.dart;
    if (hg.i != dart_particle[map.alpha(0, hd)] || hg.j != dart_particle[hd] ||
        hg.k != dart_particle[map.alpha(0, map.alpha(1, hd))] || hg.EI != blk.section.EI)
      return "hinge " + std::to_string(h) + " is stale";
  }
  return {};
}

std::string Model::check_near(const std::vector<ParticleId>& ps) const {
  for (ParticleId p : ps) {
    if (!particles.valid(p)) continue;
    if (!particles.position[p].allFinite() || !particles.velocity[p].allFinite())
      return "particle " + std::to_string(p) + " is not finite";
    if (particles.active[p] != (particles.degree[p] > 0 && !particles.passive[p]))
      return "particle " + std::to_string(p) + " has a stale active flag";
    std::uint32_t degree = 0;
    for (Dart d : darts_of(p)) {
      ++degree;
      if (!map.alive(d) || dart_particle[d] != p) return "particle " + std::to_string(p) + " has a stale dart ring";
      if (!block_valid(dart_block[d])) return "dart " + std::to_string(d) + " belongs to a dead block";
      for (int i = 0; i < 3; ++i) {
        Dart e = map.alpha(i, d);
        if (!map.alive(e) || map.alpha(i, e) != d) return "dart " + std::to_string(d) + ": alpha" + std::to_string(i) + " is broken";
      }
      if (std::string m = check_dart(d); !m.empty()) return m;
      if (std::string m = check_dart(map.alpha(0, d)); !m.empty()) return m;
    }
    if (degree != particles.degree[p]) return "particle " + std::to_string(p) + " miscounts its darts";
  }
  return {};
}

std::string Model::check() const {
  if (std::string m = map.check(); !m.empty()) return "map: " + m;
  std::ostringstream err;
  std::vector<std::size_t> block_darts(blocks.size(), 0);
  std::vector<std::uint32_t> degree(particles.capacity(), 0);
  std::vector<double> lumped(particles.capacity(), 0.0);
  for (Dart d = 0; d < map.capacity(); ++d) {
    if (!map.alive(d)) continue;
    BlockId b = dart_block[d];
    if (!block_valid(b)) return "dart " + std::to_string(d) + " belongs to a dead block";
    ++block_darts[b];
    ParticleId p = dart_particle[d];
    if (!particles.valid(p)) return "dart " + std::to_string(d) + " embeds a dead particle";
    ++degree[p];
    for (int i = 0; i < 3; ++i)
      if (dart_block[map.alpha(i, d)] != b) return "dart " + std::to_string(d) + ": alpha" + std::to_string(i) + " leaves its block";
    if (std::string m = check_dart(d); !m.empty()) return m;
  }
  for (std::size_t e = 0; e < bars.size(); ++e) {
    const Bar& bar = bars[e];
    if (!map.alive(bar.dart) || dart_bar[bar.dart] != e) return "bar " + std::to_string(e) + " is orphaned";
    double half = 0.5 * bar.line_mass * bar.rest_length;
    lumped[bar.i] += half;
    lumped[bar.j] += half;
  }
  for (std::size_t h = 0; h < hinges.size(); ++h)
    if (!map.alive(hinges[h].dart) || dart_hinge[hinges[h].dart] != h) return "hinge " + std::to_string(h) + " is orphaned";
  for (BlockId b = 0; b < blocks.size(); ++b) {
    const Block& blk = blocks[b];
    if (!blk.alive) continue;
    if (blk.darts != block_darts[b]) return "block " + std::to_string(b) + " miscounts its darts";
    if (!map.alive(blk.dart) || dart_block[blk.dart] != b) return "block " + std::to_string(b) + " has no valid start dart";
    if (map.orbit_size(kComponentOrbit, blk.dart) != blk.darts) return "block " + std::to_string(b) + " is not one connected component";
    if (blk.kind != BlockKind::Patch) {
      if (blk.closed == map.is_free(1, blk.dart)) return "beam " + std::to_string(b) + ": start dart does not match open/closed";
    }
  }
  for (ParticleId p = 0; p < particles.capacity(); ++p) {
    if (!particles.alive[p]) continue;
    if (degree[p] != particles.degree[p]) return "particle " + std::to_string(p) + " miscounts its darts";
    if (!near(lumped[p], particles.lumped_mass[p])) return "particle " + std::to_string(p) + " has a stale lumped mass";
    if (particles.active[p] != (particles.degree[p] > 0 && !particles.passive[p]))
      return "particle " + std::to_string(p) + " has a stale active flag";
    if (!particles.position[p].allFinite() || !particles.velocity[p].allFinite())
      return "particle " + std::to_string(p) + " is not finite";
  }
  return {};
}

}  // namespace tendril
