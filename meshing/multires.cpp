#include "multires.hpp"

#include <map>
#include <string>
#include <utility>

#include "commit_patch.hpp"
#include "patch_mesh.hpp"

namespace tendril::meshing {

namespace {

std::string pid(ParticleId p) { return std::to_string(p); }

// The fine particles must still be the ones the patch made (a deleted and
// recycled slot would alias another particle) and the fine patch alive.
void require_parts(const Model& m, const MultiresPatch& mr, const std::string& what) {
  if (!m.block_valid(mr.fine) || m.blocks[mr.fine].generation != mr.fine_generation)
    throw ModelError(what + ": the fine patch " + std::to_string(mr.fine) + " was deleted");
  for (std::size_t k = 0; k < mr.particles.size(); ++k) {
    const ParticleId p = mr.particles[k];
    if (!m.particle_valid(p) || m.particles.generation[p] != mr.generations[k])
      throw ModelError(what + ": fine particle " + pid(p) + " was deleted");
    for (ParticleId c : mr.corners[k])
      if (!m.particle_valid(c)) throw ModelError(what + ": coarse particle " + pid(c) + " was deleted");
  }
}

}  // namespace

MultiresPatch multires_patch(Model& m, BlockId coarse, int factor, const Section* fine) {
  const std::string what = "multires";
  const PatchMesh pm = patch_mesh(m, coarse, what.c_str());
  if (m.is_cst_patch(coarse))
    throw ModelError(what + ": patch " + std::to_string(coarse) + " is in CST mode; switch it to bars first");
  if (factor < 2 || factor > kMaxMultiresFactor)
    throw ModelError(what + ": factor must be an integer from 2 to " + std::to_string(kMaxMultiresFactor) + ", got " +
                     std::to_string(factor));
  const Model& cm = m;
  for (ParticleId p : pm.particles)
    if (cm.particles.passive[p]) throw ModelError(what + ": particle " + pid(p) + " of the coarse patch is passive");
  const Section coarse_section = cm.blocks[coarse].section;
  Section fine_section = coarse_section;
  if (fine) {
    fine_section = *fine;
  } else {
    fine_section.EA /= factor;
    fine_section.prestress /= factor;
    fine_section.line_mass /= factor;
  }
  validate_section(fine_section, what);

  // The fine mesh: coarse vertices keep their indices; then the factor - 1
  // points of every coarse edge (from its lower to its higher vertex), then
  // the (factor - 1)^2 interior points of every coarse quad. Each new vertex
  // remembers its four coarse corners and bilinear weights.
  const int k = factor;
  PlannedPatch plan;
  plan.existing = pm.particles;
  plan.mesh.positions = pm.mesh.positions;
  std::vector<std::array<Index, 4>> corner_of;   // per new vertex, mesh indices
  std::vector<std::array<double, 4>> weight_of;
  auto add_vertex = [&](const std::array<Index, 4>& c, const std::array<double, 4>& w) {
    Vec3 x = Vec3::Zero();
    for (int a = 0; a < 4; ++a) x += w[a] * pm.mesh.positions[c[a]];
    plan.mesh.positions.push_back(x);
    corner_of.push_back(c);
    weight_of.push_back(w);
    return Index(plan.mesh.positions.size() - 1);
  };
  std::map<std::pair<Index, Index>, Index> edge_first;  // first new vertex of each coarse edge
  auto edge_point = [&](Index a, Index b, int t) {     // t in 1..k-1 from a towards b
    const Index lo = std::min(a, b), hi = std::max(a, b);
    auto [it, added] = edge_first.try_emplace({lo, hi}, 0);
    if (added) {
      for (int s = 1; s < k; ++s) {
        const double u = double(s) / k;
        const Index v = add_vertex({lo, hi, lo, hi}, {1 - u, u, 0, 0});
        if (s == 1) it->second = v;
      }
    }
    return it->second + Index(a == lo ? t - 1 : k - 1 - t);
  };
  std::vector<Index> grid(std::size_t(k + 1) * (k + 1));
  auto at = [&](int i, int j) -> Index& { return grid[std::size_t(i) * (k + 1) + j]; };
  for (const QuadIndices& q : pm.mesh.quads) {
    const Index v0 = q[0], v1 = q[1], v2 = q[2], v3 = q[3];
    at(0, 0) = v0, at(0, k) = v1, at(k, k) = v2, at(k, 0) = v3;
    for (int t = 1; t < k; ++t) {
      at(0, t) = edge_point(v0, v1, t);
      at(t, k) = edge_point(v1, v2, t);
      at(k, t) = edge_point(v3, v2, t);
      at(t, 0) = edge_point(v0, v3, t);
    }
    for (int i = 1; i < k; ++i)
      for (int j = 1; j < k; ++j) {
        const double s = double(j) / k, t = double(i) / k;
        at(i, j) = add_vertex({v0, v1, v2, v3}, {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t});
      }
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) plan.mesh.quads.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
  }

