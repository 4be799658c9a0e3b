// Rule 22 (meshing/tube.hpp): the catenoid-like tube between two patches'
// interiors. Two parallel grids, the centre particle of each: its quads are
// cut out, the rims (8 particles each) joined by a tube; states, counts,
// positions and map validity after it, the tube's waist after form-finding;
// refusals and a rolled-back transaction leave the model bit-identical.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>

#include "helpers.hpp"
#include "patch_mesh.hpp"
#include "paving.hpp"
#include "paving_shapes.hpp"
#include "physics/solver.hpp"
#include "tube.hpp"

using namespace tendril;
using namespace tendril::meshing;
using namespace tendril::meshing::test;

namespace {

// A (n x n)-particle unit grid at height z, centred on (c, c) with c = (n-1)/2.
std::vector<ParticleId> grid(Model& m, int n, double z) {
  std::vector<ParticleId> ps;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) ps.push_back(m.add_particle(Vec3(c, r, z)));
  m.add_quad_grid(ps, n, n, patch_section());
  return ps;
}

double radius(const Vec3& x, double centre) { return std::hypot(x.x() - centre, x.y() - centre); }

}  // namespace

TEST_CASE("rule 22: a tube between the centres of two parallel grids") {
  Model m;
  const int n = 7, rows = 3;
  const auto bottom = grid(m, n, 0), top = grid(m, n, 2);
  const ParticleId p1 = bottom[3 * n + 3], p2 = top[3 * n + 3];
  const BlockId patch_a = m.blocks_of(p1)[0], patch_b = m.blocks_of(p2)[0];
  // A tube much softer (EA 20 N) than the grids (1000 N), both prestressed
  // with 5 N, so that the tube's prestress shapes it.
  const TubeBetweenPatches t = tube_between_patches(m, p1, p2, rows, Section{20, 0, 5, 0});
  CHECK(m.check() == "");
  // p's four quads went, p with them; the rims are p's 8 grid neighbours.
  CHECK(t.cut_a == std::vector<ParticleId>{p1});
  CHECK(t.cut_b == std::vector<ParticleId>{p2});
  CHECK(t.removed == std::vector<ParticleId>{p1, p2});
  // (their slots are reused by the tube's new particles)
  CHECK(m.particle_count() == std::size_t(2 * n * n - 2 + 8 * rows));
  CHECK(patch_mesh(m, patch_a).particles.size() == std::size_t(n * n - 1));
  REQUIRE(t.rim_a.size() == 8);
  REQUIRE(t.rim_b.size() == 8);
  CHECK(patch_mesh(m, patch_a).mesh.quads.size() == 36 - 4);
  CHECK(patch_mesh(m, patch_b).mesh.quads.size() == 36 - 4);
  const PatchMesh tube = patch_mesh(m, t.tube.patch);
  CHECK(tube.mesh.quads.size() == std::size_t(8 * (rows + 1)));
  CHECK(tube.particles.size() == std::size_t(8 * (rows + 2)));
  CHECK(t.tube.created.size() == std::size_t(8 * rows));
  for (std::size_t i = 0; i < 8; ++i) {
    const Vec3 a = m.particles.position[t.rim_a[i]], b = m.particles.position[t.rim_b[i]];
    // The rims are the neighbours, unmoved, and shared by patch and tube.
    CHECK(radius(a, 3) <= std::sqrt(2.0) + 1e-12);
    CHECK(radius(a, 3) >= 1 - 1e-12);
    CHECK(a.z() == 0);
    CHECK(m.state(t.rim_a[i]) == State::Shared);
    CHECK(m.state(t.rim_b[i]) == State::Shared);
    CHECK(m.blocks_of(t.rim_a[i]) == std::vector<BlockId>{patch_a, t.tube.patch});
    // Facing without twist: each rung is vertical.
    CHECK(b.x() == a.x());
    CHECK(b.y() == a.y());
    CHECK(b.z() == 2);
    // Rule 21's rows: evenly on the straight rungs.
    for (int k = 1; k <= rows; ++k) {
      const ParticleId q = t.tube.created[std::size_t(k - 1) * 8 + i];
      CHECK(m.state(q) == State::Simple);
      CHECK((m.particles.position[q] - (a + (b - a) * (double(k) / (rows + 1)))).norm() < 1e-12);
    }
  }

  // Form-finding with the grids' borders held: the prestressed tube necks
  // like a catenoid, symmetric about the mid-plane z = 1.
  for (std::size_t i = 0; i < bottom.size(); ++i) {
    const int r = int(i) / n, c = int(i) % n;
    if (r == 0 || c == 0 || r == n - 1 || c == n - 1) m.set_lock(bottom[i], kLockTranslation), m.set_lock(top[i], kLockTranslation);
  }
  Solver solver(m);
  const RunResult run = solver.run(1e-6, 200000);
  REQUIRE(run.converged);
  CHECK(m.check() == "");
  double rim = 0, waist = 0, mid_z = 0, rim_z = 0, gap = 0, waist_spread = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    rim += radius(m.particles.position[t.rim_a[i]], 3) / 8;
    rim_z += (m.particles.position[t.rim_a[i]].z() + m.particles.position[t.rim_b[i]].z() - 2) / 8;
    gap += (m.particles.position[t.rim_b[i]].z() - m.particles.position[t.rim_a[i]].z()) / 8;
    const Vec3 w = m.particles.position[t.tube.created[8 + i]];  // row 2 of 3: the middle
    waist += radius(w, 3) / 8;
    mid_z = std::max(mid_z, std::abs(w.z() - 1));
  }
  for (std::size_t i = 0; i < 8; ++i)
    waist_spread = std::max(waist_spread, std::abs(radius(m.particles.position[t.tube.created[8 + i]], 3) - waist));
  MESSAGE("rim radius " << rim << ", waist radius " << waist << ", mid-plane offset " << mid_z
                        << ", rims " << gap << " m apart");
  CHECK(mid_z < 1e-6);                 // symmetric about the mid-plane
  CHECK(std::abs(rim_z) < 1e-6);       // the two rims move symmetrically
  CHECK(gap < 2);                      // towards each other
  CHECK(waist < 0.85 * rim);           // necks (0.79 measured)
  CHECK(waist > 0.6 * rim);            // but does not collapse
  CHECK(waist_spread < 0.25 * waist);  // and stays round (a square grid's rim is an octagon)
}

