// The neighbour index against brute force on random clouds.
#include <doctest/doctest.h>

#include <algorithm>
#include <random>

#include "model/model.hpp"
#include "query/neighbours.hpp"

using namespace tendril;

TEST_CASE("neighbour queries equal brute force, nearest first, for several cell sizes") {
  Model m;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-5, 5);
  for (int i = 0; i < 2000; ++i) m.add_particle(Vec3(u(rng), u(rng), u(rng)));
  for (int i = 0; i < 100; ++i) m.delete_particle(ParticleId(i * 7));
  for (double cell : {0.3, 1.0, 4.0}) {
    NeighbourIndex index;
    index.build(m.particles, cell);
    CHECK(index.size() == 1900);
    for (int q = 0; q < 50; ++q) {
      const Vec3 c(u(rng), u(rng), u(rng));
      const double r = 0.2 + 2.0 * q / 50.0;
      std::vector<std::pair<double, ParticleId>> brute;
      for (ParticleId p = 0; p < m.particles.capacity(); ++p)
        if (m.particles.valid(p) && (m.particles.position[p] - c).squaredNorm() <= r * r)
          brute.push_back({(m.particles.position[p] - c).squaredNorm(), p});
      std::sort(brute.begin(), brute.end());
      std::vector<ParticleId> expected;
      for (auto& b : brute) expected.push_back(b.second);
      CHECK(index.within(m.particles, c, r) == expected);
    }
  }
}
