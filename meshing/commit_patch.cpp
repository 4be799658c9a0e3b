#include "commit_patch.hpp"

#include <cmath>
#include <unordered_set>
#include <utility>

#include "edge_table.hpp"

namespace tendril::meshing {

void validate_section(const Section& s, const std::string& what) {
  auto finite_nonneg = [&](double x, const char* key) {
    if (!(x >= 0) || !std::isfinite(x)) throw ModelError(what + ": " + key + " must be a finite number >= 0");
  };
  finite_nonneg(s.EA, "EA");
  finite_nonneg(s.EI, "EI");
  if (!std::isfinite(s.prestress)) throw ModelError(what + ": prestress must be a finite number >= 0");
  finite_nonneg(s.line_mass, "line_mass");
  if (s.EA <= 0) throw ModelError(what + ": EA must be > 0");
}

void validate_patch(const Model& m, const PlannedPatch& plan, const Section& s, const std::string& what) {
  const QuadMesh& mesh = plan.mesh;
  if (mesh.quads.empty()) throw ModelError(what + ": the patch would have no quads");
  if (plan.existing.size() > mesh.positions.size())
    throw ModelError(what + ": more existing particles than mesh vertices");
  validate_section(s, what);
  std::unordered_set<ParticleId> seen;
  for (ParticleId p : plan.existing) {
    m.require_particle(p, what.c_str());
    if (!seen.insert(p).second) throw ModelError(what + ": particle " + std::to_string(p) + " is used twice");
  }
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    if (!mesh.positions[i].allFinite()) throw ModelError(what + ": vertex " + std::to_string(i) + " is not finite");
  const EdgeTable t = edge_table(to_polygons(mesh).faces, mesh.positions.size(), what);
  for (const auto& e : t.ends)
    if (mesh.positions[e[0]] == mesh.positions[e[1]])
      throw ModelError(what + ": the edge between vertices " + std::to_string(e[0]) + " and " + std::to_string(e[1]) +
                       " has zero length");
  // One piece: union of quads across interior edges.
  std::vector<std::size_t> parent(mesh.quads.size());
  for (std::size_t q = 0; q < parent.size(); ++q) parent[q] = q;
  auto root = [&](std::size_t q) {
    while (parent[q] != q) q = parent[q] = parent[parent[q]];
    return q;
  };
  std::size_t groups = parent.size();
  for (const auto& f : t.faces)
    if (f[1] != kNoFace) {
      std::size_t a = root(f[0]), b = root(f[1]);
      if (a != b) parent[a] = b, --groups;
    }
  if (groups != 1) throw ModelError(what + ": the quads form " + std::to_string(groups) + " separate pieces");
  // Vertices used by no quad would become isolated particles.
  std::vector<bool> used(mesh.positions.size(), false);
  for (const QuadIndices& q : mesh.quads)
    for (Index v : q) used[v] = true;
  for (std::size_t i = plan.existing.size(); i < used.size(); ++i)
    if (!used[i]) throw ModelError(what + ": new vertex " + std::to_string(i) + " is in no quad");
}

CommittedPatch commit_patch(Model& m, const PlannedPatch& plan, const Section& s, const std::string& what) {
  validate_patch(m, plan, s, what);
  const QuadMesh& mesh = plan.mesh;
  CommittedPatch out;
  out.particles = plan.existing;
  std::vector<std::pair<ParticleId, Vec3>> moved;  // to undo
  for (std::size_t i = 0; i < plan.existing.size(); ++i) {
    const ParticleId p = plan.existing[i];
    const Vec3 now = std::as_const(m).particles.position[p];  // a const read is not logged
    if (now != mesh.positions[i]) {
      moved.emplace_back(p, now);
      m.particles.position[p] = mesh.positions[i];
    }
  }
  try {
    for (std::size_t i = plan.existing.size(); i < mesh.positions.size(); ++i) {
      out.created.push_back(m.add_particle(mesh.positions[i]));
      out.particles.push_back(out.created.back());
    }
    std::vector<Model::Quad> quads;
    quads.reserve(mesh.quads.size());
    for (const QuadIndices& q : mesh.quads)
      quads.push_back({out.particles[q[0]], out.particles[q[1]], out.particles[q[2]], out.particles[q[3]]});
    out.patch = m.add_patch(quads, s);
    out.quads = std::move(quads);
  } catch (...) {
    // Reverse order restores the free-slot stack as it was.
    for (auto it = out.created.rbegin(); it != out.created.rend(); ++it) m.delete_particle(*it);
    for (const auto& [p, x] : moved) m.particles.position[p] = x;
    throw;
  }
  for (const auto& [p, x] : moved) out.moved.push_back(p);
  return out;
}

}  // namespace tendril::meshing
