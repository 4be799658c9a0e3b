#pragma once
// The prestressed net of issue 18, which bench_net and bench_scaling solve:
// side x side particles 1 m apart, bars on the grid edges (EA = 1e5 N,
// prestress 1e3 N), the boundary fixed, 1 N in -z on every interior
// particle.
#include <memory>
#include <vector>

#include "model/model.hpp"

namespace tendril::bench {

inline std::unique_ptr<Model> prestressed_net(int side) {
  auto m = std::make_unique<Model>();
  std::vector<ParticleId> grid;
  grid.reserve(std::size_t(side) * std::size_t(side));
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) {
      const ParticleId p = m->add_particle(Vec3(c, r, 0));
      grid.push_back(p);
      if (r == 0 || c == 0 || r == side - 1 || c == side - 1) m->set_lock(p, kLockTranslation);
      else m->set_load(p, Vec3(0, 0, -1));
    }
  m->add_quad_grid(grid, side, side, Section{1e5, 0, 1e3, 0});
  return m;
}

}  // namespace tendril::bench
