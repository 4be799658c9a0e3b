// Clamps of 3-DOF beam ends (model.hpp): a fixed tangent at the end of a
// spline beam, as a boundary condition of the beam rather than a lock on
// the next particle (whose straight first segment is a first-order error).
#include <algorithm>
#include <cmath>

#include "model/model.hpp"

namespace tendril {

namespace {
std::string pid(ParticleId p) { return std::to_string(p); }
}  // namespace

bool Model::clamp_acts(Dart d) const {
  if (!map.alive(d) || clamp[d].isZero(0) || map.is_free(0, d) || !map.is_free(1, d)) return false;
  const Block& b = blocks[dart_block[d]];
  return b.alive && b.kind == BlockKind::Beam && b.dofs == 3;
}

namespace {

// The end dart of beam b at particle p, or kNoDart.
Dart end_dart(const Model& m, ParticleId p, BlockId b, const char* fn) {
  m.require_particle(p, fn);
  m.require_block(b, fn);
  if (m.blocks[b].kind != BlockKind::Beam)
    throw ModelError(std::string(fn) + ": block " + std::to_string(b) + " is a " + block_kind_name(m.blocks[b].kind) +
                     "; only beam ends are clamped");
  Dart found = kNoDart;
  bool on_beam = false;
  for (Dart head = m.particles.first_dart[p], d = head; d != kNone;) {
    if (m.dart_block[d] == b) {
      on_beam = true;
      if (m.map.is_free(1, d)) found = d;
    }
    d = m.ring_next[d];
    if (d == head) break;
  }
  if (!on_beam) throw ModelError(std::string(fn) + ": particle " + pid(p) + " is not on beam " + std::to_string(b));
  if (found == kNoDart)
    throw ModelError(std::string(fn) + ": particle " + pid(p) + " is not an end of beam " + std::to_string(b) +
                     "; only beam ends are clamped");
  return found;
}

}  // namespace

void Model::set_clamp(ParticleId p, BlockId b, const Vec3& direction) {
  const Dart d = end_dart(*this, p, b, "clamp");
  if (blocks[b].dofs != 3)
    throw ModelError("clamp: beam " + std::to_string(b) +
                     " has 6 DOF; clamp its end by locking the end particle's rotations (lock \"rxyz\")");
  if (!direction.allFinite()) throw ModelError("clamp: the direction is not finite");
  Vec3 t = direction;
  if (t.isZero(0)) t = particles.position[dart_particle[map.alpha(0, d)]] - particles.position[p];
  if (!(t.norm() > 0))
    throw ModelError("clamp: particle " + pid(p) + " and its neighbour coincide; give the direction");
  ++revision;
  clamp[d] = t.normalized();
  if (std::find(clamp_darts.raw().begin(), clamp_darts.raw().end(), d) == clamp_darts.raw().end())
    clamp_darts.push_back(d);
}

void Model::remove_clamp(ParticleId p, BlockId b) {
  const Dart d = end_dart(*this, p, b, "unclamp");
  ++revision;
  clamp[d] = Vec3::Zero();
}

bool Model::clamped(ParticleId p, BlockId b, Vec3* direction) const {
  const Dart d = end_dart(*this, p, b, "clamped");
  if (direction) *direction = clamp[d];
  return !clamp[d].isZero(0);
}

}  // namespace tendril
