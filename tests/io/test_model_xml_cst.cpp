// The model database stores a patch's CST formulation (thesis 5.5.2.2):
// membrane attributes and <triangle> children, exact in both modes; bad
// documents are refused naming the element and attribute.
#include <doctest/doctest.h>

#include "../physics/cst_scenes.hpp"
#include "io/model_xml.hpp"

using namespace tendril;
using namespace tendril::test;

namespace {

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

void refused(const std::string& xml, const char* words) {
  Model m;
  SolverSettings s;
  CHECK_THROWS_WITH_AS(load_model_xml_string(xml, m, s, "cst.xml"), doctest::Contains(words), ModelFormatError);
  CHECK(m.particle_count() == 0u);
}

}  // namespace

TEST_CASE("model database: CST patches round-trip bit for bit, references included") {
  FlatSquare sq(3, 3.0);
  Membrane an;
  an.mode = Membrane::Analysis;
  an.sigma_warp = 3;
  an.sigma_weft = 2;
  an.dxx = 400;
  an.dxy = 50;
  an.dyx = 40;
  an.dyy = 300;
  an.G = 0.1;
  const auto tris = triangles_of(sq.m, sq.patch, Vec3(1, 0, 0));
  sq.m.set_patch_formulation(sq.patch, an, tris);
  // Move the particles: the stored references are those of the switch, not
  // of the positions saved.
  for (ParticleId p : sq.ps) sq.m.particles.position[p] += Vec3(0.001 * p, 0, 0.01);
  const std::string xml = model_xml_string(sq.m, {});
  Model loaded;
  SolverSettings settings;
  load_model_xml_string(xml, loaded, settings);
  CHECK(loaded.check() == "");
  CHECK(model_xml_string(loaded, settings) == xml);
  std::vector<CstReference> a, b;
  sq.m.patch_triangles(sq.patch, &a);
  loaded.patch_triangles(loaded.live_blocks()[0], &b);
  std::sort(a.begin(), a.end(), [](auto& x, auto& y) { return x.l1 < y.l1 || (x.l1 == y.l1 && x.c < y.c); });
  std::sort(b.begin(), b.end(), [](auto& x, auto& y) { return x.l1 < y.l1 || (x.l1 == y.l1 && x.c < y.c); });
  CHECK(a == b);
  CHECK(loaded.patch_formulation(loaded.live_blocks()[0]) == an);

  refused(replaced(xml, "membrane=\"analysis\"", "membrane=\"soap\""), "attribute 'membrane' must be");
  refused(replaced(xml, " dxx=\"", " dxz=\""), "attribute 'dxx' is missing");
  refused(replaced(xml, " l1=\"", " l2=\""), "attribute 'l1' is missing");
  refused(replaced(xml, "<triangle a=\"0\"", "<triangle a=\"99\""), "no particle with id 99");
  refused(replaced(xml, "membrane=\"analysis\"", "membrane=\"form\""), "unknown attribute 'dxx'");
  refused(replaced(xml, "<triangle a=\"0\" b=\"1\"", "<triangle a=\"1\" b=\"0\""), "is not half of a quad");
}

TEST_CASE("model database: a triangle needs a CST patch") {
  FlatSquare sq(1, 1.0);
  const std::string xml = model_xml_string(sq.m, {});
  refused(replaced(xml, "</patch>", "<triangle a=\"0\" b=\"1\" c=\"3\"/></patch>"), "needs the patch's attribute membrane");
}
