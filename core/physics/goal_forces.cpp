// Goals as stiff springs for the explicit integrators: each pulls its
// particle towards its projection with its weight, which joins S (eq. 3.4)
// so the fictitious masses keep the step stable.
#include "physics/element_forces.hpp"
#include "physics/solver.hpp"

namespace tendril {

void Solver::accumulate_goal_forces(const Vec3* x, Vec3* F, double* S) const {
  const std::uint8_t* active = model_.particles.active.data();
  const double gf = settings.geometric_factor;
  for (const Goal& g : model_.goals) {
    if (!active[g.i] || (g.j != kNone && !active[g.j])) continue;  // a passive particle stays frozen
    const GoalForce f = goal_force(g, x, gf);
    F[g.i] += f.fi;
    S[g.i] += f.k;
    if (g.kind == Goal::Length) {
      F[g.j] -= f.fi;
      S[g.j] += f.k;
    }
  }
}

}  // namespace tendril
