// Projective dynamics follows a topology change with a low-rank correction
// of its old factor (projective.hpp, low_rank_solve.hpp): the positions are
// those of a fresh factorisation of the same matrix after every change, and
// the factorisation count stays at one until the changed rows outgrow their
// budget.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "model/model.hpp"
#include "physics/projective.hpp"
#include "physics/solver.hpp"
#include "prestressed_net.hpp"

using namespace tendril;

namespace {

// bench_net's net, small: s x s particles 1 m apart, prestressed bars on the
// grid edges, the boundary locked, 1 N down on the interior; and five
// cables across cells, whose rest lengths the odd changes shorten.
struct Net {
  Model m;
  int s;
  std::vector<ParticleId> grid;
  explicit Net(int side) : s(side), grid(test::prestressed_net(m, side)) {
    for (int k = 1; k < 10; k += 2) m.add_cable(at(r(k), c(k) + 1), at(r(k) + 1, c(k)), Section{2e5, 0, 0, 0});
  }
  static int r(int k) { return 1 + 2 * (k % 5); }
  static int c(int k) { return 1 + 4 * (k / 5); }
  ParticleId at(int r, int c) const { return grid[std::size_t(r) * s + c]; }
};

// A new particle half a metre under the k-th place, on a cable, loaded
// with 20 N: the matrix grows by a row per axis.
void hang(Net& n, int k) {
  const ParticleId a = n.at(Net::r(k), Net::c(k));
  const ParticleId p = n.m.add_particle(n.m.particles.position[a] + Vec3(0, 0, -0.5));
  n.m.add_cable(a, p, Section{1e5, 0, 0, 0});
  n.m.set_load(p, Vec3(0, 0, -20));
}

// The k-th change, every one on particles no earlier one touched: even k a
// new cable across a cell (rule 6), odd k one of the net's cables across the
// other diagonal 2 % shorter.
void change(Net& n, int k) {
  const int r = Net::r(k), c = Net::c(k);
  if (k % 2 == 0) n.m.add_cable(n.at(r, c), n.at(r + 1, c + 1), Section{2e5, 0, 0, 0});
  else n.m.set_rest_length(n.at(r, c + 1), n.at(r + 1, c), 0.98 * std::sqrt(2.0));
}

struct Run {
  std::vector<Vec3> x;
  std::uint64_t factorizations, updates;
};

Run run(bool low_rank, int changes, int every, void (*rule)(Net&, int) = change) {
  Net n(12);
  Solver s(n.m);
  s.settings.integrator = Integrator::ProjectiveDynamics;
  s.set_projective_low_rank(low_rank);
  for (int k = 0; k < changes; ++k) {
    for (int i = 0; i < every; ++i) s.step();
    rule(n, k);
  }
  for (int i = 0; i < every; ++i) s.step();
  return {std::vector<Vec3>(n.m.particles.position.begin(), n.m.particles.position.end()), s.factorizations(),
          s.projective_updates()};
}

double largest_difference(const Run& a, const Run& b) {
  double d = 0, size = 0;
  for (std::size_t p = 0; p < std::min(a.x.size(), b.x.size()); ++p) {  // the particles both have
    d = std::max(d, (a.x[p] - b.x[p]).norm());
    size = std::max(size, a.x[p].norm());
  }
  return d / size;
}

// Particles leave and come back: a passive one, one locked in every axis,
// both integrated again two changes later.
void leave(Net& n, int k) {
  const ParticleId a = n.at(Net::r(0), Net::c(0)), b = n.at(Net::r(2), Net::c(2));
  if (k == 0) n.m.set_passive(a, true);
  if (k == 1) n.m.set_lock(b, kLockTranslation);
  if (k == 2) n.m.set_passive(a, false);
  if (k == 3) n.m.set_lock(b, 0);
}

// `changes` changes by `rule`, `every` steps apart, followed by the old
// factor and, the other way, each update factored afresh: one
// factorisation and an update per change both ways, the same positions,
// and the changes moved the net by more than `moved` (the comparison is
// not between two idle runs). The run with the correction.
Run followed_as_afresh(const char* what, int changes, int every, void (*rule)(Net&, int), double moved) {
  const Run cheap = run(true, changes, every, rule), fresh = run(false, changes, every, rule);
  CHECK(cheap.factorizations == 1);
  CHECK(cheap.updates == std::uint64_t(changes));
  CHECK(fresh.updates == std::uint64_t(changes));
  CHECK(fresh.factorizations == std::uint64_t(1 + changes));  // the first, and each update's afresh
  const double d = largest_difference(cheap, fresh);
  MESSAGE(what << ": largest position difference " << d << " of the net's size");
  CHECK(d < 1e-9);
  CHECK(largest_difference(cheap, run(true, 0, (changes + 1) * every)) > moved);
  return cheap;
}

}  // namespace

