#pragma once
// The issue-18 net, small (bench/prestressed_net.hpp builds it for the
// benchmarks): s x s particles 1 m apart, bars on the grid edges (EA = 1e5 N,
// prestress 1e3 N), the boundary locked, `load` in -z on the interior.
#include <vector>

#include "model/model.hpp"

namespace tendril::test {

inline std::vector<ParticleId> prestressed_net(Model& m, int s, double load = 1.0) {
  std::vector<ParticleId> grid;
  for (int r = 0; r < s; ++r)
    for (int c = 0; c < s; ++c) {
      const ParticleId p = m.add_particle(Vec3(c, r, 0));
      grid.push_back(p);
      if (r == 0 || c == 0 || r == s - 1 || c == s - 1) m.set_lock(p, kLockTranslation);
      else m.set_load(p, Vec3(0, 0, -load));
    }
  m.add_quad_grid(grid, s, s, Section{1e5, 0, 1e3, 0});
  return grid;
}

}  // namespace tendril::test
