// A uniform pressure p on the quads of a patch (Model::set_pressure): a
// follower load, re-evaluated at every evaluation. A quad a b c d has the
// area vector A = 1/2 (c - a) x (d - b) (exact for a warped quad: the
// vector area of any surface spanning its four edges), and each corner
// takes p A / 4. The load turns with the face; its derivative by a corner
// is bounded by p times half a diagonal over four, which goes into S so
// that the fictitious masses (eq. 3.4) stay stable under a large pressure.
// An area load q along d (Model::set_area_load, snow) is the same walk with
// a dead direction: each corner takes q |A . d| d / 4, its derivative
// bounded alike.
#include <cmath>

#include "physics/solver.hpp"

namespace tendril {

bool Solver::pressure_acts() const {
  if (pressure_revision_ != model_.revision) {
    pressure_quads_.clear();
    for (BlockId b = 0; b < model_.blocks.size(); ++b) {
      const Block& blk = model_.blocks[b];
      if (!blk.alive || blk.kind != BlockKind::Patch) continue;
      if (blk.pressure != 0)
        for (const Model::Quad& q : model_.pressure_quads(b)) pressure_quads_.push_back({q, blk.pressure});
      if (blk.area_load != 0)
        for (const Model::Quad& q : model_.area_load_quads(b))
          pressure_quads_.push_back({q, blk.area_load, blk.area_load_direction});
    }
    pressure_revision_ = model_.revision;
  }
  return !pressure_quads_.empty();
}

void Solver::accumulate_pressure_forces(const Vec3* x, Vec3* F, double* S) const {
  if (!pressure_acts()) return;
  const std::uint8_t* active = model_.particles.active.data();
  for (const PressureQuad& f : pressure_quads_) {
    const auto& [a, b, c, d] = f.q;
    if (!(active[a] & active[b] & active[c] & active[d])) continue;  // dormant, as its elements are
    const Vec3 ac = x[c] - x[a], bd = x[d] - x[b];
    const Vec3 area2 = ac.cross(bd);  // twice the area vector
    const Vec3 share = f.along.isZero(0) ? Vec3((0.125 * f.p) * area2) : Vec3((0.125 * f.p * std::abs(area2.dot(f.along))) * f.along);
    for (ParticleId p : f.q) F[p] += share;
    if (!S) continue;
    const double k = 0.125 * std::abs(f.p) * (ac.norm() + bd.norm());
    for (ParticleId p : f.q) S[p] += k;
  }
}

}  // namespace tendril