TEST_CASE("projective: a change every 4 steps is followed by the old factor, as a fresh factorisation would") {
  // 8 changes touch 16 rows, which are always followed (projective.cpp,
  // outgrown): every one without a factorisation.
  followed_as_afresh("8 changes", 8, 4, change, 1e-4);
}

TEST_CASE("projective: the ninth change outgrows the budget and refactors, in both ways alike") {
  // 18 rows: their columns of L^-1 P and C would read more than the net's
  // L and D, which a factorisation gives back.
  const Run cheap = run(true, 10, 3), fresh = run(false, 10, 3);
  CHECK(cheap.factorizations == 2);  // the first, and the ninth change's
  CHECK(cheap.updates == 9);
  CHECK(fresh.factorizations == 2 + 9);  // and each update's, factored afresh
  CHECK(fresh.updates == 9);
  CHECK(largest_difference(cheap, fresh) < 1e-9);
}

TEST_CASE("projective: a low-rank run is the same, bit for bit, run twice and with two threads") {
  const Run a = run(true, 6, 3);
  Net n(12);
  Solver s(n.m);
  s.settings.integrator = Integrator::ProjectiveDynamics;
  s.settings.threads = 2;
  for (int k = 0; k < 6; ++k) {
    for (int i = 0; i < 3; ++i) s.step();
    change(n, k);
  }
  for (int i = 0; i < 3; ++i) s.step();
  const Run b = run(true, 6, 3);
  for (std::size_t p = 0; p < a.x.size(); ++p) {
    CHECK(a.x[p] == b.x[p]);
    CHECK(a.x[p] == n.m.particles.position[p]);
  }
}

TEST_CASE("projective: new particles on cables join the correction, as a fresh factorisation would") {
  // Each adds a row and changes one (x, y and z share the rows): 5 x 2 rows.
  const Run cheap = followed_as_afresh("5 new particles", 5, 4, hang, 1e-4);  // the loads moved the net
  CHECK(cheap.x.size() == 144 + 5);
}

TEST_CASE("projective: particles made passive, locked and freed again are followed, as a fresh factorisation would") {
  followed_as_afresh("passive and locked particles", 4, 4, leave, 1e-6);  // the particles held still moved the net
}

TEST_CASE("projective: a row left stays decoupled: the followed system solves as one factored without it") {
  // The system alone: after each change, the old factor with its rows kept
  // and corrected against a system factored afresh for the changed model,
  // at the same positions and masses, solving the same right-hand side.
  Net n(12);
  const std::size_t had = n.m.particles.capacity();
  const std::vector<Vec3> x(n.m.particles.position.begin(), n.m.particles.position.end());
  const std::vector<double> mass(had + 1, 2.0), diagonal(had + 1, 0.0);
  const ProjectiveSystem::Key key{&n.m, 0.1, 0.1, 1, 1, 0};
  ProjectiveSystem followed;
  followed.factor(key, 1, n.m, x.data(), mass, 1.0, diagonal);
  const ParticleId a = n.at(3, 3), b = n.at(6, 7);
  const BlockId cable = n.m.add_cable(a, n.at(4, 4), Section{2e5, 0, 0, 0});
  auto compare = [&](std::uint64_t revision) {
    std::vector<Vec3> at(x);
    at.resize(n.m.particles.capacity(), Vec3(5, 5, -1));  // a new particle's place
    REQUIRE(followed.update(key, revision, n.m, at.data(), mass, false, 1.0, diagonal));
    ProjectiveSystem fresh;
    fresh.factor(key, revision, n.m, followed.reference().data(), followed.mass(), 1.0, diagonal);
    std::vector<Vec3> u(at.size()), v(at.size());
    for (std::size_t p = 0; p < u.size(); ++p) u[p] = v[p] = Vec3(std::sin(p + 1.0), std::cos(3.0 * p), 0.5);
    followed.solve(n.m, u.data());
    fresh.solve(n.m, v.data());
    double d = 0, size = 0;
    for (ParticleId p : n.m.particles.integrated.raw()) {
      d = std::max(d, (u[p] - v[p]).norm());
      size = std::max(size, v[p].norm());
    }
    CHECK(size > 1e-6);  // the stiff net moves little, but moves
    return d / size;
  };
  n.m.set_passive(a, true);  // its row and the cable's coupling leave
  CHECK(compare(2) < 1e-12);
  n.m.set_lock(b, kLockTranslation);
  CHECK(compare(3) < 1e-12);
  n.m.set_passive(a, false);  // back in its row
  CHECK(compare(4) < 1e-12);
  CHECK(followed.rows(0) == 100);  // the interior: no row added for it
  CHECK(followed.rows(2) == 100);
  n.m.delete_cable(cable);
  hang(n, 4);  // a new particle: a row after the others
  CHECK(n.m.particles.capacity() == had + 1);
  CHECK(compare(5) < 1e-12);
  CHECK(followed.rows(0) == 101);
  CHECK(followed.factorizations() == 1);
  CHECK(followed.updates() == 4);
}

