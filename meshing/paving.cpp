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

QuadMesh paving(const std::vector<Vec3>& loop, const PavingOptions& options) {
  const std::size_t n = loop.size();
  if (n < 8) throw ModelError(kWhat + ": needs at least 8 particles, got " + std::to_string(n));
  if (n % 2)
    throw ModelError(kWhat + ": needs an even number of particles (an all-quad patch has an even boundary), got " +
                     std::to_string(n));
  Vec3 centroid = Vec3::Zero(), newell = Vec3::Zero();
  double perimeter = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!loop[i].allFinite()) throw ModelError(kWhat + ": point " + std::to_string(i) + " is not finite");
    for (std::size_t j = i + 1; j < n; ++j)
      if (loop[i] == loop[j]) throw ModelError(kWhat + ": points " + std::to_string(i) + " and " + std::to_string(j) + " coincide");
    centroid += loop[i] / double(n);
    newell += loop[i].cross(loop[(i + 1) % n]);
    perimeter += (loop[(i + 1) % n] - loop[i]).norm();
  }
  if (newell.norm() <= 1e-12 * perimeter * perimeter)
    throw ModelError(kWhat + ": the loop encloses no area (collinear or folded onto itself)");
  // The Newell normal follows the loop's winding, so the projected loop runs
  // counter-clockwise in (e1, e2).
  const Vec3 normal = newell.normalized();
  const Vec3 e1 = (normal.unitOrthogonal());
  const Vec3 e2 = normal.cross(e1);
  std::vector<Vec2> flat(n);
  std::vector<double> height(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = loop[i] - centroid;
    flat[i] = Vec2(d.dot(e1), d.dot(e2));
    height[i] = d.dot(normal);
  }
  if (!simple_polygon(flat))
    throw ModelError(kWhat + ": the loop, projected on its best-fit plane, intersects itself");
  const Mesh2 mesh = pave_2d(flat, options);
  height.resize(mesh.points.size(), 0.0);
  harmonic_heights(mesh, n, height);
  QuadMesh out;
  out.positions = loop;
  for (std::size_t v = n; v < mesh.points.size(); ++v)
    out.positions.push_back(centroid + mesh.points[v].x() * e1 + mesh.points[v].y() * e2 + height[v] * normal);
  out.quads = mesh.quads;
  return out;
}

CommittedPatch patch_by_paving(Model& m, const std::vector<ParticleId>& loop, const Section& s,
                               const PavingOptions& options) {
  std::unordered_set<ParticleId> seen;
  std::vector<Vec3> points;
  for (ParticleId p : loop) {
    m.require_particle(p, kWhat.c_str());
    if (!seen.insert(p).second) throw ModelError(kWhat + ": particle " + std::to_string(p) + " appears twice in the loop");
    points.push_back(std::as_const(m).particles.position[p]);
  }
  validate_section(s, kWhat);
  PlannedPatch plan{paving(points, options), loop};
  return commit_patch(m, plan, s, kWhat);
}

}  // namespace tendril::meshing
