#include "catmull_clark.hpp"

#include "edge_table.hpp"

namespace tendril::meshing {

QuadMesh catmull_clark(const PolygonMesh& m, const std::vector<bool>& pinned) {
  const std::size_t nv = m.positions.size(), nf = m.faces.size();
  if (!pinned.empty() && pinned.size() != nv)
    throw ModelError("catmull_clark: pinned has " + std::to_string(pinned.size()) + " flags for " +
                     std::to_string(nv) + " vertices");
  const EdgeTable t = edge_table(m.faces, nv, "catmull_clark");
  const std::size_t ne = t.ends.size();
  const std::vector<bool> boundary = boundary_vertices(t, nv);

  QuadMesh out;
  out.positions.resize(nv + nf + ne);
  const Index face_base = Index(nv), edge_base = Index(nv + nf);

  std::vector<Vec3> face_point(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    Vec3 sum = Vec3::Zero();
    for (Index v : m.faces[f]) sum += m.positions[v];
    face_point[f] = sum / double(m.faces[f].size());
    out.positions[face_base + f] = face_point[f];
  }
  for (std::size_t e = 0; e < ne; ++e) {
    const Vec3& a = m.positions[t.ends[e][0]];
    const Vec3& b = m.positions[t.ends[e][1]];
    out.positions[edge_base + e] = t.boundary(Index(e)) ? Vec3((a + b) / 2)
                                                        : Vec3((a + b + face_point[t.faces[e][0]] + face_point[t.faces[e][1]]) / 4);
  }

  // Interior vertices: sums over incident faces and edges.
  std::vector<Vec3> face_sum(nv, Vec3::Zero()), neighbour_sum(nv, Vec3::Zero());
  std::vector<unsigned> faces_at(nv, 0), edges_at(nv, 0);
  for (std::size_t f = 0; f < nf; ++f)
    for (Index v : m.faces[f]) face_sum[v] += face_point[f], ++faces_at[v];
  for (const auto& e : t.ends) {
    neighbour_sum[e[0]] += m.positions[e[1]];
    neighbour_sum[e[1]] += m.positions[e[0]];
    ++edges_at[e[0]], ++edges_at[e[1]];
  }
  for (std::size_t v = 0; v < nv; ++v) {
    const Vec3& x = m.positions[v];
    if (boundary[v] || edges_at[v] == 0 || (!pinned.empty() && pinned[v])) {
      out.positions[v] = x;
      continue;
    }
    // Without a boundary edge, a manifold fan has as many faces as edges.
    if (faces_at[v] != edges_at[v])
      throw ModelError("catmull_clark: vertex " + std::to_string(v) + " has " + std::to_string(faces_at[v]) +
                       " faces but " + std::to_string(edges_at[v]) + " edges; its faces do not form one fan");
    const double n = edges_at[v];
    // (Q + 2R + (n-3)V)/n with R = (V + mean neighbour)/2, expanded.
    out.positions[v] = (face_sum[v] / n + neighbour_sum[v] / n) / n + x * ((n - 2) / n);
  }

  out.quads.reserve(ne * 2);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& face = m.faces[f];
    const std::size_t k = face.size();
    for (std::size_t i = 0; i < k; ++i)
      out.quads.push_back({face[i], edge_base + t.face_edges[f][i], face_base + Index(f),
                           edge_base + t.face_edges[f][(i + k - 1) % k]});
  }
  return out;
}

QuadMesh catmull_clark(const QuadMesh& m, const std::vector<bool>& pinned) {
  return catmull_clark(to_polygons(m), pinned);
}

}  // namespace tendril::meshing
