#include "physics/solver.hpp"

#include <cmath>

namespace tendril {

const char* damping_name(Damping d) {
  switch (d) {
    case Damping::None: return "none";
    case Damping::Viscous: return "viscous";
    case Damping::Kinetic: return "kinetic";
  }
  return "?";
}

namespace {
inline Vec3 free_mask(std::uint8_t lock) {
  return Vec3((lock & kLockX) ? 0.0 : 1.0, (lock & kLockY) ? 0.0 : 1.0, (lock & kLockZ) ? 0.0 : 1.0);
}
}  // namespace

void Solver::compute_forces() {
  Particles& P = model_.particles;
  const std::size_t n = P.capacity();
  Vec3* x = P.position.data();
  Vec3* F = P.force.data();
  double* S = P.stiffness.data();
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

void Solver::check_finite() const {
  const Particles& P = model_.particles;
  for (ParticleId p = 0; p < P.capacity(); ++p) {
    if (!P.active[p]) continue;
    if (!P.force[p].allFinite() || !std::isfinite(P.stiffness[p]))
      throw NumericalError("solver: the force on particle " + std::to_string(p) +
                           " is not finite at step " + std::to_string(steps_) +
                           "; no particle was moved");
  }
}

void Solver::step() {
  compute_forces();
  integrate_leapfrog();
  ++steps_;
  time_ += settings.dt;
}

void Solver::integrate_leapfrog() {
  Particles& P = model_.particles;
  const std::size_t n = P.capacity();
  const double dt = settings.dt;
  const double mass_scale = settings.mass_factor * 0.5 * dt * dt;  // eq. 3.4
  double A = 1, B = 1;
  if (settings.damping == Damping::Viscous) {  // eq. 3.26
    A = (1 - settings.viscous / 2) / (1 + settings.viscous / 2);
    B = (1 + A) / 2;
  }
  const double first = restart_ ? 0.5 : 1.0;  // Leapfrog is not self-starting
  double residual2 = 0, momentum2 = 0, ke = 0;
  bool finite = true;
  Vec3* v = P.velocity.data();
  const Vec3* F = P.force.data();
  for (std::size_t p = 0; p < n; ++p) {
    if (!P.active[p]) continue;
    const Vec3 Ff = F[p].cwiseProduct(free_mask(P.lock[p]));
    const double M = mass_scale * P.stiffness[p];
    finite &= Ff.allFinite() && M > 0;
    residual2 = std::max(residual2, Ff.squaredNorm());
    v[p] = (restart_ ? 0.0 : A) * v[p] + (first * B * dt / M) * Ff;  // eq. 3.11 / 3.26
    ke += M * v[p].squaredNorm();                                    // eq. 3.28
    momentum2 = std::max(momentum2, M * M * v[p].squaredNorm());
  }
  if (!finite) {
    // Undo nothing: positions are untouched. Name the first culprit.
    for (std::size_t p = 0; p < n; ++p) v[p].setZero();
    check_finite();
    throw NumericalError("solver: a particle has no stiffness (an element with zero EA?) at step " +
                         std::to_string(steps_));
  }
  residual_ = std::sqrt(residual2);
  // The force that would stop the fastest particle within one step: a
  // particle crossing its equilibrium at speed has no residual but is not
  // at rest, so convergence asks for both to be small.
  motion_ = std::sqrt(momentum2) / dt;
  restart_ = false;
  Vec3* x = P.position.data();
  if (settings.damping == Damping::Kinetic && ke_samples_ >= 1 && ke < ke_prev_) {
    // Peak passed: move back to the interpolated peak (eq. 3.29-3.31), stop.
    double q = 0;
    if (ke_samples_ >= 2) {
      const double G = ke_prev2_ - ke_prev_, H = ke_prev_ - ke;
      if (H - G != 0) q = H / (H - G);
    }
    for (std::size_t p = 0; p < n; ++p) {
      if (!P.active[p]) continue;
      const double M = mass_scale * P.stiffness[p];
      const Vec3 Ff = F[p].cwiseProduct(free_mask(P.lock[p]));
      x[p] += dt * v[p] - dt * (1 + q) * v[p] + 0.5 * dt * dt * q * Ff / M;
      v[p].setZero();
    }
    ++resets_;
    ke_samples_ = 0;
    ke_prev_ = ke_prev2_ = 0;
    restart_ = true;
    kinetic_energy_ = 0;
    motion_ = 0;
    return;
  }
  for (std::size_t p = 0; p < n; ++p)
    if (P.active[p]) x[p] += dt * v[p];  // eq. 3.12
  ke_prev2_ = ke_prev_;
  ke_prev_ = ke;
  ++ke_samples_;
  kinetic_energy_ = ke;
}

RunResult Solver::run(double tolerance, std::uint64_t max_steps,
                      const std::function<void(const RunResult&)>& progress, std::uint64_t progress_every) {
  RunResult r;
  while (r.steps < max_steps) {
    step();
    ++r.steps;
    r.residual = residual_;
    if (residual_ < tolerance && motion_ < tolerance) {
      r.converged = true;
      break;
    }
    if (progress && r.steps % progress_every == 0) progress(r);
  }
  return r;
}

Vec3 Solver::reaction(ParticleId p) const {
  model_.require_particle(p, "reaction");
  const Vec3 locked = Vec3::Ones() - free_mask(model_.particles.lock[p]);
  return -model_.particles.force[p].cwiseProduct(locked);
}

void Solver::reset_motion() {
  Particles& P = model_.particles;
  for (auto& v : P.velocity.raw()) v.setZero();
  ke_samples_ = 0;
  ke_prev_ = ke_prev2_ = kinetic_energy_ = 0;
  restart_ = true;
}

}  // namespace tendril
