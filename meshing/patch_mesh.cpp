#include "patch_mesh.hpp"

#include <algorithm>
#include <unordered_map>

namespace tendril::meshing {

PatchMesh patch_mesh(const Model& m, BlockId b, const char* what) {
  m.require_block(b, what);
  if (m.blocks[b].kind != BlockKind::Patch)
    throw ModelError(std::string(what) + ": block " + std::to_string(b) + " is a " +
                     block_kind_name(m.blocks[b].kind) + ", not a patch");
  PatchMesh out;
  out.particles = m.particles_of(b);  // ascending
  std::unordered_map<ParticleId, Index> local;
  for (Index i = 0; i < out.particles.size(); ++i) {
    local.emplace(out.particles[i], i);
    out.mesh.positions.push_back(m.particles.position[out.particles[i]]);
  }
  std::vector<Dart> darts = m.map.orbit(kComponentOrbit, m.blocks[b].dart);
  std::sort(darts.begin(), darts.end());
  std::unordered_map<Dart, bool> done;
  done.reserve(darts.size());
  for (Dart d : darts) {
    if (done.count(d)) continue;
    m.map.for_orbit(kFaceOrbit, d, [&](Dart x) {
      done.emplace(x, true);
      return true;
    });
    // d, a0(d), a0 a1 a0(d), ... visit the corners in order around the face.
    QuadIndices q{};
    Dart x = d;
    for (int k = 0; k < 4; ++k) {
      q[k] = local.at(m.dart_particle[x]);
      x = m.map.alpha(1, m.map.alpha(0, x));
    }
    out.mesh.quads.push_back(q);
  }
  return out;
}

}  // namespace tendril::meshing
