// Forces of rotational joints (thesis 6.5.2, fig. 6.32): each neighbour is
// pulled towards its target (element_forces.hpp: joint_targets) with the
// joint's fictitious stiffness, and the shared particle takes the opposite sum.
#include "physics/element_forces.hpp"
#include "physics/solver.hpp"

namespace tendril {

void Solver::accumulate_joint_forces(const Vec3* x, Vec3* F, double* S) const {
  const std::uint8_t* active = model_.particles.active.data();
  for (const RotationalJoint& jt : model_.joints.items) {
    ParticleId n[4];
    if (!model_.joint_neighbours(jt.particle, n)) continue;  // no longer a crossing: inert
    // A joint touching a passive particle is dormant, like an element.
    if (!(active[jt.particle] & active[n[0]] & active[n[1]] & active[n[2]] & active[n[3]])) continue;
    Vec3 target[4];
    if (!joint_targets(jt, n, x, target)) continue;  // parallel beams: no plane to turn in
    Vec3 sum = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      const Vec3 f = jt.stiffness * (target[k] - x[n[k]]);
      F[n[k]] += f;
      sum += f;
      S[n[k]] += jt.stiffness;
    }
    F[jt.particle] -= sum;
    S[jt.particle] += 4 * jt.stiffness;
  }
}

}  // namespace tendril
