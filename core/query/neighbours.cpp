#include "query/neighbours.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tendril {

// Clamped to +-2^62 before the cast (a centre at 1e300 would overflow it), so
// that a cell index plus a few neighbours stays in range too. Far cells
// alias, and the distance test sorts them out.
std::int64_t NeighbourIndex::coord(double v) const {
  constexpr double kFar = 4611686018427387904.0;  // 2^62
  return static_cast<std::int64_t>(std::clamp(std::floor(v / cell_), -kFar, kFar));
}

std::uint64_t NeighbourIndex::key(std::int64_t x, std::int64_t y, std::int64_t z) const {
  // 21 bits per axis (two's complement, wrapped): distinct cells far apart
  // may share a key, which only costs a distance test.
  const std::uint64_t m = (1u << 21) - 1;
  return (std::uint64_t(x) & m) << 42 | (std::uint64_t(y) & m) << 21 | (std::uint64_t(z) & m);
}

void NeighbourIndex::build(const Particles& particles, double cell) {
  if (!(cell > 0) || !std::isfinite(cell)) throw std::invalid_argument("neighbour index: cell size must be > 0");
  cell_ = cell;
  entries_.clear();
  for (ParticleId p = 0; p < particles.capacity(); ++p) {
    if (!particles.alive[p]) continue;
    const Vec3& x = particles.position[p];
    entries_.push_back({key(coord(x.x()), coord(x.y()), coord(x.z())), p});
  }
  std::sort(entries_.begin(), entries_.end());
}

std::vector<ParticleId> NeighbourIndex::within(const Particles& particles, const Vec3& centre, double radius) const {
  std::vector<std::pair<double, ParticleId>> found;
  const std::int64_t reach = std::max<std::int64_t>(1, std::int64_t(std::ceil(radius / cell_)));
  const std::int64_t cx = coord(centre.x()), cy = coord(centre.y()), cz = coord(centre.z());
  const double r2 = radius * radius;
  std::vector<std::uint64_t> keys;
  for (std::int64_t dx = -reach; dx <= reach; ++dx)
    for (std::int64_t dy = -reach; dy <= reach; ++dy)
      for (std::int64_t dz = -reach; dz <= reach; ++dz) keys.push_back(key(cx + dx, cy + dy, cz + dz));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());  // wrapped keys may repeat
  for (std::uint64_t k : keys) {
    auto it = std::lower_bound(entries_.begin(), entries_.end(), std::pair<std::uint64_t, ParticleId>{k, 0});
    for (; it != entries_.end() && it->first == k; ++it) {
      const ParticleId p = it->second;
      if (!particles.valid(p)) continue;
      const double d2 = (particles.position[p] - centre).squaredNorm();
      if (d2 <= r2) found.push_back({d2, p});
    }
  }
  std::sort(found.begin(), found.end());
  std::vector<ParticleId> out;
  out.reserve(found.size());
  for (const auto& f : found) out.push_back(f.second);
  return out;
}

}  // namespace tendril