TEST_CASE("rule 22 with two rings of neighbourhood cuts a diamond: 12 quads, 5 particles, a 16-particle rim") {
  Model m;
  const int n = 9;
  const auto bottom = grid(m, n, 0), top = grid(m, n, 3);
  const TubeBetweenPatches t = tube_between_patches(m, bottom[4 * n + 4], top[4 * n + 4], 2, patch_section(), 2);
  CHECK(m.check() == "");
  CHECK(t.rim_a.size() == 16);
  CHECK(t.cut_a.size() == 5);  // the centre and its 4 edge neighbours
  CHECK(t.cut_b.size() == 5);
  CHECK(t.removed.size() == 10);
  CHECK(patch_mesh(m, m.blocks_of(bottom[0])[0]).mesh.quads.size() == 64 - 12);
  CHECK(patch_mesh(m, t.tube.patch).mesh.quads.size() == 16 * 3);
}

TEST_CASE("rule 22 refuses particles it cannot use, leaving the model bit-identical") {
  Model m;
  const int n = 7, nt = 9;
  const auto bottom = grid(m, n, 0), top = grid(m, nt, 2);
  // A paved circle: its irregular vertices have rims of 6 or 10 particles.
  std::vector<ParticleId> ring;
  for (const Vec3& x : circle_loop(32, 5)) ring.push_back(m.add_particle(x + Vec3(20, 0, 0)));
  const CommittedPatch disc = patch_by_paving(m, ring, patch_section());
  ParticleId odd = kNone;
  for (ParticleId q : disc.created) {
    std::size_t valence = 0;
    bool deep = true;  // none of its quads touches the ring
    for (const auto& quad : disc.quads)
      if (std::count(quad.begin(), quad.end(), q)) {
        ++valence;
        for (ParticleId c : quad) deep = deep && std::find(ring.begin(), ring.end(), c) == ring.end();
      }
    if (deep && valence != 4 && odd == kNone) odd = q;
  }
  REQUIRE(odd != kNone);
  const ParticleId shared = top[4 * nt + 4];
  const ParticleId beam_end = m.add_particle(Vec3(4, 4, 5));
  m.add_beam({shared, beam_end}, beam_section());  // the top centre becomes shared
  const Fingerprint before(m);
  auto refused = [&](ParticleId a, ParticleId b, const char* message, int rings = 1, int rows = 1) {
    CAPTURE(message);
    CHECK_THROWS_WITH_AS(tube_between_patches(m, a, b, rows, patch_section(), rings), doctest::Contains(message),
                         ModelError);
    CHECK(Fingerprint(m) == before);
  };
  const ParticleId centre = bottom[3 * n + 3], near_shared = top[4 * nt + 3];
  refused(centre, shared, "is shared; rule 22 needs a simple particle inside a patch");
  refused(centre, bottom[0], "is on the boundary of patch");
  refused(centre, near_shared, "is shared; the neighbourhood to cut must be simple particles", 2);
  refused(centre, bottom[3 * n + 4], "overlap");
  refused(centre, near_shared, "reaches the boundary", 3);
  refused(centre, odd, "are not equivalent: their rims have 8 and");
  refused(centre, centre, "both particles are");
  refused(centre, near_shared, "rings must be between 1 and 8", 0);
  refused(centre, near_shared, "rows must be between", 1, -1);
  refused(centre, beam_end, "rule 22 needs a simple particle inside a patch");
}

TEST_CASE("rule 22 inside a transaction: rollback restores the cut patches exactly") {
  Model m;
  const auto bottom = grid(m, 7, 0), top = grid(m, 7, 2);
  const Fingerprint before(m);
  m.begin_transaction();
  const TubeBetweenPatches t = tube_between_patches(m, bottom[24], top[24], 2, patch_section());
  CHECK(m.check() == "");
  CHECK(m.block_count(BlockKind::Patch) == 3);
  m.rollback_transaction();
  CHECK(m.check() == "");
  CHECK(Fingerprint(m) == before);
}
