// Residual forces and greatest direct stiffnesses (eq. 3.4) of every element
// at given positions: bars (eq. 3.32-3.35), spline-beam hinges
// (eq. 3.41-3.43) and 6-DOF beams (eq. 3.44-3.50). The integrators evaluate
// them at the step's positions and at their intermediate stages.
#include <algorithm>
#include <cmath>

#include "physics/element_forces.hpp"
#include "physics/numerical_errors.hpp"
#include "physics/solver.hpp"

namespace tendril {

void Solver::accumulate_forces(const Vec3* x, const Quat* q, Vec3* F, double* S, Vec3* T, double* K) const {
  const Particles& P = model_.particles;
  const Vec3 g = model_.gravity;
  const Vec3* load = P.load.data();
  const double *point_mass = P.point_mass.data(), *lumped_mass = P.lumped_mass.data();
  for (ParticleId p : P.integrated.raw()) {
    F[p] = load[p] + (point_mass[p] + lumped_mass[p]) * g;
    S[p] = 0;
  }
  for (ParticleId p : P.rotational.raw()) {
    T[p] = P.moment[p];
    K[p] = 0;
  }
  const double gf = settings.geometric_factor;
  // Only awake elements: those touching a passive particle (multi-
  // resolution, thesis 5.5.2.3) sit behind ElementBuffer::awake, unvisited.
  for (const Bar* bp = model_.bars.awake_begin(); bp != model_.bars.awake_end(); ++bp) {
    const Bar& b = *bp;
    const Vec3 d = x[b.j] - x[b.i];
    const double L = d.norm();
    const double k = b.EA / b.rest_length;
    double T = b.prestress + k * (L - b.rest_length);  // eq. 3.32
    if (b.tension_only && T < 0) T = 0;
    if (L > 0) {
      const Vec3 f = (T / L) * d;  // eq. 3.33
      F[b.i] += f;
      F[b.j] -= f;
    }
    const double s = k + (L > 0 && T > 0 ? gf * T / L : 0.0);  // eq. 3.35
    S[b.i] += s;
    S[b.j] += s;
  }
  for (const Hinge* hp = model_.hinges.awake_begin(); hp != model_.hinges.awake_end(); ++hp) {
    const Hinge& h = *hp;
    const HingeForces f = hinge_forces(h, x);
    if (!std::isfinite(f.ka + f.kb)) [[unlikely]]
      throw_degenerate_hinge(model_, h, x);  // a zero-length link (coincident particles): stop, naming them
    S[h.j] += f.ka + f.kb;
    F[h.i] += f.fi;
    F[h.k] += f.fk;
    F[h.j] -= f.fi + f.fk;
  }
  for (const Beam6* bp = model_.beam6s.awake_begin(); bp != model_.beam6s.awake_end(); ++bp) {
    const Beam6& b = *bp;
    const Beam6Ends e = beam6_ends(b, x, q, gf);
    S[b.i] += e.k;
    S[b.j] += e.k;
    K[b.i] += e.kr;
    K[b.j] += e.kr;
    F[b.i] -= e.fj;
    F[b.j] += e.fj;
    T[b.i] += e.ta;
    T[b.j] += e.tb;
  }
  if (!model_.joints.items.empty()) accumulate_joint_forces(x, F, S);
  if (!model_.goals.empty()) accumulate_goal_forces(x, F, S);
  if (!model_.csts.items.empty()) accumulate_cst_forces(x, F, S);
}

}  // namespace tendril
