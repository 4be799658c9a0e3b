// The CalculiX deck (io/ccx.hpp): what each element becomes, checked on the
// numbers the deck carries; the .dat reader on a file of ccx's layout. The
// comparison with ccx itself is bench/fe/fe.lua (test fe-ccx when ccx is
// installed).
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "../physics/cst_scenes.hpp"
#include "io/atomic_file.hpp"
#include "io/ccx.hpp"
#include "io/input_file.hpp"

using namespace tendril;
using namespace tendril::test;

namespace {

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

// The data line after the first line that starts with `keyword`.
std::string line_after(const std::string& text, const std::string& keyword, int skip = 1) {
  std::size_t at = text.find(keyword);
  REQUIRE(at != std::string::npos);
  for (int k = 0; k < skip; ++k) at = text.find('\n', at) + 1;
  return text.substr(at, text.find('\n', at) - at);
}

}  // namespace

TEST_CASE("ccx: a cable is a spring with its force now, none below its slack length") {
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(2, 0, 0));
  m.add_cable(a, b, Section{1000, 0, 50, 0}, 1.0);  // 2 m long, rest 1 m: N = 50 + 1000 * 1 = 1050 N
  m.set_lock(a, kLockTranslation);
  m.set_load(b, Vec3(0, -3, 0));
  const std::string deck = ccx_string(m);
  CHECK(has(deck, "*NODE, NSET=NALL\n1, 0., 0., 0.\n2, 2., 0., 0.\n"));
  CHECK(has(deck, "*ELEMENT, TYPE=SPRINGA, ELSET=SPRINGS\n1, 1, 2\n"));
  // Force against elongation from now: zero at -1050 / (EA / L) = -1.05 m, 1050 N at 0, + 1000 N/m beyond.
  CHECK(has(deck, "*SPRING, ELSET=S1, NONLINEAR\n0., -2.\n0., -1.05\n1050., 0.\n3050., 2.\n"));
  CHECK(has(deck, "*BOUNDARY\n1, 1, 1\n1, 2, 2\n1, 3, 3\n"));
  CHECK(has(deck, "*CLOAD\n2, 2, -3.\n"));
  CHECK(has(deck, "*STEP, NLGEOM"));
}

TEST_CASE("ccx: a beam is B32R with a rectangle that gives EA, EIy, EIz exactly and GJ by Poisson's ratio") {
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0));
  const BlockId b = m.add_beam_from(a, Vec3(2, 0, 0), 2, Section{1e6, 50, 0, 0});
  m.set_beam_formulation(b, 6);
  const std::string deck = ccx_string(m);
  CHECK(has(deck, "*ELEMENT, TYPE=B32R, ELSET=BEAMS\n"));
  // Square a = sqrt(12 EI / EA); E = EA / a^2; J = 0.1406 a^4 and GJ = EI:
  // nu = E J / (2 GJ) - 1.
  const double side = std::sqrt(12 * 50 / 1e6), E = 1e6 / (side * side);
  const double J = (1.0 / 3 - 0.21 * (1 - 1.0 / 12)) * std::pow(side, 4);
  const std::string dims = line_after(deck, "*BEAM SECTION, ELSET=B1");
  CHECK(std::stod(dims) == doctest::Approx(side).epsilon(1e-12));
  const std::string elastic = line_after(deck, "*ELASTIC\n");
  CHECK(std::stod(elastic) == doctest::Approx(E).epsilon(1e-12));
  CHECK(std::stod(elastic.substr(elastic.find(',') + 1)) == doctest::Approx(E * J / (2 * 50) - 1).epsilon(1e-12));
  // A middle node per segment, after the particles' nodes.
  CHECK(has(deck, "4, 0.5, 0., 0.\n"));
  CHECK(has(deck, "1, 1, 4, 2\n"));
}

