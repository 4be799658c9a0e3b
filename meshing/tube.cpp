#include "tube.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "edge_table.hpp"
#include "patch_mesh.hpp"
#include "projection.hpp"

namespace tendril::meshing {
namespace {

const std::string kWhat = "tube";

std::string pid(ParticleId p) { return std::to_string(p); }

// A neighbourhood to cut out of a patch, read from the model without changing it.
struct Hole {
  std::vector<ParticleId> centres;  // removed one by one with rule 23
  std::vector<ParticleId> cut;      // every particle that goes (centres included)
  std::vector<ParticleId> rim;      // the hole's boundary, in order round it
};

Hole plan_hole(const Model& m, ParticleId p, int rings) {
  m.require_particle(p, kWhat.c_str());
  const State st = m.state(p);
  const std::vector<BlockId> bs = m.blocks_of(p);
  if (st != State::Simple || bs.size() != 1 || m.blocks[bs[0]].kind != BlockKind::Patch)
    throw ModelError(kWhat + ": particle " + pid(p) + " is " + std::string(state_name(st)) +
                     "; rule 22 needs a simple particle inside a patch");
  const BlockId patch = bs[0];
  if (m.is_cst_patch(patch))
    throw ModelError(kWhat + ": patch " + std::to_string(patch) + " is in CST mode; switch it back to bars first");
  const PatchMesh pm = patch_mesh(m, patch, kWhat.c_str());
  const std::size_t nv = pm.particles.size();
  auto vertex = [&](ParticleId q) {
    return Index(std::lower_bound(pm.particles.begin(), pm.particles.end(), q) - pm.particles.begin());
  };
  const EdgeTable t = edge_table(to_polygons(pm.mesh).faces, nv, kWhat);
  const std::vector<bool> on_boundary = boundary_vertices(t, nv);
  // The centres: particles within rings - 1 edges of p.
  std::vector<std::vector<Index>> neighbours(nv);
  for (const auto& e : t.ends) neighbours[e[0]].push_back(e[1]), neighbours[e[1]].push_back(e[0]);
  std::vector<int> distance(nv, -1);
  std::vector<Index> centres{vertex(p)};
  distance[centres[0]] = 0;
  for (std::size_t k = 0; k < centres.size(); ++k) {
    const Index v = centres[k];
    if (distance[v] + 1 >= rings) continue;
    for (Index u : neighbours[v])
      if (distance[u] < 0) distance[u] = distance[v] + 1, centres.push_back(u);
  }
  Hole hole;
  for (Index v : centres) {
    const ParticleId q = pm.particles[v];
    if (on_boundary[v])
      throw ModelError(kWhat + ": particle " + pid(q) + (q == p ? "" : " (near particle " + pid(p) + ")") +
                       " is on the boundary of patch " + std::to_string(patch) + ", not inside it");
    if (m.state(q) != State::Simple)
      throw ModelError(kWhat + ": particle " + pid(q) + " near particle " + pid(p) + " is " +
                       std::string(state_name(m.state(q))) + "; the neighbourhood to cut must be simple particles");
    hole.centres.push_back(q);
  }
  // The neighbourhood: every quad touching a centre.
  std::vector<bool> in(pm.mesh.quads.size(), false);
  for (std::size_t f = 0; f < in.size(); ++f)
    for (Index v : pm.mesh.quads[f]) in[f] = in[f] || distance[v] >= 0;
  // Its rim: edges with the neighbourhood on one side and the patch on the other.
  std::map<Index, std::vector<Index>> rim_next;
  std::vector<bool> on_rim(nv, false), touched(nv, false);
  for (std::size_t f = 0; f < in.size(); ++f)
    if (in[f])
      for (Index v : pm.mesh.quads[f]) touched[v] = true;
  for (Index e = 0; e < t.ends.size(); ++e) {
    const bool a = in[t.faces[e][0]], b = t.boundary(e) ? false : bool(in[t.faces[e][1]]);
    if (a == b) continue;
    if (t.boundary(e))
      throw ModelError(kWhat + ": the neighbourhood of particle " + pid(p) + " reaches the boundary of patch " +
                       std::to_string(patch) + " (take fewer rings)");
    const Index u = t.ends[e][0], w = t.ends[e][1];
    rim_next[u].push_back(w), rim_next[w].push_back(u);
    on_rim[u] = on_rim[w] = true;
  }
  for (Index v = 0; v < nv; ++v) {
    if (!touched[v] || on_rim[v]) continue;
    const ParticleId q = pm.particles[v];
    if (m.state(q) != State::Simple)
      throw ModelError(kWhat + ": particle " + pid(q) + " inside the neighbourhood of particle " + pid(p) + " is " +
                       std::string(state_name(m.state(q))) + " and would be cut off");
    hole.cut.push_back(q);
  }
  // One closed loop through every rim particle, each with two rim neighbours.
  for (const auto& [v, next] : rim_next)
    if (next.size() != 2)
      throw ModelError(kWhat + ": the neighbourhood of particle " + pid(p) + " is not a disc (its rim touches itself at particle " +
                       pid(pm.particles[v]) + ")");
  Index start = rim_next.begin()->first, previous = start, v = rim_next.at(start)[0];
  hole.rim.push_back(pm.particles[start]);
  while (v != start) {
    hole.rim.push_back(pm.particles[v]);
    const auto& next = rim_next.at(v);
    const Index after = next[0] == previous ? next[1] : next[0];
    previous = v, v = after;
  }
  if (hole.rim.size() != rim_next.size())
    throw ModelError(kWhat + ": the neighbourhood of particle " + pid(p) + " is not a disc (its rim is several loops)");
  return hole;
}

// Orders b to face a: the direction and starting particle with the least sum
// of squared distances between a[i] and b[i] (first minimum, deterministic).
std::vector<ParticleId> facing(const Model& m, const std::vector<ParticleId>& a, const std::vector<ParticleId>& b) {
  const std::size_t n = a.size();
  double best = std::numeric_limits<double>::infinity();
  std::vector<ParticleId> out;
  for (int dir : {1, -1})
    for (std::size_t s = 0; s < n; ++s) {
      std::vector<ParticleId> c(n);
      double sum = 0;
      for (std::size_t i = 0; i < n; ++i) {
        c[i] = b[(s + n + std::size_t(dir) * i) % n];
        sum += (m.particles.position[a[i]] - m.particles.position[c[i]]).squaredNorm();
      }
      if (sum < best) best = sum, out = c;
    }
  return out;
}

// Rule 23 on each centre still on the patch (a centre whose quads all went
// with its neighbours' was released with them).
void cut(Model& m, const Hole& hole, std::vector<ParticleId>& removed) {
  for (ParticleId q : hole.centres)
    if (m.particles.valid(q) && m.particles.degree[q] > 0) {
      m.remove_from_patch(q);
      removed.push_back(q);
    }
}

}  // namespace

TubeBetweenPatches tube_between_patches(Model& m, ParticleId p1, ParticleId p2, int rows, const Section& s, int rings) {
  if (rings < 1 || rings > kMaxTubeRings)
    throw ModelError(kWhat + ": rings must be between 1 and " + std::to_string(kMaxTubeRings) + ", got " + std::to_string(rings));
  if (rows < 0 || rows > kMaxProjectionRows)
    throw ModelError(kWhat + ": rows must be between 0 and " + std::to_string(kMaxProjectionRows) + ", got " +
                     std::to_string(rows));
  if (p1 == p2) throw ModelError(kWhat + ": both particles are " + pid(p1));
  validate_section(s, kWhat);
  const Model& cm = m;
  const Hole a = plan_hole(cm, p1, rings), b = plan_hole(cm, p2, rings);
  std::set<ParticleId> first(a.rim.begin(), a.rim.end());
  first.insert(a.cut.begin(), a.cut.end());
  for (const auto* list : {&b.rim, &b.cut})
    for (ParticleId q : *list)
      if (first.count(q))
        throw ModelError(kWhat + ": the neighbourhoods of particles " + pid(p1) + " and " + pid(p2) +
                         " overlap (both hold particle " + pid(q) + ")");
  if (a.rim.size() != b.rim.size())
    throw ModelError(kWhat + ": the neighbourhoods of particles " + pid(p1) + " and " + pid(p2) +
                     " are not equivalent: their rims have " + std::to_string(a.rim.size()) + " and " +
                     std::to_string(b.rim.size()) + " particles");
  TubeBetweenPatches out;
  out.rim_a = a.rim;
  out.rim_b = facing(cm, a.rim, b.rim);
  out.cut_a = a.cut, out.cut_b = b.cut;
  std::vector<Vec3> pa, pb;
  for (ParticleId q : out.rim_a) pa.push_back(cm.particles.position[q]);
  for (ParticleId q : out.rim_b) pb.push_back(cm.particles.position[q]);
  PlannedPatch plan{projection(pa, pb, rows, true), out.rim_a};
  plan.existing.insert(plan.existing.end(), out.rim_b.begin(), out.rim_b.end());

  const bool own = !m.in_transaction();
  if (own) m.begin_transaction();
  try {
    cut(m, a, out.removed);
    cut(m, b, out.removed);
    out.tube = commit_patch(m, plan, s, kWhat);
  } catch (...) {
    if (own) m.rollback_transaction();
    throw;
  }
  if (own) m.commit_transaction();
  return out;
}

}  // namespace tendril::meshing
