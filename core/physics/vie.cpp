// Variational Implicit Euler (thesis 3.3.5, fig. 3.16): from the momentum
// guess x0 = x + dt v + dt^2 / M f_ext (eq. 3.57-3.58), vie_iterations
// local-global iterations, each projecting every element (projections.hpp,
// eq. 3.59) and moving every particle to the weighted average of its
// projections and of x0 with the weight M / dt^2 of the momentum term
// (eq. 3.57, 3.63); then v = (x - x_t) / dt (eq. 3.64).
// Loads and gravity enter through x0 only. Locked axes keep their value.
// The first guess is the inertial x + dt v, not x0 (eq. 3.58 minimises the
// momentum term alone): a fixed number of iterations stops short of the
// step's solution by a fraction of the distance from the guess, and a guess
// shifted by the external forces would leave that fraction of them
// unbalanced in every stationary state (20 % of the weight of the hanging
// chain with 8 iterations). From x + dt v, a stationary state is an
// equilibrium whatever the number of iterations.
// Rotation: the same with the rotation vector from the step's frame in place
// of x, the external moment in x0 and I / dt^2 for the momentum weight.
// Viscous damping scales the momentum guess by eq. 3.26's A; kinetic damping
// treats the step like the other synchronous integrators (commit()).
// Each step evaluates the forces once at its start (the residual, and S for
// the fictitious masses of eq. 3.4 at dt) and counts every local step as one
// more evaluation.
#include <algorithm>
#include <cmath>

#include "model/frames.hpp"
#include "physics/free_axes.hpp"
#include "physics/projections.hpp"
#include "physics/solver.hpp"

namespace tendril {

namespace {

// The rotation vector of q (the inverse of eq. 3.16's rotation_of).
Vec3 rotation_vector(const Quat& q) {
  Quat r = q;
  if (r.w() < 0) r.coeffs() = -r.coeffs();
  const Vec3 v(r.x(), r.y(), r.z());
  const double s = v.norm();
  if (s < 1e-12) return 2 * v;
  return (2 * std::atan2(s, r.w()) / s) * v;
}

}  // namespace

void Solver::start_implicit_step(double dt) {
  synchronize_velocities();
  const Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  const std::uint8_t* lock = P.lock.data();
  double A = 1;
  if (settings.damping == Damping::Viscous) A = (1 - settings.viscous / 2) / (1 + settings.viscous / 2);
  const Vec3 g = model_.gravity;
  for (ParticleId p : P.integrated.raw()) {  // no awake element reads a passive particle
    const Vec3 external = P.load[p] + (P.point_mass[p] + P.lumped_mass[p]) * g;
    const Vec3 free = free_axes(lock[p]);
    const Vec3 inertial = (dt * A * P.velocity[p]).cwiseProduct(free);
    x0_[p] = P.position[p] + inertial + ((dt * dt / mass_[p]) * external).cwiseProduct(free);
    xs_[p] = P.position[p] + inertial;  // the first guess follows the momentum
  }
  add_couples_to_x0(dt);  // moments on 3-DOF particles, at the step's start (couples.cpp)
  for (ParticleId p : P.rotational.raw()) {
    qs_[p] = P.orientation[p];
    if (!active[p]) continue;
    const Vec3 free = free_rotation_axes(lock[p]);
    const Vec3 inertial = (dt * A * P.angular_velocity[p]).cwiseProduct(free);
    r0_[p] = inertial + ((dt * dt / inertia_[p]) * P.moment[p]).cwiseProduct(free);
    qs_[p] = Quat(rotation_of(inertial) * P.orientation[p]).normalized();
  }
}

void Solver::finish_implicit_step(double dt) {
  const Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  double ke = 0, momentum2 = 0;
  for (ParticleId p : P.integrated.raw()) {
    if (!xs_[p].allFinite())
      throw NumericalError("solver: the position of particle " + std::to_string(p) + " is not finite after a " +
                           integrator_name(settings.integrator) + " step " + std::to_string(steps_) +
                           "; no particle was moved");
    vs_[p] = (xs_[p] - P.position[p]) / dt;  // eq. 3.64
    const double M = mass_[p];
    ke += M * vs_[p].squaredNorm();
    momentum2 = std::max(momentum2, M * M * vs_[p].squaredNorm());
  }
  for (ParticleId p : P.rotational.raw()) {
    if (!active[p]) continue;
    if (!qs_[p].coeffs().allFinite())
      throw NumericalError("solver: the frame of particle " + std::to_string(p) + " is not finite after a " +
                           integrator_name(settings.integrator) + " step " + std::to_string(steps_) +
                           "; no particle was moved");
    ws_[p] = rotation_vector(qs_[p] * P.orientation[p].conjugate()) / dt;
    const double I = inertia_[p];
    ke += I * ws_[p].squaredNorm();
    momentum2 = std::max(momentum2, I * I * ws_[p].squaredNorm());
  }
  // motion() compares M |v| / dt with forces; this step's dt is vie_dt.
  commit(xs_.data(), vs_.data(), qs_.data(), ws_.data(), ke, momentum2 * (settings.dt * settings.dt) / (dt * dt));
}

void Solver::local_step(const Vec3* x, const Quat* q) {
  accumulate_projections(model_, x, q, settings.geometric_factor, {Fs_.data(), Ss_.data(), Ts_.data(), Ks_.data()});
  ++evaluations_;
  accumulate_pressure_forces(x, Fs_.data(), nullptr);  // an external force, evaluated where the particles are
  if (model_.csts.items.empty()) return;
  // CST membranes (cst_forces.cpp) project each corner by its force over
  // twice its eq. 3.40 stiffness, as a bar does.
  const std::size_t n = model_.particles.capacity();
  if (cst_weight_.size() != n) cst_weight_.resize(n);
  std::fill(cst_weight_.begin(), cst_weight_.end(), 0.0);
  accumulate_cst_forces(x, Fs_.data(), cst_weight_.data());
  for (std::size_t p = 0; p < n; ++p) Ss_[p] += 2 * cst_weight_[p];
}

void Solver::integrate_vie() {
  const double dt = vie_dt();
  start_implicit_step(dt);
  const Particles& P = model_.particles;
  const std::uint8_t* lock = P.lock.data();
  const double inv_dt2 = 1 / (dt * dt);
  const int iterations = settings.vie_iterations > 0 ? settings.vie_iterations : kVieIterations;
  for (int it = 0; it < iterations; ++it) {
    local_step(xs_.data(), qs_.data());
    for (ParticleId p : P.integrated.raw()) {  // global step, eq. 3.63 with the momentum term
      const double m = mass_[p] * inv_dt2;
      xs_[p] += ((m * (x0_[p] - xs_[p]) + Fs_[p]) / (m + Ss_[p])).cwiseProduct(free_axes(lock[p]));
    }
    rotation_global_step(inv_dt2);
  }
  finish_implicit_step(dt);
}

void Solver::rotation_global_step(double inv_dt2) {
  const Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  const std::uint8_t* lock = P.lock.data();
  for (ParticleId p : P.rotational.raw()) {
    if (!active[p]) continue;
    const double m = inertia_[p] * inv_dt2;
    const Vec3 turned = rotation_vector(qs_[p] * P.orientation[p].conjugate());
    const Vec3 r = ((m * (r0_[p] - turned) + Ts_[p]) / (m + Ks_[p])).cwiseProduct(free_rotation_axes(lock[p]));
    qs_[p] = Quat(rotation_of(r) * qs_[p]).normalized();
  }
}

}  // namespace tendril
