// The invariants every production must leave intact (DESIGN principle 2):
// map validity, embeddings, block bookkeeping, and element buffers that equal
// what a rebuild from the map would produce.
#include <cmath>
#include <sstream>

#include "model/frames.hpp"
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
  // Elements: one bar per edge (a Beam6 on 6-DOF beams), one hinge per
  // interior vertex of a 3-DOF beam.
  const Block& blk = blocks[b];
  const bool six = blk.kind == BlockKind::Beam && blk.dofs == 6;
  if (six) {
    if (dart_bar[d] != kNone) return "dart " + std::to_string(d) + " of a 6-DOF beam has a bar";
    if (std::string m = check_beam6(d); !m.empty()) return m;
  } else if (!edge_has_bar(d)) {
    if (dart_bar[d] != kNone || dart_beam6[d] != kNone)
      return "dart " + std::to_string(d) + ": an interior edge of a CST patch has an edge element";
  } else {
    if (dart_beam6[d] != kNone) return "dart " + std::to_string(d) + " of a 3-DOF block has a 6-DOF beam element";
    ElementIndex e = dart_bar[d];
    if (e == kNone || e >= bars.size()) return "dart " + std::to_string(d) + " has no bar";
    const Bar& bar = bars[e];
    if (dart_bar[bar.dart] != e || (bar.dart != d && bar.dart != other && map.alpha(2, bar.dart) != d &&
                                    map.alpha(2, bar.dart) != other))
      return "bar " + std::to_string(e) + " does not point back to its edge";
    ParticleId bi = dart_particle[bar.dart], bj = dart_particle[map.alpha(0, bar.dart)];
    if (bar.i != bi || bar.j != bj) return "bar " + std::to_string(e) + " has stale particles";
    if ((e < bars.awake) != (!particles.passive[bi] && !particles.passive[bj]))
      return "bar " + std::to_string(e) + " is on the wrong side of the awake/dormant partition";
    if (!near(bar.rest_length, rest_length[d]) || bar.EA != blk.section.EA || bar.prestress != bar_prestress(d) ||
        bar.line_mass != blk.section.line_mass || bar.tension_only != (blk.kind == BlockKind::Cable))
      return "bar " + std::to_string(e) + " parameters differ from its block and edge";
  }
  if (blk.kind == BlockKind::Patch && blk.membrane.cst()) {
    if (std::string m = check_cst_face(d); !m.empty()) return m;
  } else if (cst_first[d] || dart_cst[d] != kNone) {
    return "dart " + std::to_string(d) + " carries a CST triangle outside a CST patch";
  }
  const bool interior = blk.kind == BlockKind::Beam && !six && !map.is_free(1, d);
  ElementIndex h = dart_hinge[d];
  if (interior != (h != kNone)) return "dart " + std::to_string(d) + (interior ? " lacks its hinge" : " has a stray hinge");
  if (interior) {
    if (h >= hinges.size()) return "dart " + std::to_string(d) + ": hinge index out of range";
    const Hinge& hg = hinges[h];
    if (hg.dart != d && hg.dart != map.alpha(1, d)) return "hinge " + std::to_string(h) + " does not point back";
    Dart hd = hg.dart;
    if (hg.i != dart_particle[map.alpha(0, hd)] || hg.j != dart_particle[hd] ||
        hg.k != dart_particle[map.alpha(0, map.alpha(1, hd))] || hg.EI != blk.section.EI ||
        hg.rest_curvature != rest_curvature[hd] || rest_curvature[hd] != rest_curvature[map.alpha(1, hd)])
      return "hinge " + std::to_string(h) + " is stale";
    if ((h < hinges.awake) != (!particles.passive[hg.i] && !particles.passive[hg.j] && !particles.passive[hg.k]))
      return "hinge " + std::to_string(h) + " is on the wrong side of the awake/dormant partition";
  }
  return {};
}

std::string Model::check_beam6(Dart d) const {
  const ElementIndex e = dart_beam6[d];
  if (e == kNone || e >= beam6s.size()) return "dart " + std::to_string(d) + " of a 6-DOF beam has no Beam6";
  const Beam6& el = beam6s[e];
  const Dart other = map.alpha(0, d);
  const std::string name = "6-DOF beam element " + std::to_string(e);
  if (dart_beam6[el.dart] != e || (el.dart != d && el.dart != other)) return name + " does not point back to its edge";
  const Dart far = map.alpha(0, el.dart);
  if (el.i != dart_particle[el.dart] || el.j != dart_particle[far]) return name + " has stale particles";
  if ((e < beam6s.awake) != (!particles.passive[el.i] && !particles.passive[el.j]))
    return name + " is on the wrong side of the awake/dormant partition";
  if (!(el.end_i.coeffs() == beam_end[el.dart].coeffs()) ||
      !(el.end_j.coeffs() == Quat(beam_end[far] * end_flip()).coeffs()))
    return name + " has stale beam ends";
  if (!el.end_i.coeffs().allFinite() || !el.end_j.coeffs().allFinite() || std::abs(el.end_i.norm() - 1) > 1e-9 ||
      std::abs(el.end_j.norm() - 1) > 1e-9)
    return name + ": a beam end is not a rotation";
  const Section& s = blocks[dart_block[d]].section;
  if (!near(el.rest_length, rest_length[d]) || el.EA != s.EA || el.EIy != s.bending_y() || el.EIz != s.bending_z() ||
      el.GJ != s.torsion() || el.prestress != s.prestress || el.line_mass != s.line_mass)
    return name + " parameters differ from its block and edge";
  return {};
}

