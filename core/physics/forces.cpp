// Residual forces and greatest direct stiffnesses (eq. 3.4) of every element
// at given positions: bars (eq. 3.32-3.35) and spline-beam hinges
// (eq. 3.41-3.43). The integrators evaluate them at the step's positions and
// at their intermediate stages.
#include "physics/solver.hpp"

namespace tendril {

void Solver::accumulate_forces(const Vec3* x, Vec3* F, double* S) const {
  const Particles& P = model_.particles;
  const std::size_t n = P.capacity();
  const Vec3 g = model_.gravity;
  for (std::size_t p = 0; p < n; ++p) {
    F[p] = P.load[p] + (P.point_mass[p] + P.lumped_mass[p]) * g;
    S[p] = 0;
  }
  const double gf = settings.geometric_factor;
  for (const Bar& b : model_.bars.items) {
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
  for (const Hinge& h : model_.hinges.items) {
    const Vec3 a = x[h.j] - x[h.i], b = x[h.k] - x[h.j];
    const double La = a.norm(), Lb = b.norm(), Lc = (x[h.k] - x[h.i]).norm();
    const double ka = 4 * h.EI / (La * La * La), kb = 4 * h.EI / (Lb * Lb * Lb);  // eq. 3.43
    S[h.j] += ka + kb;
    const Vec3 nrm = a.cross(b);
    const double nn = nrm.norm();
    if (nn <= 0 || Lc <= 0) continue;  // straight (or degenerate): no bending force
    const double sin_alpha = nn / (La * Lb);
    // Moment EI*(kappa - kappa0) with kappa = 2 sin(alpha) / Lc (eq. 3.41).
    const double M = h.EI * (2 * sin_alpha / Lc - h.rest_curvature);
    // Shears M/La and M/Lb act normal to the links in the plane ijk
    // (eq. 3.42), pushing the ends away from the centre of curvature.
    const Vec3 fi = (M / La) * a.cross(nrm).normalized();
    const Vec3 fk = (M / Lb) * b.cross(nrm).normalized();
    F[h.i] += fi;
    F[h.k] += fk;
    F[h.j] -= fi + fk;
  }
}

}  // namespace tendril
