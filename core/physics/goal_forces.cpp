// Goals as stiff springs for the explicit integrators: each pulls its
// particle towards its projection with its weight, which joins S (eq. 3.4)
// so the fictitious masses keep the step stable.
#include "physics/element_forces.hpp"
#include "physics/planarity.hpp"
#include "physics/rigid_body.hpp"
#include "physics/shell_bending.hpp"
#include "physics/solver.hpp"

namespace tendril {

void Solver::accumulate_goal_forces(const Vec3* x, Vec3* F, double* S) const {
  const std::uint8_t* active = model_.particles.active.data();
  const double gf = settings.geometric_factor;
  std::vector<Vec3> pulls;
  for (const Goal& g : model_.goals) {
    if (!active[g.i] || (g.j != kNone && !active[g.j])) continue;  // a passive particle stays frozen
    if (g.kind == Goal::Rigid) {
      if (!members_active(g, active)) continue;
      // S: the row sum of w (I - 1 1^T / n), 2 w (1 - 1/n), as for planarity.
      rigid_pulls(g, x, pulls);
      const double n = double(g.members.size());
      for (std::size_t a = 0; a < g.members.size(); ++a) {
        F[g.members[a]] += pulls[a];
        S[g.members[a]] += 2 * g.weight * (1 - 1 / n);
      }
      continue;
    }
    if (g.kind == Goal::Bend) {
      if (!(active[g.k] & active[g.l])) continue;
      const BendPulls f = bend_pulls(g, x);
      for (int a = 0; a < 4; ++a) {
        F[f.p[a]] += f.f[a];
        S[f.p[a]] += f.k[a];
      }
      continue;
    }
    if (g.kind == Goal::Planar) {
      if (!(active[g.k] & active[g.l])) continue;
      // S: the row sum of the goal's stiffness, w (1 - 1/4) on a corner's
      // own offset and w / 4 through each of the three others (S = w, the
      // twist's stiffness alone, lands a symmetric twist on its equilibrium
      // in one step, where Leapfrog's peak interpolation cannot see a peak).
      const PlanarityPulls f = planarity_pulls(g, x);
      for (int a = 0; a < 4; ++a) {
        F[f.p[a]] += f.f[a];
        S[f.p[a]] += 1.5 * g.weight;
      }
      continue;
    }
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
