#pragma once
// Every integrator a model can run with: the explicit and implicit ones
// and the constraint-based ones (projective, mixed), for tests that check
// a behaviour under all of them.
#include <vector>

#include "physics/solver.hpp"

namespace tendril::test {

inline std::vector<Integrator> every_integrator() {
  std::vector<Integrator> all(kIntegrators.begin(), kIntegrators.end());
  all.insert(all.end(), kConstraintIntegrators.begin(), kConstraintIntegrators.end());
  return all;
}

}  // namespace tendril::test
