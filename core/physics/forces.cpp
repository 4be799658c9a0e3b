// Residual forces and greatest direct stiffnesses (eq. 3.4) of every element
// at given positions: bars (eq. 3.32-3.35), spline-beam hinges
// (eq. 3.41-3.43) and 6-DOF beams (eq. 3.44-3.50). The integrators evaluate
// them at the step's positions and at their intermediate stages.
#include <algorithm>

#include "model/frames.hpp"
#include "physics/solver.hpp"

namespace tendril {

namespace {

// Eq. 3.47 and 3.49 bound each direction of a beam end by its own diagonal
// stiffness (12 EI / L^3 for translation, 4 EI / L for rotation). Coupled,
// the bending modes of a beam with those lumped masses reach
// omega^2 = 2.69 * 2 / dt^2 (a chain's free end; 3.5 for one free element),
// beyond Leapfrog's 4 / dt^2. 7/4 on both bending terms bounds every
// element's bending modes, hence every model's, by 4 / dt^2.
constexpr double kBendingMassFactor = 1.75;

// Li's co-rotational Euler-Bernoulli element (eq. 3.44-3.46): included
// angles of the beam ends in the element frame, end moments from them, the
// shear forces that balance those moments, and the axial force.
inline void beam6_forces(const Beam6& b, const Vec3* x, const Quat* q, Vec3* F, Vec3* T, double* S, double* K,
                         double gf) {
  const double L = b.rest_length;
  const Vec3 d = x[b.j] - x[b.i];
  const double l = d.norm();
  const double N = b.prestress + b.EA * (l - L) / L;  // eq. 3.32 with K = EA / L
  const double EI = std::max(b.EIy, b.EIz);
  const double k = std::max(b.EA / L, kBendingMassFactor * 12 * EI / (L * L * L)) +
                   (l > 0 && N > 0 ? gf * N / l : 0.0);                          // eq. 3.47
  const double kr = std::max(b.GJ / L, kBendingMassFactor * 4 * EI / L);  // eq. 3.49
  S[b.i] += k;
  S[b.j] += k;
  K[b.i] += kr;
  K[b.j] += kr;
  if (!(l > 0)) return;
  const ParticleId i = b.i, j = b.j;
  const Mat3 Ea = (q[i] * b.end_i).toRotationMatrix(), Eb = (q[j] * b.end_j).toRotationMatrix();
  const Vec3 ux = d / l;  // eq. 3.45
  const Mat3 U = element_frame(ux, Ea, Eb);
  const Vec3 uy = U.col(1), uz = U.col(2);
  // Eq. 3.44: the beam-end tangents measured against the chord, and the
  // relative twist of the two ends about it.
  const double za = Ea.col(0).dot(uy), zb = Eb.col(0).dot(uy);
  const double ya = -Ea.col(0).dot(uz), yb = -Eb.col(0).dot(uz);
  const double twist = 0.5 * (Eb.col(1).dot(Ea.col(2)) - Ea.col(1).dot(Eb.col(2)));
  // Eq. 3.46: end moments; a positive angle is turned back by its moment.
  const double cz = 2 * b.EIz / L, cy = 2 * b.EIy / L;
  const double Mza = cz * (2 * za + zb), Mzb = cz * (za + 2 * zb);
  const double Mya = cy * (2 * ya + yb), Myb = cy * (ya + 2 * yb);
  const double Mx = b.GJ / L * twist;
  const Vec3 ta = Mx * ux - Mya * uy - Mza * uz;
  const Vec3 tb = -Mx * ux - Myb * uy - Mzb * uz;
  T[i] += ta;
  T[j] += tb;
  // Shears: the couple that balances the end moments (eq. 3.46's
  // f_y = 6 EI (theta_a + theta_b) / L^2), plus the axial force.
  const Vec3 fj = ux.cross(ta + tb) / l - N * ux;
  F[i] -= fj;
  F[j] += fj;
}

}  // namespace

void Solver::accumulate_forces(const Vec3* x, const Quat* q, Vec3* F, double* S, Vec3* T, double* K) const {
  const Particles& P = model_.particles;
  const std::size_t n = P.capacity();
  const Vec3 g = model_.gravity;
  for (std::size_t p = 0; p < n; ++p) {
    F[p] = P.load[p] + (P.point_mass[p] + P.lumped_mass[p]) * g;
    S[p] = 0;
  }
  for (ParticleId p : P.rotational.raw()) {
    T[p] = P.moment[p];
    K[p] = 0;
  }
  const double gf = settings.geometric_factor;
  // Elements whose particles are all passive (multi-resolution, thesis
  // 5.5.2.3) are skipped: they move nothing that is integrated.
  const std::uint8_t* active = P.active.data();
  for (const Bar& b : model_.bars.items) {
    if (!(active[b.i] | active[b.j])) continue;
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
    if (!(active[h.i] | active[h.j] | active[h.k])) continue;
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
  for (const Beam6& b : model_.beam6s.items)
    if (active[b.i] | active[b.j]) beam6_forces(b, x, q, F, T, S, K, gf);
  if (!model_.joints.items.empty()) accumulate_joint_forces(x, F, S);
  if (!model_.csts.items.empty()) accumulate_cst_forces(x, F, S);
}

}  // namespace tendril
