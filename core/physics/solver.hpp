#pragma once
// Dynamic relaxation on the model's flat buffers (thesis 3.2): forces from
// elements and loads, lumped fictitious masses from the greatest direct
// stiffness (eq. 3.4), Leapfrog (eq. 3.11-3.12) with viscous (eq. 3.26) or
// kinetic damping with Barnes' parabolic correction (eq. 3.28-3.31).
// The step allocates nothing and reads the topology only through the buffers.
#include <cstdint>
#include <functional>
#include <string>

#include "model/model.hpp"

namespace tendril {

enum class Damping { None, Viscous, Kinetic };
const char* damping_name(Damping d);

struct SolverSettings {
  double dt = 1.0;                // time step; masses scale with dt^2 (eq. 3.4)
  Damping damping = Damping::Kinetic;
  double viscous = 0.1;           // C of eq. 3.26
  double geometric_factor = 1.0;  // g of eq. 3.35
  double mass_factor = 1.0;       // extra safety on eq. 3.4 (>= 1)
};

struct RunResult {
  std::uint64_t steps = 0;  // steps taken by this run
  double residual = 0;      // largest unconstrained force norm [N]
  bool converged = false;
};

// Thrown when a force or position stops being finite. The step that found it
// did not move any particle.
struct NumericalError : ModelError {
  using ModelError::ModelError;
};

class Solver {
 public:
  explicit Solver(Model& model) : model_(model) {}
  SolverSettings settings;

  void step();
  // Steps until both the residual and motion() are below `tolerance` [N], or
  // `max_steps` were taken.
  // `progress` (if set) is called every `progress_every` steps.
  RunResult run(double tolerance, std::uint64_t max_steps,
                const std::function<void(const RunResult&)>& progress = {}, std::uint64_t progress_every = 1000);

  void compute_forces();  // residual forces and direct stiffnesses at the current positions
  double residual() const { return residual_; }
  double kinetic_energy() const { return kinetic_energy_; }
  // Largest M |v| / dt: the force that would stop the fastest particle in one step.
  double motion() const { return motion_; }
  std::uint64_t steps() const { return steps_; }
  double time() const { return time_; }
  std::uint64_t kinetic_resets() const { return resets_; }
  // The force the supports exert on a locked particle (minus the residual
  // force along its locked axes).
  Vec3 reaction(ParticleId p) const;
  // Forgets velocities and the kinetic-energy history (after a topology change
  // that invalidates them, or on request).
  void reset_motion();

 private:
  void integrate_leapfrog();
  void check_finite() const;
  Model& model_;
  double residual_ = 0, motion_ = 0;
  double kinetic_energy_ = 0;
  double ke_prev_ = 0, ke_prev2_ = 0;  // E and D of eq. 3.29
  int ke_samples_ = 0;
  bool restart_ = true;  // the next velocity update is a half step
  std::uint64_t steps_ = 0, resets_ = 0;
  double time_ = 0;
};

}  // namespace tendril
