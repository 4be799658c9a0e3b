#include "physics/solver.hpp"

#include <algorithm>
#include <cmath>

#include "physics/free_axes.hpp"
#include "physics/numerical_errors.hpp"

namespace tendril {

const char* damping_name(Damping d) {
  switch (d) {
    case Damping::None: return "none";
    case Damping::Viscous: return "viscous";
    case Damping::Kinetic: return "kinetic";
  }
  return "?";
}

const char* integrator_name(Integrator i) {
  switch (i) {
    case Integrator::Leapfrog: return "leapfrog";
    case Integrator::SymplecticEuler: return "symplectic_euler";
    case Integrator::VelocityVerlet: return "velocity_verlet";
    case Integrator::Midpoint: return "midpoint";
    case Integrator::RK4: return "rk4";
    case Integrator::VariationalImplicitEuler: return "vie";
    case Integrator::ProjectiveDynamics: return "projective";
    case Integrator::Mixed: return "mixed";
    case Integrator::Newton: return "newton";
    case Integrator::Auto: return "auto";
  }
  return "?";
}

std::optional<Integrator> parse_integrator(std::string_view name) {
  for (Integrator i : kIntegrators)
    if (name == integrator_name(i)) return i;
  for (Integrator i : kConstraintIntegrators)
    if (name == integrator_name(i)) return i;
  for (Integrator i : kStaticIntegrators)
    if (name == integrator_name(i)) return i;
  if (name == integrator_name(Integrator::Auto)) return Integrator::Auto;
  return std::nullopt;
}

int force_evaluations_per_step(Integrator i) {
  switch (i) {
    case Integrator::Leapfrog:
    case Integrator::SymplecticEuler: return 1;
    case Integrator::VelocityVerlet:
    case Integrator::Midpoint: return 2;
    case Integrator::RK4: return 4;
    // Constraint-based: one evaluation for the residual, then one local step
    // per iteration (SolverSettings::vie_iterations); the explicit phase of
    // Mixed takes one.
    case Integrator::VariationalImplicitEuler:
    case Integrator::ProjectiveDynamics:
    case Integrator::Mixed: return 1;
    // Newton: the residual, then one per trial of its line search.
    case Integrator::Newton: return 1;
    case Integrator::Auto: return 1;  // Leapfrog's or Newton's
  }
  return 0;
}

double fictitious_mass_scale(Integrator i) {
  switch (i) {
    case Integrator::Leapfrog:
    case Integrator::VelocityVerlet:
    case Integrator::RK4:
    case Integrator::VariationalImplicitEuler:
    case Integrator::ProjectiveDynamics:
    case Integrator::Mixed:
    case Integrator::Newton: return 1;  // Newton has no masses: 1 for a switch to another integrator
    case Integrator::Auto: return 1;    // Leapfrog's
    case Integrator::SymplecticEuler: return 2;
    case Integrator::Midpoint: return 48;
  }
  return 1;
}

const char* mass_mode_name(MassMode m) {
  switch (m) {
    case MassMode::Fictitious: return "fictitious";
    case MassMode::Physical: return "physical";
  }
  return "?";
}

std::optional<MassMode> parse_mass_mode(std::string_view name) {
  for (MassMode m : {MassMode::Fictitious, MassMode::Physical})
    if (name == mass_mode_name(m)) return m;
  return std::nullopt;
}

const char* Solver::phase() const {
  if (settings.integrator == Integrator::Auto) return integrator_name(auto_last_);
  if (settings.integrator != Integrator::Mixed) return integrator_name(settings.integrator);
  return mixed_implicit_ ? integrator_name(settings.mixed_implicit) : "leapfrog";
}

namespace {
bool implicit(Integrator i) {
  return i == Integrator::VariationalImplicitEuler || i == Integrator::ProjectiveDynamics || i == Integrator::Mixed;
}
}  // namespace

void Solver::compute_forces() {
  Particles& P = model_.particles;
  accumulate_forces(P.position.data(), P.orientation.data(), P.force.data(), P.stiffness.data(), P.torque.data(),
                    P.rot_stiffness.data());
  ++evaluations_;
}

void Solver::step() {
  // Auto steps as the integrator it resolves to: every part of the step
  // reads settings.integrator, which names it until the step ends.
  const Integrator chosen = settings.integrator;
  if (chosen == Integrator::Auto) settings.integrator = auto_last_ = auto_choice_;
  try {
    take_step();
  } catch (...) {
    settings.integrator = chosen;
    failed_.push_back(steps_);
    failed_newton_.push_back(chosen == Integrator::Auto && auto_last_ == Integrator::Newton);
    throw;
  }
  settings.integrator = chosen;
  if (chosen == Integrator::Auto && auto_last_ == Integrator::Newton) {
    if (auto_newton_steps_.empty() || auto_newton_steps_.back().end != steps_ - 1)
      auto_newton_steps_.push_back({steps_ - 1, steps_});
    else
      auto_newton_steps_.back().end = steps_;
  }
}

void Solver::step_auto_newton() {
  if (settings.integrator != Integrator::Auto)
    throw ModelError(std::string("solver: a step of \"auto\" as Newton's, but the integrator is \"") +
                     integrator_name(settings.integrator) + "\"");
  const Integrator before = auto_choice_;
  auto_choice_ = Integrator::Newton;
  try {
    step();
  } catch (...) {
    auto_choice_ = before;
    throw;
  }
  auto_choice_ = before;
}

void Solver::take_step() {
  if (steps_ % kRunawayCheckEvery == 0) check_runaway();
  size_scratch();
  if (settings.integrator == Integrator::Newton) {
    mixed_implicit_ = false, mixed_peak_ = 0;
    integrate_newton();
    count_step(settings.dt);
    return;
  }
  if (fused_kick_drift_applies()) {
    mixed_implicit_ = false, mixed_peak_ = 0;
    fused_kick_drift(settings.integrator == Integrator::SymplecticEuler || half_step_);
    count_step(settings.dt);
    return;
  }
  compute_forces();
  // Leapfrog's and Symplectic Euler's kick finds the masses in its own pass.
  const bool kick_prepares =
      settings.integrator == Integrator::Leapfrog || settings.integrator == Integrator::SymplecticEuler;
  if (!kick_prepares) prepare_masses();
  if (settings.integrator != Integrator::Mixed) mixed_implicit_ = false, mixed_peak_ = 0;
  switch (settings.integrator) {
    case Integrator::Leapfrog: kick_drift(half_step_, kick_prepares); break;
    case Integrator::SymplecticEuler: kick_drift(true, kick_prepares); break;
    case Integrator::VelocityVerlet: integrate_velocity_verlet(); break;
    case Integrator::Midpoint: integrate_midpoint(); break;
    case Integrator::RK4: integrate_rk4(); break;
    case Integrator::VariationalImplicitEuler: integrate_vie(); break;
    case Integrator::ProjectiveDynamics: integrate_projective(); break;
    case Integrator::Mixed: integrate_mixed(); return;  // counts its own step and time
    case Integrator::Newton: break;                     // taken above
    case Integrator::Auto: break;                       // step() resolved it
  }
  count_step(implicit(settings.integrator) ? vie_dt() : settings.dt);
}

void Solver::count_step(double dt) {
  ++steps_;
  time_ += dt;
  ++model_.steps;
  model_.time += dt;
}

void Solver::size_scratch() {
  const std::size_t n = model_.particles.capacity();
  if (mass_.size() != n) mass_.resize(n);
  const bool rotating = !model_.particles.rotational.empty();
  if (rotating && inertia_.size() != n) inertia_.resize(n);
  const Integrator i = settings.integrator;
  if (i == Integrator::Leapfrog || i == Integrator::SymplecticEuler) return;
  if (implicit(i) && x0_.size() != n) {
    x0_.resize(n);
    r0_.resize(n);
  }
  // xs_ alone may have its size already: the fused bar step drifts into it.
  if (xs_.size() != n || Fs_.size() != n) {
    xs_.resize(n);
    Fs_.resize(n);
    vs_.resize(n);
    Ss_.resize(n);
  }
  if (rotating && qs_.size() != n) {
    qs_.resize(n);
    Ts_.resize(n);
    ws_.resize(n);
    Ks_.resize(n);
  }
  if (i == Integrator::RK4 && sum_x_.size() != n) {
    sum_x_.resize(n);
    sum_v_.resize(n);
  }
  if (i == Integrator::RK4 && rotating && sum_r_.size() != n) {
    sum_r_.resize(n);
    sum_w_.resize(n);
  }
}

void Solver::prepare_masses() {
  const Particles& P = model_.particles;
  const bool physical = settings.mass_mode == MassMode::Physical;
  const double mass_scale =
      settings.mass_factor * fictitious_mass_scale(settings.integrator) * 0.5 * settings.dt * settings.dt;  // eq. 3.4
  double residual2 = 0;
  for (ParticleId p : P.integrated.raw()) {
    if (!P.force[p].allFinite() || !std::isfinite(P.stiffness[p]))
      throw NumericalError("solver: the force or stiffness on " + describe_particle(model_, ParticleId(p)) +
                           " is not finite at step " + std::to_string(steps_) + "; no particle was moved");
    const Vec3 free = free_axes(P.lock[p]);
    double M;
    if (physical) {
      M = P.point_mass[p] + P.lumped_mass[p];
      if (!(M > 0)) {
        if (free.isZero())
          M = 1;  // fully locked: its mass only ever scales zero
        else
          throw ModelError("solver: particle " + std::to_string(p) +
                           " has no physical mass; mass_mode \"physical\" needs a point mass or a line mass on "
                           "every particle that can move");
      }
    } else {
      M = mass_scale * P.stiffness[p];
      if (!(M > 0))
        throw NumericalError("solver: " + describe_particle(model_, ParticleId(p)) +
                             " has no stiffness: nothing holds it along its free axes, a mechanism (every element at "
                             "it with zero EA, or every neighbour passive) at step " + std::to_string(steps_) +
                             "; no particle was moved");
    }
    mass_[p] = M;
    residual2 = std::max(residual2, P.force[p].cwiseProduct(free).squaredNorm());
  }
  double torque2 = 0;
  if (!P.rotational.empty()) {
    if (physical) {
      // A half element of line mass mu and length L turning about its node:
      // mu L^3 / 24, the same about every axis (isotropic, thesis 3.2.4.2).
      for (ParticleId p : P.rotational.raw()) inertia_[p] = 0;
      for (const Beam6* b = model_.beam6s.awake_begin(); b != model_.beam6s.awake_end(); ++b) {
        const double I = b->line_mass * b->rest_length * b->rest_length * b->rest_length / 24;
        inertia_[b->i] += I;
        inertia_[b->j] += I;
      }
    }
    for (ParticleId p : P.rotational.raw()) {
      if (!P.active[p]) continue;
      if (!P.torque[p].allFinite() || !std::isfinite(P.rot_stiffness[p]))
        throw NumericalError("solver: the torque on " + describe_particle(model_, p) + " is not finite at step " +
                             std::to_string(steps_) + "; no particle was moved");
      const Vec3 free = free_rotation_axes(P.lock[p]);
      if (physical) {
        if (!(inertia_[p] > 0)) {
          if (!free.isZero())
            throw ModelError("solver: particle " + std::to_string(p) +
                             " has no rotary inertia; mass_mode \"physical\" needs a line mass on its 6-DOF beams "
                             "or its rotations locked");
          inertia_[p] = 1;
        }
      } else {
        inertia_[p] = mass_scale * P.rot_stiffness[p];  // eq. 3.50 with eq. 3.4
        if (!(inertia_[p] > 0))
          throw NumericalError("solver: particle " + std::to_string(p) + " has no rotational stiffness at step " +
                               std::to_string(steps_));
      }
      torque2 = std::max(torque2, P.torque[p].cwiseProduct(free).squaredNorm());
    }
  }
  torque_residual_ = std::sqrt(torque2);
  residual_ = std::max(std::sqrt(residual2), torque_residual_);
}

void Solver::stage_forces() {
  accumulate_forces(xs_.data(), qs_.data(), Fs_.data(), Ss_.data(), Ts_.data(), Ks_.data());
  ++evaluations_;
  const Particles& P = model_.particles;
  for (ParticleId p : P.integrated.raw()) {
    if (!Fs_[p].allFinite() || !xs_[p].allFinite())
      throw NumericalError("solver: the force on " + describe_particle(model_, ParticleId(p)) + " is not finite at a " +
                           integrator_name(settings.integrator) + " stage of step " + std::to_string(steps_) +
                           "; no particle was moved");
  }
  for (ParticleId p : P.rotational.raw()) {
    if (!P.active[p]) continue;
    if (!Ts_[p].allFinite() || !qs_[p].coeffs().allFinite())
      throw NumericalError("solver: the torque on " + describe_particle(model_, p) + " is not finite at a " +
                           integrator_name(settings.integrator) + " stage of step " + std::to_string(steps_) +
                           "; no particle was moved");
  }
}

double Solver::viscous_rate() const { return settings.damping == Damping::Viscous ? settings.viscous : 0.0; }

bool Solver::kinetic_peak_passed(double ke) const {
  if (settings.damping != Damping::Kinetic || ke_samples_ < 1) return false;
  // Leapfrog and Symplectic Euler interpolate the peak (eq. 3.29-3.31). The
  // others stop where they are, so a plateau counts as the peak: a step that
  // lands exactly on equilibrium keeps its speed for one more step.
  const bool interpolated = settings.integrator == Integrator::Leapfrog ||
                            settings.integrator == Integrator::SymplecticEuler;
  return interpolated ? ke < ke_prev_ : ke <= ke_prev_;
}

void Solver::record_energy(double ke, double momentum2) {
  ke_prev2_ = ke_prev_;
  ke_prev_ = ke;
  ++ke_samples_;
  kinetic_energy_ = ke;
  // The force that would stop the fastest particle within one step: a
  // particle crossing its equilibrium at speed has no residual but is not
  // at rest, so convergence asks for both to be small.
  motion_ = std::sqrt(momentum2) / settings.dt;
}

void Solver::record_reset() {
  ++resets_;
  ke_samples_ = 0;
  ke_prev_ = ke_prev2_ = 0;
  kinetic_energy_ = 0;
  motion_ = 0;
  half_step_ = false;
}

RunResult Solver::run(double tolerance, std::uint64_t max_steps,
                      const std::function<void(const RunResult&)>& progress, std::uint64_t progress_every) {
  return run(RunLimits{tolerance, 0, max_steps}, progress, progress_every);
}

bool Solver::auto_newton_applies() const {
  return settings.integrator == Integrator::Auto && settings.mass_mode == MassMode::Fictitious &&
         settings.damping == Damping::Kinetic && !newton_refusal();
}

// Auto: Newton for a form-finding run of a model it takes; Leapfrog when it
// stalls (a mechanism, a slack part K has no stiffness for) or is slow to
// converge, from the positions it reached, which are nearer equilibrium
// (each Newton step lowers the energy). m:step stays Leapfrog.
Solver::RunScope::RunScope(Solver& s, bool statics) : s_(s), statics_(statics) { choose(); }

Solver::RunScope::~RunScope() { s_.auto_choice_ = Integrator::Leapfrog; }

void Solver::RunScope::choose() {
  s_.auto_choice_ = statics_ && s_.auto_newton_applies() ? Integrator::Newton : Integrator::Leapfrog;
  revision_ = s_.model_.revision;
  newton_steps_ = 0;
}

void Solver::RunScope::stepped() {
  // A rule or a front end changed the model: a new start for Newton, or
  // none (a beam joined).
  if (s_.model_.revision != revision_) return choose();
  if (s_.auto_choice_ == Integrator::Newton &&
      (s_.newton_stalled_ || ++newton_steps_ >= kAutoNewtonSteps || !s_.auto_newton_applies()))
    s_.auto_choice_ = Integrator::Leapfrog;
}

RunResult Solver::run(const RunLimits& limits, const std::function<void(const RunResult&)>& progress,
                      std::uint64_t progress_every) {
  RunMonitor monitor(model_, *this, limits);
  RunScope scope(*this);
  while (monitor.result().steps < limits.max_steps) {
    step();
    scope.stepped();
    if (monitor.observe()) return monitor.finish(true);
    if (monitor.failed()) break;
    if (progress && monitor.result().steps % progress_every == 0) progress(monitor.result());
  }
  return monitor.finish(false);
}

Vec3 Solver::reaction(ParticleId p) const {
  model_.require_particle(p, "reaction");
  const Vec3 locked = Vec3::Ones() - free_axes(model_.particles.lock[p]);
  return -model_.particles.force[p].cwiseProduct(locked);
}

Vec3 Solver::reaction_moment(ParticleId p) const {
  model_.require_particle(p, "reaction_moment");
  if (model_.particles.rot_degree[p] == 0) return Vec3::Zero();
  const Vec3 locked = Vec3::Ones() - free_rotation_axes(model_.particles.lock[p]);
  return -model_.particles.torque[p].cwiseProduct(locked);
}

void Solver::reset_motion() {
  Particles& P = model_.particles;
  for (auto& v : P.velocity.raw()) v.setZero();
  for (auto& w : P.angular_velocity.raw()) w.setZero();
  ke_samples_ = 0;
  ke_prev_ = ke_prev2_ = kinetic_energy_ = 0;
  half_step_ = false;
}

}  // namespace tendril
