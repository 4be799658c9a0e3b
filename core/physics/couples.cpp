// External moments on particles without rotations (thesis 3.2.8.3's 3-DOF
// spline beam has none): the moment M acts as force couples across the
// particle's beam segments. Across the segment from p to its neighbour q,
// d = x_p - x_q, p takes f = (s M) x d / |d|^2 and q takes -f: their moment
// d x f is the part of s M normal to d (a 3-DOF beam carries no twist, so
// the component along the segment has nothing to act on). The shares s go
// by what each segment can carry, |M x d^|^2: equal at an interior particle
// of a straight beam (the usual statically equivalent couple of a point
// moment), the whole moment across a beam end's segment, and none across a
// segment along M (a strip's column at its loaded end), which would drop
// its part. The couples follow the segments as they turn (a follower moment
// in the plane of bending).
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
    for (Dart head = P.first_dart[p], d = head; d != kNone;) {
      const Dart e = model_.map.alpha(0, d);
      if (e != d && model_.blocks[model_.dart_block[d]].kind == BlockKind::Beam)
        couples_.push_back({p, model_.dart_particle[e]});
      d = model_.ring_next[d];
      if (d == head) break;
    }
  }
  return couples_;
}

namespace {

// Calls f(p, q, force on p) for every couple, the couples of one particle
// (consecutive in the list) sharing its moment by |M x d^|^2.
template <class Couples, class F>
void for_each_couple_force(const Couples& cs, const Vec3* x, const Vec3* moment,
                           const std::uint8_t* active, F&& f) {
  for (std::size_t first = 0, last; first < cs.size(); first = last) {
    const ParticleId p = cs[first].p;
    for (last = first; last < cs.size() && cs[last].p == p; ++last) {}
    const Vec3& M = moment[p];
    double total = 0;
    for (std::size_t k = first; k < last; ++k) {
      const Vec3 d = x[p] - x[cs[k].q];
      const double dd = d.squaredNorm();
      if (dd > 0 && (active[p] & active[cs[k].q])) total += M.cross(d).squaredNorm() / dd;
    }
    if (!(total > 0)) continue;
    for (std::size_t k = first; k < last; ++k) {
      const ParticleId q = cs[k].q;
      if (!(active[p] & active[q])) continue;  // dormant, like an element touching a passive particle
      const Vec3 d = x[p] - x[q];
      const double dd = d.squaredNorm();
      if (!(dd > 0)) continue;
      const double share = M.cross(d).squaredNorm() / dd / total;
      f(p, q, Vec3((share * M).cross(d) / dd));
    }
  }
}

}  // namespace

void Solver::accumulate_couples(const Vec3* x, Vec3* F) const {
  const Particles& P = model_.particles;
  for_each_couple_force(couples(), x, P.moment.data(), P.active.data(), [&](ParticleId p, ParticleId q, const Vec3& f) {
    F[p] += f;
    F[q] -= f;
  });
}

void Solver::add_couples_to_x0(double dt) {
  const Particles& P = model_.particles;
  const std::uint8_t* lock = P.lock.data();
  for_each_couple_force(couples(), P.position.data(), P.moment.data(), P.active.data(),
                        [&](ParticleId p, ParticleId q, const Vec3& f) {
                          x0_[p] += ((dt * dt / mass_[p]) * f).cwiseProduct(free_axes(lock[p]));
                          x0_[q] -= ((dt * dt / mass_[q]) * f).cwiseProduct(free_axes(lock[q]));
                        });
}

}  // namespace tendril
