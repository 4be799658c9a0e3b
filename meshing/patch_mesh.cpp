#include "patch_mesh.hpp"

#include <algorithm>

namespace tendril::meshing {

PatchMesh patch_mesh(const Model& m, BlockId b, const char* what) {
  m.require_block(b, what);
  if (m.blocks[b].kind != BlockKind::Patch)
    throw ModelError(std::string(what) + ": block " + std::to_string(b) + " is a " +
                     block_kind_name(m.blocks[b].kind) + ", not a patch");
  PatchMesh out;
  // Sorted vectors, binary searches and walks where hash maps and marked
  // orbits were: deriving the 128 x 128 net's quads took 25 ms with them.
  // The same vertices (the block's particles, ascending: Model::particles_of)
  // and quads.
  std::vector<Dart> darts = m.map.orbit(kComponentOrbit, m.blocks[b].dart);
  std::sort(darts.begin(), darts.end());
  out.particles.reserve(darts.size());
  for (Dart d : darts) out.particles.push_back(m.dart_particle[d]);
  std::sort(out.particles.begin(), out.particles.end());
  out.particles.erase(std::unique(out.particles.begin(), out.particles.end()), out.particles.end());
  out.mesh.positions.reserve(out.particles.size());
  for (ParticleId p : out.particles) out.mesh.positions.push_back(m.particles.position[p]);
  auto local = [&](ParticleId p) {
    return Index(std::lower_bound(out.particles.begin(), out.particles.end(), p) - out.particles.begin());
  };
  // A face is the quad of its smallest dart: walked from each dart of the
  // patch (its eight darts: x and alpha0(x) at each corner), no marks.
  auto smallest_of_quad = [&](Dart d, Dart& lo) {
    Dart x = d;
    lo = d;
    for (int c = 0; c < 4; ++c) {
      lo = std::min({lo, x, m.map.alpha(0, x)});
      x = m.map.alpha(1, m.map.alpha(0, x));
    }
    return x == d;  // false: the face is not a quad
  };
  out.mesh.quads.reserve(darts.size() / 8);
  for (Dart d : darts) {
    Dart lo;
    if (!smallest_of_quad(d, lo))
      throw ModelError(std::string(what) + ": patch " + std::to_string(b) + " has a face that is not a quad");
    if (lo != d) continue;
    // d, a0(d), a0 a1 a0(d), ... visit the corners in order around the face.
    QuadIndices q{};
    Dart x = d;
    for (int c = 0; c < 4; ++c) {
      q[c] = local(m.dart_particle[x]);
      x = m.map.alpha(1, m.map.alpha(0, x));
    }
    out.mesh.quads.push_back(q);
  }
  return out;
}

}  // namespace tendril::meshing
