#include "paving.hpp"

#include <cmath>
#include <unordered_set>
#include <utility>

namespace tendril::meshing {
namespace {

const std::string kWhat = "paving";

// Heights of the new nodes above the plane: Gauss-Seidel on the graph
// Laplacian with the loop's heights fixed.
void harmonic_heights(const Mesh2& mesh, std::size_t fixed, std::vector<double>& height) {
  std::vector<std::vector<Index>> neighbours(mesh.points.size());
  for (const QuadIndices& q : mesh.quads)
    for (int k = 0; k < 4; ++k) neighbours[q[k]].push_back(q[(k + 1) % 4]), neighbours[q[k]].push_back(q[(k + 3) % 4]);
  double scale = 0;
  for (std::size_t v = 0; v < fixed; ++v) scale = std::max(scale, std::abs(height[v]));
  if (scale == 0) return;  // planar: every height stays 0
  for (int it = 0; it < 100000; ++it) {
    double change = 0;
    for (std::size_t v = fixed; v < height.size(); ++v) {
      double sum = 0;
      for (Index u : neighbours[v]) sum += height[u];
      const double h = sum / double(neighbours[v].size());  // each edge counted twice, evenly
      change = std::max(change, std::abs(h - height[v]));
      height[v] = h;
    }
    if (change <= 1e-14 * scale) break;
  }
}

}  // namespace

QuadMesh paving(const std::vector<Vec3>& loop, const PavingOptions& options) { return paving(loop, {}, options); }

QuadMesh paving(const std::vector<Vec3>& outer, const std::vector<std::vector<Vec3>>& holes,
                const PavingOptions& options) {
  const std::size_t n = outer.size();
  if (n < 8) throw ModelError(kWhat + ": needs at least 8 particles, got " + std::to_string(n));
  std::vector<Vec3> all = outer;
  for (const std::vector<Vec3>& hole : holes) all.insert(all.end(), hole.begin(), hole.end());
  if (all.size() % 2)
    throw ModelError(kWhat + ": needs an even number of particles (an all-quad patch has an even boundary), got " +
                     std::to_string(all.size()));
  // Points are numbered through all loops: the outer loop's, then each hole's.
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (!all[i].allFinite()) throw ModelError(kWhat + ": point " + std::to_string(i) + " is not finite");
    for (std::size_t j = i + 1; j < all.size(); ++j)
      if (all[i] == all[j]) throw ModelError(kWhat + ": points " + std::to_string(i) + " and " + std::to_string(j) + " coincide");
  }
  Vec3 centroid = Vec3::Zero(), newell = Vec3::Zero();
  double perimeter = 0;
  for (std::size_t i = 0; i < n; ++i) {
    centroid += outer[i] / double(n);
    newell += outer[i].cross(outer[(i + 1) % n]);
    perimeter += (outer[(i + 1) % n] - outer[i]).norm();
  }
  if (newell.norm() <= 1e-12 * perimeter * perimeter)
    throw ModelError(kWhat + ": the loop encloses no area (collinear or folded onto itself)");
  // The Newell normal follows the loop's winding, so the projected loop runs
  // counter-clockwise in (e1, e2).
  const Vec3 normal = newell.normalized();
  const Vec3 e1 = (normal.unitOrthogonal());
  const Vec3 e2 = normal.cross(e1);
  auto flatten = [&](const std::vector<Vec3>& loop) {
    std::vector<Vec2> flat;
    for (const Vec3& x : loop) flat.emplace_back((x - centroid).dot(e1), (x - centroid).dot(e2));
    return flat;
  };
  const std::vector<Vec2> flat = flatten(outer);
  std::vector<std::vector<Vec2>> flat_holes;
  for (const std::vector<Vec3>& hole : holes) flat_holes.push_back(flatten(hole));
  if (!simple_polygon(flat))
    throw ModelError(kWhat + ": the loop, projected on its best-fit plane, intersects itself");
  const Mesh2 mesh = pave_2d(flat, flat_holes, options);
  std::vector<double> height;
  for (const Vec3& x : all) height.push_back((x - centroid).dot(normal));
  height.resize(mesh.points.size(), 0.0);
  harmonic_heights(mesh, all.size(), height);
  QuadMesh out;
  out.positions = all;
  for (std::size_t v = all.size(); v < mesh.points.size(); ++v)
    out.positions.push_back(centroid + mesh.points[v].x() * e1 + mesh.points[v].y() * e2 + height[v] * normal);
  out.quads = mesh.quads;
  return out;
}

CommittedPatch patch_by_paving(Model& m, const std::vector<ParticleId>& loop, const Section& s,
                               const PavingOptions& options) {
  return patch_by_paving(m, loop, {}, s, options);
}

CommittedPatch patch_by_paving(Model& m, const std::vector<ParticleId>& outer,
                               const std::vector<std::vector<ParticleId>>& holes, const Section& s,
                               const PavingOptions& options) {
  std::unordered_set<ParticleId> seen;
  std::vector<ParticleId> all;
  auto gather = [&](const std::vector<ParticleId>& loop, const std::string& name) {
    std::vector<Vec3> points;
    for (ParticleId p : loop) {
      m.require_particle(p, kWhat.c_str());
      if (!seen.insert(p).second)
        throw ModelError(kWhat + ": particle " + std::to_string(p) + " appears twice in the " + name);
      points.push_back(std::as_const(m).particles.position[p]);
      all.push_back(p);
    }
    return points;
  };
  const std::vector<Vec3> points = gather(outer, holes.empty() ? "loop" : "loops");
  std::vector<std::vector<Vec3>> hole_points;
  for (const std::vector<ParticleId>& hole : holes) hole_points.push_back(gather(hole, "loops"));
  validate_section(s, kWhat);
  PlannedPatch plan{paving(points, hole_points, options), all};
  return commit_patch(m, plan, s, kWhat);
}

}  // namespace tendril::meshing
