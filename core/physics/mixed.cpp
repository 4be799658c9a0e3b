// The mixed solver of thesis 5.4.2.2 (fig. 5.17): Leapfrog while the model
// is far from equilibrium, where small steps make large changes, and the
// Variational Implicit Euler with its larger step (vie_dt) near it, or, with
// mixed_implicit = ProjectiveDynamics, the prefactored projective step.
// Near equilibrium means: the residual at a step's start fell to
// mixed_switch (default 1 %) of the largest residual seen in this Leapfrog
// phase. The VIE phase ends when the residual grows above twice the one it
// started from (a load, a rule or a script disturbed the model): Leapfrog
// takes over again with a fresh peak. Every switch forgets the motion
// (reset_motion): the two phases' velocities live on different time steps.
#include <algorithm>

#include "physics/solver.hpp"

namespace tendril {

void Solver::integrate_mixed() {
  if (!mixed_implicit_) {
    mixed_peak_ = std::max(mixed_peak_, residual_);
    if (residual_ <= settings.mixed_switch * mixed_peak_) {
      mixed_implicit_ = true;
      mixed_entry_ = residual_;
      reset_motion();
    }
  } else if (residual_ > 2 * mixed_entry_) {
    mixed_implicit_ = false;
    mixed_peak_ = residual_;
    reset_motion();
  }
  const double dt = mixed_implicit_ ? vie_dt() : settings.dt;
  if (mixed_implicit_) {
    if (settings.mixed_implicit == Integrator::ProjectiveDynamics) integrate_projective();
    else integrate_vie();
  } else {
    integrate_leapfrog();
  }
  count_step(dt);
}

}  // namespace tendril