std::string Model::check_rotation(ParticleId p) const {
  const Particles& P = particles;
  if (!P.orientation[p].coeffs().allFinite() || std::abs(P.orientation[p].norm() - 1) > 1e-9)
    return "particle " + std::to_string(p) + ": its frame is not a rotation";
  if (!P.angular_velocity[p].allFinite()) return "particle " + std::to_string(p) + ": angular velocity is not finite";
  const std::uint32_t slot = P.rotational_slot[p];
  if ((P.rot_degree[p] > 0) != (slot != kNone) ||
      (slot != kNone && (slot >= P.rotational.size() || P.rotational[slot] != p)))
    return "particle " + std::to_string(p) + " is misfiled in the list of rotating particles";
  return {};
}

// Multi-resolution bookkeeping: p is in Particles::integrated exactly when
// it is active, at the slot it remembers.
std::string Model::check_integrated(ParticleId p) const {
  const std::uint32_t slot = particles.integrated_slot[p];
  if ((particles.active[p] != 0) != (slot != kNone) ||
      (slot != kNone && (slot >= particles.integrated.size() || particles.integrated[slot] != p)))
    return "particle " + std::to_string(p) + " is misfiled in the list of integrated particles";
  return {};
}

std::string Model::check_near(const std::vector<ParticleId>& ps) const {
  for (ParticleId p : ps) {
    if (!particles.valid(p)) continue;
    if (!particles.position[p].allFinite() || !particles.velocity[p].allFinite())
      return "particle " + std::to_string(p) + " is not finite";
    if (particles.active[p] != (particles.degree[p] > 0 && !particles.passive[p]))
      return "particle " + std::to_string(p) + " has a stale active flag";
    if (std::string m = check_integrated(p); !m.empty()) return m;
    if (std::string m = check_rotation(p); !m.empty()) return m;
    std::uint32_t degree = 0, rot_degree = 0;
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
      rot_degree += dart_beam6[d] != kNone;
    }
    if (degree != particles.degree[p]) return "particle " + std::to_string(p) + " miscounts its darts";
    if (rot_degree != particles.rot_degree[p]) return "particle " + std::to_string(p) + " miscounts its 6-DOF beam ends";
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
  if (bars.awake > bars.size() || hinges.awake > hinges.size() || beam6s.awake > beam6s.size() ||
      csts.awake > csts.size())
    return "an element buffer counts more awake elements than it holds";
  for (std::size_t e = 0; e < bars.size(); ++e) {
    const Bar& bar = bars[e];
    if (!map.alive(bar.dart) || dart_bar[bar.dart] != e) return "bar " + std::to_string(e) + " is orphaned";
    if (e >= bars.awake) continue;  // dormant: lumps no mass
    double half = 0.5 * bar.line_mass * bar.rest_length;
    lumped[bar.i] += half;
    lumped[bar.j] += half;
  }
  std::vector<std::uint32_t> rot_degree(particles.capacity(), 0);
  for (std::size_t e = 0; e < beam6s.size(); ++e) {
    const Beam6& el = beam6s[e];
    if (!map.alive(el.dart) || dart_beam6[el.dart] != e) return "6-DOF beam element " + std::to_string(e) + " is orphaned";
    if (e < beam6s.awake) {
      double half = 0.5 * el.line_mass * el.rest_length;
      lumped[el.i] += half;
      lumped[el.j] += half;
    }
    ++rot_degree[el.i];
    ++rot_degree[el.j];
  }
  for (std::size_t e = 0; e < csts.size(); ++e)
    if (!map.alive(csts[e].dart) || dart_cst[csts[e].dart] != e || !cst_first[csts[e].dart])
      return "CST element " + std::to_string(e) + " is orphaned";
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
    if (blk.membrane.cst() && blk.kind != BlockKind::Patch) return "block " + std::to_string(b) + " is CST but not a patch";
    if (blk.dofs != 3 && !(blk.dofs == 6 && blk.kind == BlockKind::Beam))
      return "block " + std::to_string(b) + " has " + std::to_string(int(blk.dofs)) + " DOF per particle";
  }
  std::size_t rotating = 0, integrated = 0;
  for (ParticleId p = 0; p < particles.capacity(); ++p) {
    if (!particles.alive[p]) continue;
    if (degree[p] != particles.degree[p]) return "particle " + std::to_string(p) + " miscounts its darts";
    if (!near(lumped[p], particles.lumped_mass[p])) return "particle " + std::to_string(p) + " has a stale lumped mass";
    if (particles.active[p] != (particles.degree[p] > 0 && !particles.passive[p]))
      return "particle " + std::to_string(p) + " has a stale active flag";
    if (!particles.position[p].allFinite() || !particles.velocity[p].allFinite())
      return "particle " + std::to_string(p) + " is not finite";
    if (rot_degree[p] != particles.rot_degree[p]) return "particle " + std::to_string(p) + " miscounts its 6-DOF beam ends";
    if (std::string m = check_rotation(p); !m.empty()) return m;
    if (std::string m = check_integrated(p); !m.empty()) return m;
    rotating += rot_degree[p] > 0;
    integrated += particles.active[p];
  }
  if (rotating != particles.rotational.size()) return "the list of rotating particles holds a dead or stray particle";
  if (integrated != particles.integrated.size()) return "the list of integrated particles holds a dead or stray particle";
  return {};
}

}  // namespace tendril