TEST_CASE("ccx: a CST patch in analysis is M3D3 with d / t and its prestress / t; form-finding is refused") {
  FlatSquare sq(2, 2.0);
  Membrane ff;
  ff.mode = Membrane::FormFinding;
  ff.sigma_warp = ff.sigma_weft = 10;
  sq.m.set_patch_formulation(sq.patch, ff, triangles_of(sq.m, sq.patch, Vec3(1, 0, 0)));
  CHECK_THROWS_WITH_AS(ccx_string(sq.m), doctest::Contains("is a CST patch in form-finding"), ModelError);
  Membrane an;
  an.mode = Membrane::Analysis;
  an.sigma_warp = 30;
  an.sigma_weft = 20;
  an.dxx = 600;
  an.dxy = an.dyx = 100;
  an.dyy = 500;
  an.G = 40;
  sq.m.set_patch_formulation(sq.patch, an, triangles_of(sq.m, sq.patch, Vec3(1, 0, 0)));
  const std::string deck = ccx_string(sq.m);
  const double t = kCcxMembraneThickness;
  CHECK(has(deck, "*ELEMENT, TYPE=M3D3, ELSET=MEMBRANES\n"));
  CHECK(line_after(deck, "*ELASTIC, TYPE=ORTHO") == "600000., 100000., 500000., 0., 0., 600000., 40000., 40000.");
  CHECK(has(deck, "*MEMBRANE SECTION, ELSET=M"));
  // The warp along x here: the initial stress is 30 / t along x, 20 / t along y.
  const std::string s = line_after(deck, "*INITIAL CONDITIONS, TYPE=STRESS");
  CHECK(has(s, ", 1, 30000., 20000., 0., 0., 0., 0."));
  (void)t;
}

TEST_CASE("ccx: pressure on a CST patch is *DLOAD P1 where it pushes along (x_j - x_i) x (x_k - x_i), P2 against") {
  FlatSquare sq(2, 2.0);
  Membrane an;
  an.mode = Membrane::Analysis;
  an.sigma_warp = an.sigma_weft = 100;
  an.dxx = an.dyy = 600;
  an.dxy = an.dyx = 100;
  an.G = 40;
  sq.m.set_patch_formulation(sq.patch, an, triangles_of(sq.m, sq.patch, Vec3(1, 0, 0)));
  const Particles& P = sq.m.particles;
  // Each M3D3's label against the side its pressure pushes towards: ccx 2.20
  // pushes P1 along the element's (x_j - x_i) x (x_k - x_i) (docs/calculix.md).
  auto check_side = [&](const Vec3& towards) {
    sq.m.set_pressure(sq.patch, 300, towards);
    const std::string deck = ccx_string(sq.m);
    REQUIRE(has(deck, "*DLOAD\n"));
    std::map<int, std::string> label;  // element -> "P1, 300." or "P2, 300."
    for (std::size_t at = deck.find("*DLOAD\n") + 7; at < deck.size() && deck[at] != '*';
         at = deck.find('\n', at) + 1) {
      const std::string line = deck.substr(at, deck.find('\n', at) - at);
      label[std::stoi(line)] = line.substr(line.find(',') + 2);
    }
    std::size_t at = deck.find("*ELEMENT, TYPE=M3D3");
    REQUIRE(at != std::string::npos);
    int triangles = 0;
    for (at = deck.find('\n', at) + 1; deck[at] != '*'; at = deck.find('\n', at) + 1) {
      int el, i, j, k;
      REQUIRE(std::sscanf(deck.c_str() + at, "%d, %d, %d, %d", &el, &i, &j, &k) == 4);
      const Vec3 n = (P.position[j - 1] - P.position[i - 1]).cross(P.position[k - 1] - P.position[i - 1]);
      CAPTURE(el);
      CHECK(label[el] == (n.dot(towards) > 0 ? "P1, 300." : "P2, 300."));
      ++triangles;
    }
    CHECK(triangles == 8);  // 2 x 2 quads, two triangles each
    CHECK(label.size() == 8);
    CHECK(!has(deck, "*CLOAD"));  // the faces carry it, no nodal forces besides
  };
  check_side(Vec3(0, 0, -1));
  check_side(Vec3(0, 0, 1));
}

