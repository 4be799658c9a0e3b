// Switching a patch between elastic bars and CST (thesis 5.5.2.2) while the
// solver runs: local, exact under rollback, checked against the map, and
// consistent with (or refused by) the patch's topology operations.
#include <doctest/doctest.h>

#include <random>
#include <sstream>

#include "../physics/cst_scenes.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using namespace tendril::test;

namespace {

Membrane form(double warp, double weft) {
  Membrane m;
  m.mode = Membrane::FormFinding;
  m.sigma_warp = warp;
  m.sigma_weft = weft;
  return m;
}

// Everything a switch may touch, as text with exact numbers.
std::string fingerprint(const Model& m) {
  std::ostringstream o;
  o.precision(17);
  for (const Bar& b : m.bars.items) o << "bar " << b.i << ' ' << b.j << ' ' << b.rest_length << ' ' << b.dart << '\n';
  for (const Cst& c : m.csts.items)
    o << "cst " << c.i << ' ' << c.j << ' ' << c.k << ' ' << int(c.membrane.mode) << ' ' << c.membrane.sigma_warp << ' '
      << c.ref.l1 << ' ' << c.ref.h << ' ' << c.ref.c << ' ' << c.dart << '\n';
  for (BlockId b = 0; b < m.blocks.size(); ++b)
    o << "block " << b << ' ' << int(m.blocks[b].membrane.mode) << ' ' << m.blocks[b].membrane.sigma_weft << '\n';
  for (Dart d = 0; d < m.map.capacity(); ++d)
    o << int(m.cst_first[d]) << ' ' << m.cst_reference[d].h << ' ' << m.dart_cst[d] << ' ' << m.dart_bar[d] << '\n';
  for (ParticleId p = 0; p < m.particles.capacity(); ++p)
    o << m.particles.position[p].transpose() << ' ' << m.particles.lumped_mass[p] << '\n';
  return o.str();
}

}  // namespace

TEST_CASE("patch formulation: bars -> CST -> bars without stopping the solver") {
  Tube tube(12, 6, 0.95);
  Model& m = tube.m;
  const std::size_t all_bars = m.bars.size();  // 12 x 6 quads: 12 x 7 ring edges, 12 x 6 axial
  CHECK(all_bars == 12u * 7 + 12u * 6);
  Solver solver(m);
  for (int k = 0; k < 50; ++k) solver.step();
  const auto tris = triangles_of(m, tube.patch, Vec3(0, 0, 1));
  m.set_patch_formulation(tube.patch, form(2, 1), tris);
  CHECK(m.check() == "");
  CHECK(m.csts.size() == 2u * 12 * 6);
  CHECK(m.bars.size() == 2u * 12);  // the two boundary rings keep their bars
  CHECK(m.patch_triangles(tube.patch).size() == tris.size());
  for (int k = 0; k < 200; ++k) solver.step();
  CHECK(m.check() == "");
  // Form-finding -> analysis of the form found: new reference shapes.
  Membrane an;
  an.mode = Membrane::Analysis;
  an.sigma_warp = 2;
  an.sigma_weft = 1;
  an.dxx = an.dyy = 500;
  an.dxy = an.dyx = 100;
  an.G = 20;
  m.set_patch_formulation(tube.patch, an, m.patch_triangles(tube.patch));
  CHECK(m.check() == "");
  std::vector<CstReference> refs;
  m.patch_triangles(tube.patch, &refs);
  REQUIRE(refs.size() == tris.size());
  CHECK(refs[0].l1 > 0);
  CHECK(refs[0].h > 0);
  for (int k = 0; k < 200; ++k) solver.step();
  m.set_patch_formulation(tube.patch, Membrane{});
  CHECK(m.check() == "");
  CHECK(m.csts.size() == 0u);
  CHECK(m.bars.size() == all_bars);
  for (int k = 0; k < 50; ++k) solver.step();
  CHECK(m.check() == "");
  // The local patches equal a rebuild from the map, in every mode.
  m.set_patch_formulation(tube.patch, an, tris);
  const std::size_t csts = m.csts.size(), bars = m.bars.size();
  m.rebuild_elements();
  CHECK(m.check() == "");
  CHECK(m.csts.size() == csts);
  CHECK(m.bars.size() == bars);
}

