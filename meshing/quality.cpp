#include "quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "edge_table.hpp"
#include "patch_mesh.hpp"

namespace tendril::meshing {
namespace {

struct Corner {
  double jacobian;
  double angle;  // degrees
};

std::array<Corner, 4> corners(const std::array<Vec3, 4>& p) {
  const Vec3 normal = (p[2] - p[0]).cross(p[3] - p[1]);
  const double nn = normal.norm();
  std::array<Corner, 4> out{};
  for (int i = 0; i < 4; ++i) {
    const Vec3 a = p[(i + 1) % 4] - p[i], b = p[(i + 3) % 4] - p[i];
    const double la = a.norm(), lb = b.norm();
    if (la == 0 || lb == 0 || nn == 0) {
      out[i] = {0, 0};
      continue;
    }
    const double j = a.cross(b).dot(normal) / (la * lb * nn);
    // atan2 of |a x b| and a.b is accurate near 0 and 180 degrees, where acos is not.
    double angle = std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / std::numbers::pi;
    if (j < 0) angle = 360 - angle;
    out[i] = {j, angle};
  }
  return out;
}

}  // namespace

std::array<double, 4> corner_jacobians(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  auto c = corners({p0, p1, p2, p3});
  return {c[0].jacobian, c[1].jacobian, c[2].jacobian, c[3].jacobian};
}

double scaled_jacobian(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  auto j = corner_jacobians(p0, p1, p2, p3);
  return std::min(std::min(j[0], j[1]), std::min(j[2], j[3]));
}

Quality quality(const QuadMesh& m) {
  if (m.quads.empty()) throw ModelError("quality: the mesh has no quads");
  const EdgeTable t = edge_table(to_polygons(m).faces, m.positions.size(), "quality");
  Quality q;
  q.quads = m.quads.size();
  q.jacobian_min = std::numeric_limits<double>::infinity();
  q.angle_min = std::numeric_limits<double>::infinity();
  q.angle_max = -std::numeric_limits<double>::infinity();
  double sum = 0;
  for (const QuadIndices& quad : m.quads) {
    auto c = corners({m.positions[quad[0]], m.positions[quad[1]], m.positions[quad[2]], m.positions[quad[3]]});
    double jmin = std::numeric_limits<double>::infinity();
    for (const Corner& k : c) {
      jmin = std::min(jmin, k.jacobian);
      q.angle_min = std::min(q.angle_min, k.angle);
      q.angle_max = std::max(q.angle_max, k.angle);
    }
    q.jacobian_min = std::min(q.jacobian_min, jmin);
    sum += jmin;
  }
  q.jacobian_mean = sum / double(m.quads.size());

  std::vector<unsigned> valence(m.positions.size(), 0);
  for (const auto& e : t.ends) ++valence[e[0]], ++valence[e[1]];
  const std::vector<bool> boundary = boundary_vertices(t, m.positions.size());
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    if (valence[v] == 0 || boundary[v]) continue;  // unused or on the boundary
    ++q.interior_vertices;
    q.irregular_vertices += valence[v] != 4;
  }
  q.irregular_fraction = q.interior_vertices ? double(q.irregular_vertices) / double(q.interior_vertices) : 0;
  return q;
}

Quality quality(const Model& m, BlockId patch) { return quality(patch_mesh(m, patch, "quality").mesh); }

}  // namespace tendril::meshing