TEST_CASE("ccx: pressure on a bar patch is the nodal forces p A / 4 a quad corner of its shape now") {
  FlatSquare sq(2, 2.0);  // four 1 x 1 quads; the middle particle corners all four
  sq.m.set_pressure(sq.patch, 300, Vec3(0, 0, -1));
  const std::string deck = ccx_string(sq.m);
  CHECK(!has(deck, "*DLOAD"));
  CHECK(has(deck, "*CLOAD\n"));
  CHECK(has(deck, "\n" + std::to_string(sq.ps[4] + 1) + ", 3, -300.\n"));
  CHECK(has(deck, "\n" + std::to_string(sq.ps[0] + 1) + ", 3, -75.\n"));  // a corner: one quad
  CHECK(has(deck, "pressure 300. Pa as the nodal forces"));
}

TEST_CASE("ccx: the .dat reader takes the last block of displacements and names a bad line") {
  const std::string dat =
      "\n displacements (vx,vy,vz) for set NALL and time  0.5000000E+00\n\n"
      "         1  0.000000E+00  0.000000E+00  0.000000E+00\n"
      "         2  1.000000E-03 -2.000000E-03  3.000000E-03\n"
      "\n stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set E and time  0.5000000E+00\n\n"
      "         1   1  1.0E+00  0.0E+00  0.0E+00  0.0E+00  0.0E+00  0.0E+00\n"
      "\n displacements (vx,vy,vz) for set NALL and time  0.1000000E+01\n\n"
      "         1  0.000000E+00  0.000000E+00  0.000000E+00\n"
      "         2  2.000000E-03 -4.000000E-03  6.500000E-03\n";
  const auto u = parse_ccx_displacements(dat, "x.dat");
  REQUIRE(u.size() == 2u);
  CHECK(u[1].node == 2);
  CHECK(u[1].u[0] == 2e-3);
  CHECK(u[1].u[2] == 6.5e-3);
  CHECK_THROWS_WITH_AS(parse_ccx_displacements("nothing here\n", "y.dat"),
                       doctest::Contains("y.dat: no nodal displacements"), InputError);
  CHECK_THROWS_WITH_AS(
      parse_ccx_displacements(" displacements (vx,vy,vz) for set NALL\n\n         1  0.0E+00  nan  0.0E+00\n", "z.dat"),
      doctest::Contains("z.dat:3: not a displacement line"), InputError);
  const std::string path = (std::filesystem::temp_directory_path() / "tendril_test_ccx.dat").string();
  write_file_atomically(path, dat);
  CHECK(read_ccx_displacements(path).size() == 2u);
  CHECK_THROWS_AS(read_ccx_displacements("/nonexistent-dir/x.dat"), InputError);
}

TEST_CASE("ccx: 3-DOF beams meeting pinned get a node each, tied in x, y, z; rigid ones share it") {
  for (const bool rigid : {false, true}) {
    Model m;
    const ParticleId apex = m.add_particle(Vec3(0, 0, 1));
    const ParticleId a = m.add_particle(Vec3(-1, 0, 0)), b = m.add_particle(Vec3(1, 0, 0));
    const ParticleId am = m.add_particle(Vec3(-0.5, 0, 0.5)), bm = m.add_particle(Vec3(0.5, 0, 0.5));
    const BlockId A = m.add_beam({a, am, apex}, Section{1e6, 100, 0, 0});
    const BlockId B = m.add_beam({b, bm, apex}, Section{1e6, 100, 0, 0});
    if (rigid) m.set_joint(apex, A, B, JointKind::Rigid);
    const std::string deck = ccx_string(m);
    // Particles are nodes 1-5, then the nodes made in segment order: beam
    // B's end at the apex is node 9 when pinned (its middle node 10), node 1
    // when rigid (its middle node 9).
    CHECK(has(deck, rigid ? "4, 5, 9, 1\n" : "4, 5, 10, 9\n"));
    CHECK(has(deck, "*EQUATION\n2\n9, 1, 1., 1, 1, -1.\n2\n9, 2, 1., 1, 2, -1.\n2\n9, 3, 1., 1, 3, -1.\n") == !rigid);
    CHECK(has(deck, "9, 0., 0., 1.\n") == !rigid);
  }
}