TEST_CASE("patch formulation: a switch rolls back exactly; a refused one changes nothing") {
  Tube tube(8, 4, 0.9);
  Model& m = tube.m;
  const auto tris = triangles_of(m, tube.patch, Vec3(0, 0, 1));
  const std::string bars = fingerprint(m);
  m.begin_transaction();
  m.set_patch_formulation(tube.patch, form(1, 1), tris);
  CHECK(fingerprint(m) != bars);
  m.rollback_transaction();
  CHECK(fingerprint(m) == bars);
  CHECK(m.check() == "");

  m.set_patch_formulation(tube.patch, form(1, 1), tris);
  const std::string cst = fingerprint(m);
  m.begin_transaction();
  m.set_patch_formulation(tube.patch, Membrane{});
  m.rollback_transaction();
  CHECK(fingerprint(m) == cst);
  CHECK(m.check() == "");

  // Refusals: each names its argument, the model is bit-identical after.
  auto refused = [&](auto&& op, const char* words) {
    CHECK_THROWS_WITH_AS(op(), doctest::Contains(words), ModelError);
    CHECK(fingerprint(m) == cst);
  };
  refused([&] { m.set_patch_formulation(tube.patch, form(1, 1), {tris.begin(), tris.end() - 1}); }, "needs 64 triangles");
  auto swapped = tris;
  std::swap(swapped[0][1], swapped[0][2]);  // b-c is the diagonal: not half of a quad
  refused([&] { m.set_patch_formulation(tube.patch, form(1, 1), swapped); }, "is not half of a quad");
  auto twice = tris;
  twice[1] = twice[0];
  refused([&] { m.set_patch_formulation(tube.patch, form(1, 1), twice); }, "are the same triangle");
  refused([&] { m.set_patch_formulation(tube.patch, form(0, 0), tris); }, "needs a warp or weft stress");
  refused([&] { m.set_patch_formulation(tube.patch, form(-1, 1), tris); }, ">= 0");
  Membrane bad;
  bad.mode = Membrane::Analysis;
  bad.dxx = 1;
  bad.dyy = 1;
  bad.dxy = bad.dyx = 2;
  refused([&] { m.set_patch_formulation(tube.patch, bad, tris); }, "dxx dyy must exceed");
  refused([&] { m.set_patch_formulation(tube.patch, Membrane{}, tris); }, "takes no triangles");
  refused([&] { m.set_patch_formulation(999, form(1, 1), tris); }, "does not exist");
  const ParticleId a = m.add_particle(Vec3(5, 5, 5)), b = m.add_particle(Vec3(6, 5, 5));
  const BlockId cable = m.add_cable(a, b, Section{1, 0, 0, 0});
  CHECK_THROWS_WITH_AS(m.set_patch_formulation(cable, form(1, 1), tris), doctest::Contains("only patches"), ModelError);
}

TEST_CASE("patch formulation: topology operations on a CST patch") {
  FlatSquare sq(3, 3.0);
  Model& m = sq.m;
  const auto tris = triangles_of(m, sq.patch, Vec3(1, 0, 0));
  m.set_patch_formulation(sq.patch, form(1, 1), tris);
  const std::string before = fingerprint(m);
  // Rules that rewrite the quads refuse, naming the patch.
  CHECK_THROWS_WITH_AS(m.remove_from_patch(sq.at(1, 1)), doctest::Contains("back to bars first"), ModelError);
  CHECK(fingerprint(m) == before);
  // A second patch sharing the right edge: merging refuses.
  std::vector<ParticleId> more;
  for (int r = 0; r <= 3; ++r)
    for (int c = 0; c <= 1; ++c) more.push_back(c == 0 ? sq.at(r, 3) : m.add_particle(Vec3(4, r, 0)));
  const BlockId other = m.add_quad_grid(more, 4, 2, Section{1e3, 0, 0, 0});
  const std::string two = fingerprint(m);
  CHECK_THROWS_WITH_AS(m.merge_patches(sq.patch, other), doctest::Contains(("switch patch " + std::to_string(sq.patch)).c_str()),
                       ModelError);
  CHECK_THROWS_WITH_AS(m.merge_patches(other, sq.patch), doctest::Contains("back to bars first"), ModelError);
  CHECK(fingerprint(m) == two);
  // Explode a shared particle of the common edge: the triangles follow it.
  const ParticleId shared = sq.at(1, 3);
  const std::vector<ParticleId> parts = m.explode(shared);
  CHECK(parts.size() == 2u);
  CHECK(m.check() == "");
  bool follows = false;
  for (const Cst& c : m.csts.items) follows |= c.i == parts[0] || c.j == parts[0] || c.k == parts[0];
  CHECK(follows);
  // And merging them back.
  m.merge(parts);
  CHECK(m.check() == "");
  // delete_patch takes the triangles with it.
  m.delete_patch(sq.patch);
  CHECK(m.csts.size() == 0u);
  CHECK(m.check() == "");
}

