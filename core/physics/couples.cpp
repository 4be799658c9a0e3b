// External moments on particles without rotations (thesis 3.2.8.3's 3-DOF
// spline beam has none): the moment M acts as force couples across the
// particle's beam segments, shared equally among them. Across the segment
// from p to its neighbour q, d = x_p - x_q, p takes f = (s M) x d / |d|^2
// and q takes -f: their moment d x f is the part of s M normal to d (a
// 3-DOF beam carries no twist, so the component along the segment has
// nothing to act on). At an interior particle the two halves make the
// usual statically equivalent couple of a point moment; at a beam end the
// whole moment goes across the end segment. The couples follow the
// segments as they turn (a follower moment in the plane of bending).
#include "physics/free_axes.hpp"
#include "physics/solver.hpp"

namespace tendril {

const std::vector<Solver::Couple>& Solver::couples() const {
  const std::pair<std::uint64_t, std::uint64_t> at{model_.revision, model_.moment_revision};
  if (couples_at_ == at) return couples_;
  couples_at_ = at;
  couples_.clear();
  const Particles& P = model_.particles;
  for (ParticleId p = 0; p < P.capacity(); ++p) {
    if (!P.valid(p) || P.rot_degree[p] > 0 || P.moment[p].isZero(0)) continue;
    const std::size_t first = couples_.size();
    for (Dart head = P.first_dart[p], d = head; d != kNone;) {
      const Dart e = model_.map.alpha(0, d);
      if (e != d && model_.blocks[model_.dart_block[d]].kind == BlockKind::Beam)
        couples_.push_back({p, model_.dart_particle[e], 0.0});
      d = model_.ring_next[d];
      if (d == head) break;
    }
    const double share = 1.0 / double(couples_.size() - first);
    for (std::size_t k = first; k < couples_.size(); ++k) couples_[k].share = share;
  }
  return couples_;
}

namespace {

Vec3 couple_force(double share, const Vec3& xp, const Vec3& xq, const Vec3& moment) {
  const Vec3 d = xp - xq;
  const double dd = d.squaredNorm();
  if (!(dd > 0)) return Vec3::Zero();
  return (share * moment).cross(d) / dd;
}

}  // namespace

void Solver::accumulate_couples(const Vec3* x, Vec3* F) const {
  const Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  for (const Couple& c : couples()) {
    if (!(active[c.p] & active[c.q])) continue;  // dormant, like an element touching a passive particle
    const Vec3 f = couple_force(c.share, x[c.p], x[c.q], P.moment[c.p]);
    F[c.p] += f;
    F[c.q] -= f;
  }
}

void Solver::add_couples_to_x0(double dt) {
  const Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  const std::uint8_t* lock = P.lock.data();
  const Vec3* x = P.position.data();
  for (const Couple& c : couples()) {
    if (!(active[c.p] & active[c.q])) continue;
    const Vec3 f = couple_force(c.share, x[c.p], x[c.q], P.moment[c.p]);
    x0_[c.p] += ((dt * dt / mass_[c.p]) * f).cwiseProduct(free_axes(lock[c.p]));
    x0_[c.q] -= ((dt * dt / mass_[c.q]) * f).cwiseProduct(free_axes(lock[c.q]));
  }
}

}  // namespace tendril
