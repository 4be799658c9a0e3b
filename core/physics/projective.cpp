#include "physics/solver.hpp"

namespace tendril {
void Solver::integrate_projective() { throw ModelError("solver: the projective integrator is not available yet"); }
}  // namespace tendril
