#include "edge_classification.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>
#include <utility>

#include "patch_mesh.hpp"

namespace tendril::meshing {
namespace {

const std::string kWhat = "edge classification";
constexpr std::uint8_t kUnlabelled = 4;
using Labels = std::array<std::uint8_t, 4>;  // per corner of a quad: its corner of the unit square, 0..3 counter-clockwise from (0,0)

// The yarn of a quad edge whose ends carry square corners A and B: (0,0)-(1,0)
// and (1,1)-(0,1) run along u (warp), the other two along v (weft).
Yarn yarn_of(std::uint8_t A, std::uint8_t B) {
  const std::uint8_t start = ((B - A) & 3) == 1 ? A : B;
  return start % 2 == 0 ? Yarn::Warp : Yarn::Weft;
}

// The square corner across edge `y`: the neighbour lies on the other side, so
// a warp edge mirrors v (0 <-> 3, 1 <-> 2) and a weft edge mirrors u (0 <-> 1, 2 <-> 3).
std::uint8_t mirror(std::uint8_t X, Yarn y) { return y == Yarn::Warp ? std::uint8_t(3 - X) : std::uint8_t(X ^ 1); }

// Labels of a quad whose corner i is square corner A and adjacent corner j is
// B: walking the quad from i towards j walks the square from A towards B.
Labels spread(int i, int j, std::uint8_t A, std::uint8_t B) {
  const int d = (j - i) & 3, e = (B - A) & 3;
  Labels out{};
  for (int k = 0; k < 4; ++k) out[(i + k * d) & 3] = std::uint8_t((A + k * e) & 3);
  return out;
}

int corner_of(const QuadIndices& q, Index v) {
  for (int k = 0; k < 4; ++k)
    if (q[k] == v) return k;
  return -1;
}

std::string vertex_name(Index v, const std::vector<ParticleId>* names) {
  return names ? "particle " + std::to_string((*names)[v]) : "vertex " + std::to_string(v);
}

// The odd-valence interior vertex nearest (in edges) to a or b, as text.
std::string odd_vertex_near(const QuadMesh& m, const EdgeTable& t, Index a, Index b,
                            const std::vector<ParticleId>* names) {
  const std::size_t n = m.positions.size();
  std::vector<std::vector<Index>> adjacent(n);
  for (const auto& e : t.ends) adjacent[e[0]].push_back(e[1]), adjacent[e[1]].push_back(e[0]);
  const std::vector<bool> boundary = boundary_vertices(t, n);
  std::vector<bool> seen(n, false);
  std::deque<Index> queue{a, b};
  seen[a] = seen[b] = true;
  while (!queue.empty()) {
    const Index v = queue.front();
    queue.pop_front();
    if (!boundary[v] && adjacent[v].size() % 2)
      return "around " + vertex_name(v, names) + ", an interior vertex of valence " + std::to_string(adjacent[v].size());
    for (Index u : adjacent[v])
      if (!seen[u]) seen[u] = true, queue.push_back(u);
  }
  return "with no interior vertex of odd valence in reach";
}

EdgeClasses classify(const QuadMesh& m, const ClassifyOptions& o, const std::vector<ParticleId>* names) {
  if (m.quads.empty()) throw ModelError(kWhat + ": the patch has no quads");
  if (!o.warp.allFinite()) throw ModelError(kWhat + ": the warp direction is not finite");
  EdgeClasses c;
  c.edges = edge_table(to_polygons(m).faces, m.positions.size(), kWhat);
  const EdgeTable& t = c.edges;
  const std::size_t quads = m.quads.size(), edges = t.ends.size();
  std::vector<Labels> label(quads, Labels{kUnlabelled, kUnlabelled, kUnlabelled, kUnlabelled});
  std::vector<bool> classified(edges, false), judged(edges, false);
  c.yarn.assign(edges, Yarn::Warp);

  auto seed_labels = [&](Index q) {
    const QuadIndices& quad = m.quads[q];
    if (o.warp.isZero()) return spread(0, 1, 0, 1);
    int best = 0;
    double best_cos = -1, along = 1;
    for (int k = 0; k < 4; ++k) {
      const Vec3 d = m.positions[quad[(k + 1) % 4]] - m.positions[quad[k]];
      const double cos = d.dot(o.warp) / (d.norm() * o.warp.norm());
      if (std::abs(cos) > best_cos + 1e-12) best = k, best_cos = std::abs(cos), along = cos;
    }
    const int next = (best + 1) % 4;
    return along >= 0 ? spread(best, next, 0, 1) : spread(next, best, 0, 1);
  };

  std::deque<Index> queue;
  for (Index seed = 0; seed < quads; ++seed) {
    if (label[seed][0] != kUnlabelled) continue;
    label[seed] = seed_labels(seed);
    queue.push_back(seed);
    while (!queue.empty()) {
      const Index q = queue.front();
      queue.pop_front();
      for (int k = 0; k < 4; ++k) {
        const Index e = t.face_edges[q][k];
        const Index a = m.quads[q][k], b = m.quads[q][(k + 1) % 4];
        const Yarn y = yarn_of(label[q][k], label[q][(k + 1) % 4]);
        if (!classified[e]) c.yarn[e] = y, classified[e] = true;
        const Index other = t.faces[e][0] == q ? t.faces[e][1] : t.faces[e][0];
        if (other == kNoFace || judged[e]) continue;
        judged[e] = true;
        const int i = corner_of(m.quads[other], a), j = corner_of(m.quads[other], b);
        const Labels expected = spread(i, j, mirror(label[q][k], y), mirror(label[q][(k + 1) % 4], y));
        if (label[other][0] == kUnlabelled) {
          label[other] = expected;
          queue.push_back(other);
        } else if (yarn_of(label[other][i], label[other][j]) != y) {
          if (!o.allow_seams)
            throw ModelError(kWhat + ": warp and weft cannot be assigned consistently: quads " + std::to_string(q) +
                             " and " + std::to_string(other) + " disagree on the edge between " +
                             vertex_name(a, names) + " and " + vertex_name(b, names) +
                             ", where a chord of quads closes onto itself turned by 90 degrees (" +
                             odd_vertex_near(m, t, a, b, names) + "); accept a seam there with the seams option");
          c.seams.push_back(e);
        } else if (label[other] != expected) {
          c.flips.push_back(e);
        }
      }
    }
  }
  c.frame.resize(quads);
  for (Index q = 0; q < quads; ++q)
    for (int k = 0; k < 4; ++k) c.frame[q][label[q][k]] = m.quads[q][k];
  std::sort(c.seams.begin(), c.seams.end());
  std::sort(c.flips.begin(), c.flips.end());
  return c;
}

}  // namespace

EdgeClasses classify_edges(const QuadMesh& m, const ClassifyOptions& options) { return classify(m, options, nullptr); }

std::vector<Triangle> cst_triangles(const EdgeClasses& c) {
  std::vector<Triangle> out;
  out.reserve(2 * c.frame.size());
  for (const QuadIndices& f : c.frame) {
    out.push_back({f[0], f[1], f[2]});
    out.push_back({f[2], f[3], f[0]});
  }
  return out;
}

std::vector<QuadIndices> quads_from_triangles(const std::vector<Triangle>& t) {
  if (t.size() % 2) throw ModelError(kWhat + ": an odd number of triangles (" + std::to_string(t.size()) + ") is not a set of quads");
  std::vector<QuadIndices> out;
  out.reserve(t.size() / 2);
  for (std::size_t k = 0; k < t.size(); k += 2) {
    const Triangle &a = t[k], &b = t[k + 1];
    if (a[2] != b[0] || a[0] != b[2])
      throw ModelError(kWhat + ": triangles " + std::to_string(k) + " and " + std::to_string(k + 1) +
                       " do not share their diagonal");
    out.push_back({a[0], a[1], a[2], b[1]});
  }
  return out;
}

std::vector<std::array<Index, 2>> bars_from_triangles(const std::vector<Triangle>& t) {
  std::vector<std::array<Index, 2>> out;
  std::set<std::pair<Index, Index>> seen;
  for (const Triangle& tri : t)
    for (int s = 0; s < 2; ++s) {
      const Index a = tri[s], b = tri[s + 1];
      if (seen.insert({std::min(a, b), std::max(a, b)}).second) out.push_back({a, b});
    }
  return out;
}

PatchTriangulation cst_triangulation(const Model& m, BlockId patch, const ClassifyOptions& options) {
  const PatchMesh pm = patch_mesh(m, patch, "triangulation");
  const EdgeClasses c = classify(pm.mesh, options, &pm.particles);
  PatchTriangulation out;
  for (const Triangle& t : cst_triangles(c))
    out.triangles.push_back({pm.particles[t[0]], pm.particles[t[1]], pm.particles[t[2]]});
  for (Index e : c.seams) out.seams.push_back({pm.particles[c.edges.ends[e][0]], pm.particles[c.edges.ends[e][1]]});
  for (Index e : c.flips) out.flips.push_back({pm.particles[c.edges.ends[e][0]], pm.particles[c.edges.ends[e][1]]});
  for (Yarn y : c.yarn) ++(y == Yarn::Warp ? out.warp_edges : out.weft_edges);
  return out;
}

}  // namespace tendril::meshing
