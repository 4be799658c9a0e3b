#include "catmull_clark_rules.hpp"

#include <unordered_set>
#include <utility>

#include "catmull_clark.hpp"
#include "patch_mesh.hpp"

namespace tendril::meshing {

QuadMesh loop_catmull_clark(const std::vector<Vec3>& loop, int levels) {
  const std::size_t n = loop.size();
  if (n < 3) throw ModelError("catmull_clark_patch: needs at least 3 particles, got " + std::to_string(n));
  if (levels < 0 || levels > kMaxLoopLevels)
    throw ModelError("catmull_clark_patch: levels must be between 0 and " + std::to_string(kMaxLoopLevels) +
                     ", got " + std::to_string(levels));
  double perimeter = 0;
  Vec3 newell = Vec3::Zero();  // twice the vector area of the loop
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = loop[i];
    const Vec3& b = loop[(i + 1) % n];
    if (!a.allFinite()) throw ModelError("catmull_clark_patch: point " + std::to_string(i) + " is not finite");
    for (std::size_t j = i + 1; j < n; ++j)
      if (loop[j] == a)
        throw ModelError("catmull_clark_patch: points " + std::to_string(i) + " and " + std::to_string(j) + " coincide");
    perimeter += (b - a).norm();
    newell += a.cross(b);
  }
  if (newell.norm() <= 1e-12 * perimeter * perimeter)
    throw ModelError("catmull_clark_patch: the loop encloses no area (collinear or folded onto itself)");
  PolygonMesh polygon;
  polygon.positions = loop;
  polygon.faces.emplace_back();
  for (std::size_t i = 0; i < n; ++i) polygon.faces[0].push_back(Index(i));
  QuadMesh mesh = catmull_clark(polygon);
  for (int k = 0; k < levels; ++k) mesh = catmull_clark(mesh);
  return mesh;
}

CommittedPatch patch_from_loop(Model& m, const std::vector<ParticleId>& loop, int levels, const Section& s) {
  const std::string what = "catmull_clark_patch";
  std::unordered_set<ParticleId> seen;
  std::vector<Vec3> points;
  for (ParticleId p : loop) {
    m.require_particle(p, what.c_str());
    if (!seen.insert(p).second) throw ModelError(what + ": particle " + std::to_string(p) + " appears twice in the loop");
    points.push_back(std::as_const(m).particles.position[p]);
  }
  validate_section(s, what);  // before the (possibly large) subdivision
  PlannedPatch plan{loop_catmull_clark(points, levels), loop};
  return commit_patch(m, plan, s, what);
}

SubdividedPatch subdivide_patch(Model& m, BlockId b) {
  m.require_block(b, "subdivide_patch");
  // A copy: add_patch grows m.blocks, which would leave a reference dangling.
  const Section section = std::as_const(m).blocks[b].section;
  return subdivide_patch(m, b, section);
}

SubdividedPatch subdivide_patch(Model& m, BlockId b, const Section& s) {
  const std::string what = "subdivide_patch";
  PatchMesh old = patch_mesh(m, b, what.c_str());
  if (m.is_cst_patch(b))  // the new quads would need a new triangulation
    throw ModelError(what + ": patch " + std::to_string(b) + " is in CST mode; switch patch " + std::to_string(b) +
                     " back to bars first");
  validate_section(s, what);
  // Locked particles hold a constraint and shared ones another block's
  // geometry: neither may be moved by smoothing.
  std::vector<bool> pinned(old.particles.size(), false);
  for (std::size_t i = 0; i < old.particles.size(); ++i) {
    const ParticleId p = old.particles[i];
    pinned[i] = (std::as_const(m).particles.lock[p] & kLockTranslation) || m.blocks_of(p).size() > 1;
  }
  PlannedPatch plan{catmull_clark(old.mesh, pinned), old.particles};
  SubdividedPatch out;
  static_cast<CommittedPatch&>(out) = commit_patch(m, plan, s, what);
  out.replaced = b;
  return out;
}

}  // namespace tendril::meshing
