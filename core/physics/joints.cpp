// Forces of rotational joints (thesis 6.5.2, fig. 6.32): the axis is the
// normal of the two beams at the shared particle; one beam's neighbours are
// projected by rotating them +delta/2 about it, the other's by -delta/2,
// where delta is the target included angle minus the current one; each
// neighbour is pulled towards its projection with the joint's fictitious
// stiffness, and the shared particle takes the opposite sum.
#include <cmath>

#include "physics/solver.hpp"

namespace tendril {

namespace {
// Rotates r about the unit axis k by angle a (Rodrigues).
Vec3 rotated(const Vec3& r, const Vec3& k, double a) {
  return r * std::cos(a) + k.cross(r) * std::sin(a) + k * k.dot(r) * (1 - std::cos(a));
}
}  // namespace

void Solver::accumulate_joint_forces(const Vec3* x, Vec3* F, double* S) const {
  for (const RotationalJoint& jt : model_.joints.items) {
    ParticleId n[4];
    if (!model_.joint_neighbours(jt.particle, n)) continue;  // no longer a crossing: inert
    const Vec3 ta = x[n[1]] - x[n[0]], tb = x[n[3]] - x[n[2]];
    Vec3 axis = ta.cross(tb);
    const double len = axis.norm();
    if (!(len > 0)) continue;  // parallel beams: no plane to turn in
    axis /= len;
    const double delta = jt.angle - std::atan2(len, ta.dot(tb));
    const Vec3 c = x[jt.particle];
    Vec3 sum = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      // Turning beam a by -delta/2 and beam b by +delta/2 opens their angle by delta.
      const double turn = (k < 2 ? -0.5 : 0.5) * delta;
      const Vec3 target = c + rotated(x[n[k]] - c, axis, turn);
      const Vec3 f = jt.stiffness * (target - x[n[k]]);
      F[n[k]] += f;
      sum += f;
      S[n[k]] += jt.stiffness;
    }
    F[jt.particle] -= sum;
    S[jt.particle] += 4 * jt.stiffness;
  }
}

}  // namespace tendril
