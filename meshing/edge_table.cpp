#include "edge_table.hpp"

#include <algorithm>
#include <unordered_map>

namespace tendril::meshing {

PolygonMesh to_polygons(const QuadMesh& m) {
  PolygonMesh p;
  p.positions = m.positions;
  p.faces.reserve(m.quads.size());
  for (const QuadIndices& q : m.quads) p.faces.emplace_back(q.begin(), q.end());
  return p;
}

EdgeTable edge_table(const std::vector<std::vector<Index>>& faces, std::size_t vertex_count, const std::string& what) {
  EdgeTable t;
  t.face_edges.resize(faces.size());
  std::unordered_map<std::uint64_t, Index> id;  // (min, max) vertex pair -> edge
  id.reserve(faces.size() * 4);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    const std::string where = what + ": face " + std::to_string(f);
    if (face.size() < 3) throw ModelError(where + " has fewer than 3 corners");
    for (std::size_t k = 0; k < face.size(); ++k) {
      if (face[k] >= vertex_count)
        throw ModelError(where + " uses vertex " + std::to_string(face[k]) + " of " + std::to_string(vertex_count));
      for (std::size_t l = k + 1; l < face.size(); ++l)
        if (face[k] == face[l]) throw ModelError(where + " repeats vertex " + std::to_string(face[k]));
    }
    for (std::size_t k = 0; k < face.size(); ++k) {
      Index a = face[k], b = face[(k + 1) % face.size()];
      const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      auto [it, fresh] = id.try_emplace(key, Index(t.ends.size()));
      if (fresh) {
        t.ends.push_back({a, b});
        t.faces.push_back({Index(f), kNoFace});
      } else {
        auto& fs = t.faces[it->second];
        if (fs[1] != kNoFace)
          throw ModelError(what + ": the edge " + std::to_string(a) + "-" + std::to_string(b) +
                           " belongs to more than two faces");
        fs[1] = Index(f);
      }
      t.face_edges[f].push_back(it->second);
    }
  }
  return t;
}

std::vector<bool> boundary_vertices(const EdgeTable& t, std::size_t vertex_count) {
  std::vector<bool> out(vertex_count, false);
  for (Index e = 0; e < t.ends.size(); ++e)
    if (t.boundary(e)) out[t.ends[e][0]] = out[t.ends[e][1]] = true;
  return out;
}

}  // namespace tendril::meshing
