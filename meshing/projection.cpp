#include "projection.hpp"

#include <unordered_set>
#include <utility>

namespace tendril::meshing {
namespace {

const std::string kWhat = "projection";

std::string side(bool first, std::size_t i) { return std::string(first ? "A[" : "B[") + std::to_string(i) + "]"; }

void check_sizes(std::size_t na, std::size_t nb, bool closed) {
  if (na != nb)
    throw ModelError(kWhat + ": the sequences differ in length (" + std::to_string(na) + " and " + std::to_string(nb) + ")");
  const std::size_t least = closed ? 3 : 2;
  if (na < least)
    throw ModelError(kWhat + ": each sequence needs at least " + std::to_string(least) + " particles" +
                     (closed ? " when closed" : "") + ", got " + std::to_string(na));
}

}  // namespace

QuadMesh projection(const std::vector<Vec3>& a, const std::vector<Vec3>& b, int rows, bool closed) {
  check_sizes(a.size(), b.size(), closed);
  if (rows < 0 || rows > kMaxProjectionRows)
    throw ModelError(kWhat + ": rows must be between 0 and " + std::to_string(kMaxProjectionRows) + ", got " +
                     std::to_string(rows));
  const std::size_t n = a.size();
  for (int s = 0; s < 2; ++s) {
    const auto& seq = s == 0 ? a : b;
    for (std::size_t i = 0; i < n; ++i) {
      if (!seq[i].allFinite()) throw ModelError(kWhat + ": " + side(s == 0, i) + " is not finite");
      if ((i + 1 < n || closed) && seq[i] == seq[(i + 1) % n])
        throw ModelError(kWhat + ": consecutive points " + side(s == 0, i) + " and " + side(s == 0, (i + 1) % n) +
                         " coincide");
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (a[i] == b[i]) throw ModelError(kWhat + ": " + side(true, i) + " and " + side(false, i) + " coincide");

  QuadMesh m;
  m.positions = a;
  m.positions.insert(m.positions.end(), b.begin(), b.end());
  for (int k = 1; k <= rows; ++k) {
    const double t = double(k) / double(rows + 1);
    for (std::size_t i = 0; i < n; ++i) m.positions.push_back(a[i] + t * (b[i] - a[i]));
  }
  auto at = [&](int k, std::size_t i) -> Index {
    if (k == 0) return Index(i);
    if (k == rows + 1) return Index(n + i);
    return Index(2 * n + (k - 1) * n + i);
  };
  const std::size_t columns = closed ? n : n - 1;
  for (int k = 0; k <= rows; ++k)
    for (std::size_t i = 0; i < columns; ++i) {
      const std::size_t j = (i + 1) % n;
      m.quads.push_back({at(k, i), at(k, j), at(k + 1, j), at(k + 1, i)});
    }
  return m;
}

CommittedPatch patch_by_projection(Model& m, const std::vector<ParticleId>& a, const std::vector<ParticleId>& b,
                                   int rows, const Section& s, bool closed) {
  check_sizes(a.size(), b.size(), closed);
  std::unordered_set<ParticleId> seen;
  std::vector<Vec3> pa, pb;
  for (int k = 0; k < 2; ++k) {
    const auto& seq = k == 0 ? a : b;
    for (std::size_t i = 0; i < seq.size(); ++i) {
      m.require_particle(seq[i], kWhat.c_str());
      if (!seen.insert(seq[i]).second)
        throw ModelError(kWhat + ": particle " + std::to_string(seq[i]) + " (" + side(k == 0, i) +
                         ") appears twice in A and B");
      (k == 0 ? pa : pb).push_back(std::as_const(m).particles.position[seq[i]]);
    }
  }
  validate_section(s, kWhat);
  PlannedPatch plan{projection(pa, pb, rows, closed), a};
  plan.existing.insert(plan.existing.end(), b.begin(), b.end());
  return commit_patch(m, plan, s, kWhat);
}

}  // namespace tendril::meshing
