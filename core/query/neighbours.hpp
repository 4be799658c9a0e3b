#pragma once
// Neighbour search over particle positions by spatial hashing (sorted cell
// keys): building is O(n log n), a query visits only the cells its sphere
// touches. Results are sorted by distance, then id, so agents that consume
// them stay deterministic.
#include <cstdint>
#include <utility>
#include <vector>

#include "model/particles.hpp"

namespace tendril {

class NeighbourIndex {
 public:
  // Indexes every live particle with cells of edge `cell` (> 0).
  void build(const Particles& particles, double cell);
  // Live particles within `radius` of `centre` (inclusive), nearest first.
  std::vector<ParticleId> within(const Particles& particles, const Vec3& centre, double radius) const;
  double cell() const { return cell_; }
  std::size_t size() const { return entries_.size(); }

 private:
  std::uint64_t key(std::int64_t x, std::int64_t y, std::int64_t z) const;
  std::int64_t coord(double v) const;
  double cell_ = 1;
  std::vector<std::pair<std::uint64_t, ParticleId>> entries_;  // sorted by (cell key, id)
};

}  // namespace tendril