TEST_CASE("patch formulation: random operations and switches in transactions stay valid and roll back exactly") {
  // Two patches sharing an edge, a cable across them; random primitive
  // operations and formulation switches, each in a transaction that commits
  // or rolls back at random.
  FlatSquare sq(4, 4.0);
  Model& m = sq.m;
  std::vector<ParticleId> more;
  for (int r = 0; r <= 4; ++r)
    for (int c = 0; c <= 2; ++c) more.push_back(c == 0 ? sq.at(r, 4) : m.add_particle(Vec3(4 + c, r, 0.1 * c)));
  m.add_quad_grid(more, 5, 3, Section{1e3, 0, 0, 0});
  m.add_cable(sq.at(2, 2), more[7], Section{1e3, 0, 1, 0});
  std::mt19937 rng(7);
  auto any_particle = [&] {
    std::vector<ParticleId> live;
    for (ParticleId p = 0; p < m.particles.capacity(); ++p)
      if (m.particles.valid(p)) live.push_back(p);
    return live[rng() % live.size()];
  };
  auto any_patch = [&] {
    std::vector<BlockId> ps;
    for (BlockId b : m.live_blocks())
      if (m.blocks[b].kind == BlockKind::Patch) ps.push_back(b);
    return ps.empty() ? BlockId(kNone) : ps[rng() % ps.size()];
  };
  int switched = 0, refused = 0, rolled_back = 0;
  for (int round = 0; round < 400; ++round) {
    const std::string before = fingerprint(m);
    m.begin_transaction();
    try {
      switch (rng() % 7) {
        case 0:
        case 1: {
          const BlockId b = any_patch();
          if (b == kNone) break;
          Membrane mem = form(1 + rng() % 3, 1);
          if (rng() % 3 == 0) mem = Membrane{};
          else if (rng() % 2) {
            mem.mode = Membrane::Analysis;
            mem.dxx = mem.dyy = 100;
          }
          m.set_patch_formulation(b, mem, mem.cst() ? triangles_of(m, b, Vec3(1, 0, 0)) : std::vector<Model::Triangle>{});
          ++switched;
          break;
        }
        case 2: m.explode(any_particle()); break;
        case 3: m.merge({any_particle(), any_particle()}); break;
        case 4: m.remove_from_patch(any_particle()); break;
        case 5: {
          const BlockId a = any_patch(), b = any_patch();
          if (a != kNone) m.merge_patches(a, b);
          break;
        }
        case 6: m.particles.position[any_particle()] += Vec3(0.01, -0.02, 0.03); break;
      }
    } catch (const ModelError&) {
      ++refused;
    }
    if (rng() % 3 == 0) {
      m.rollback_transaction();
      ++rolled_back;
      REQUIRE(fingerprint(m) == before);
    } else {
      m.commit_transaction();
    }
    const std::string c = m.check();
    CAPTURE(round);
    REQUIRE(c == "");
  }
  MESSAGE(switched << " switches, " << refused << " refusals, " << rolled_back << " rollbacks");
  CHECK(switched > 30);
  // The buffers patched locally hold what a rebuild from the map gives.
  const std::size_t csts = m.csts.size(), bars = m.bars.size();
  m.rebuild_elements();
  CHECK(m.check() == "");
  CHECK(m.csts.size() == csts);
  CHECK(m.bars.size() == bars);
}
