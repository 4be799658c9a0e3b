#pragma once
// Shared by the meshing tests: small mesh builders and a fingerprint of a
// model that must not change when an operation is refused.
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "model/model.hpp"
#include "quad_mesh.hpp"

namespace tendril::meshing::test {

// rows x cols quads over the unit grid, vertex (r, c) at index r * (cols + 1) + c.
inline QuadMesh unit_grid(int rows, int cols) {
  QuadMesh m;
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c <= cols; ++c) m.positions.push_back(Vec3(c, r, 0));
  auto at = [&](int r, int c) { return Index(r * (cols + 1) + c); };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) m.quads.push_back({at(r, c), at(r, c + 1), at(r + 1, c + 1), at(r + 1, c)});
  return m;
}

// Builds a mesh from quads given by corner positions, merging exactly equal
// positions into one vertex.
struct MeshBuilder {
  QuadMesh mesh;
  std::map<std::tuple<double, double, double>, Index> ids;
  Index vertex(const Vec3& x) {
    auto [it, fresh] = ids.try_emplace({x.x(), x.y(), x.z()}, Index(mesh.positions.size()));
    if (fresh) mesh.positions.push_back(x);
    return it->second;
  }
  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    mesh.quads.push_back({vertex(a), vertex(b), vertex(c), vertex(d)});
  }
};

inline Section patch_section() { return Section{1e3, 0, 5, 0}; }
inline Section beam_section() { return Section{1e6, 10, 0, 0}; }

// Everything a refused operation could have touched, compared exactly.
struct Fingerprint {
  std::size_t particles, capacity, darts, dart_capacity, bars, hinges, blocks, live_blocks;
  std::vector<Vec3> position;
  std::vector<std::uint8_t> alive, lock;
  std::vector<std::uint32_t> generation, degree;
  std::vector<ParticleId> free_slots;
  std::vector<bool> block_alive;
  std::string check;

  explicit Fingerprint(const Model& m)
      : particles(m.particle_count()),
        capacity(m.particles.capacity()),
        darts(m.map.dart_count()),
        dart_capacity(m.map.capacity()),
        bars(m.bars.size()),
        hinges(m.hinges.size()),
        blocks(m.blocks.size()),
        live_blocks(m.block_count()),
        position(m.particles.position),
        alive(m.particles.alive),
        lock(m.particles.lock),
        generation(m.particles.generation),
        degree(m.particles.degree),
        free_slots(m.particles.free_slots),
        check(m.check()) {
    for (const Block& b : m.blocks) block_alive.push_back(b.alive);
  }
  bool operator==(const Fingerprint&) const = default;
};

}  // namespace tendril::meshing::test