TEST_CASE("projective: a matrix without couplings follows more than 16 changed rows, its columns being short") {
  // 1000 particles each hung from its own anchor: L has no entry below its
  // diagonal, a changed row's column of L^-1 P is the row alone, and the
  // correction reads k + k^2 entries against L's and D's 1000.
  Model m;
  std::vector<std::pair<ParticleId, ParticleId>> hung;
  for (int k = 0; k < 1000; ++k) {
    const ParticleId anchor = m.add_particle(Vec3(k, 0, 1)), p = m.add_particle(Vec3(k, 0, 0));
    m.set_lock(anchor, kLockTranslation);
    m.add_cable(anchor, p, Section{1e5, 0, 0, 0});
    hung.emplace_back(anchor, p);
  }
  const std::vector<Vec3> x(m.particles.position.begin(), m.particles.position.end());
  const std::vector<double> mass(x.size(), 2.0), diagonal(x.size(), 0.0);
  const ProjectiveSystem::Key key{&m, 0.1, 0.1, 1, 1, 0};
  ProjectiveSystem s;
  s.factor(key, 1, m, x.data(), mass, 1.0, diagonal);
  int followed = 0;
  for (int k = 0; k < 40; ++k) {
    m.set_rest_length(hung[std::size_t(k)].first, hung[std::size_t(k)].second, 0.9);  // its row's diagonal
    followed += s.update(key, 2 + std::uint64_t(k), m, x.data(), mass, false, 1.0, diagonal);
  }
  CHECK(followed == 31);  // k + k^2 <= 1000 up to 31 rows; the 32nd asks for a factorisation
  CHECK(s.factorizations() == 1);
}

TEST_CASE("projective: a deleted particle is followed; one added into its slot takes its row") {
  auto grow = [](bool low_rank) {
    Net n(12);
    Solver s(n.m);
    s.settings.integrator = Integrator::ProjectiveDynamics;
    s.set_projective_low_rank(low_rank);
    const ParticleId gone = n.m.add_particle(Vec3(1, 1, -0.5));
    const BlockId cable = n.m.add_cable(n.at(1, 1), gone, Section{1e5, 0, 0, 0});
    n.m.set_load(gone, Vec3(0, 0, -20));
    for (int i = 0; i < 4; ++i) s.step();
    n.m.delete_cable(cable);  // the particle goes with it; its rows stay, decoupled
    for (int i = 0; i < 4; ++i) s.step();
    hang(n, 3);  // into the freed slot, 6 m from where the deleted particle hung
    CHECK(n.m.particles.capacity() == gone + 1);
    for (int i = 0; i < 8; ++i) s.step();
    return Run{std::vector<Vec3>(n.m.particles.position.begin(), n.m.particles.position.end()), s.factorizations(),
               s.projective_updates()};
  };
  const Run cheap = grow(true), fresh = grow(false);
  CHECK(cheap.factorizations == 1);
  CHECK(cheap.updates == 2);  // the deletion, the particle in the slot
  CHECK(fresh.factorizations == 1 + 2);  // and each update's, factored afresh
  CHECK(fresh.updates == 2);
  CHECK(largest_difference(cheap, fresh) < 1e-9);
}