  const CommittedPatch c = commit_patch(m, plan, fine_section, what);  // validates, then changes
  MultiresPatch mr;
  mr.coarse = coarse;
  mr.fine = c.patch;
  mr.fine_generation = cm.blocks[c.patch].generation;
  mr.factor = factor;
  mr.coarse_section = coarse_section;
  mr.fine_section = fine_section;
  mr.fine_quads = c.quads;
  for (const QuadIndices& q : pm.mesh.quads)
    mr.coarse_quads.push_back({pm.particles[q[0]], pm.particles[q[1]], pm.particles[q[2]], pm.particles[q[3]]});
  mr.coarse_generation = cm.blocks[coarse].generation;
  mr.particles = c.created;
  for (std::size_t v = 0; v < c.created.size(); ++v) {
    const ParticleId p = c.created[v];
    mr.generations.push_back(cm.particles.generation[p]);
    std::array<ParticleId, 4> corners;
    for (int a = 0; a < 4; ++a) corners[a] = pm.particles[corner_of[v][a]];
    mr.corners.push_back(corners);
    mr.weights.push_back(weight_of[v]);
    // On a coarse edge between two locked particles: the locks they share.
    if (weight_of[v][2] == 0 && weight_of[v][3] == 0) {
      const std::uint8_t bits = cm.particles.lock[corners[0]] & cm.particles.lock[corners[1]] & kLockTranslation;
      if (bits) m.set_lock(p, bits);
    }
    m.set_passive(p, true);
  }
  return mr;
}

void multires_refine(Model& m, MultiresPatch& mr) {
  const std::string what = "refine";
  if (!mr.coarse_mode()) throw ModelError(what + ": the patch is already fine");
  require_parts(m, mr, what);
  if (!m.block_valid(mr.coarse) || m.blocks[mr.coarse].generation != mr.coarse_generation)
    throw ModelError(what + ": the coarse links (block " + std::to_string(mr.coarse) + ") were deleted");
  // Fig. 5.31b: every fine particle onto the coarse surface as it is now.
  const Model& cm = m;
  for (std::size_t k = 0; k < mr.particles.size(); ++k) {
    Vec3 x = Vec3::Zero();
    for (int a = 0; a < 4; ++a) x += mr.weights[k][a] * cm.particles.position[mr.corners[k][a]];
    m.particles.position[mr.particles[k]] = x;
  }
  for (ParticleId p : mr.particles) m.set_passive(p, false);
  m.delete_patch(mr.coarse);  // the temporary links; every coarse particle stays on the fine patch
  mr.coarse = kNone;
}

void multires_coarsen(Model& m, MultiresPatch& mr) {
  const std::string what = "coarsen";
  if (mr.coarse_mode()) throw ModelError(what + ": the patch is already coarse");
  require_parts(m, mr, what);
  mr.coarse = m.add_patch(mr.coarse_quads, mr.coarse_section);  // validates the links first
  mr.coarse_generation = std::as_const(m).blocks[mr.coarse].generation;
  for (ParticleId p : mr.particles) m.set_passive(p, true);
}

}  // namespace tendril::meshing
