// The model database holds patches that are not quad grids (paving,
// Catmull-Clark, projection) as <quad a b c d/> lists with their edges:
// save, load, save gives the same bytes, and malformed lists are refused
// naming the element.
#include <doctest/doctest.h>

#include "catmull_clark_rules.hpp"
#include "io/model_xml.hpp"
#include "paving.hpp"

using namespace tendril;

TEST_CASE("model database: paved and Catmull-Clark patches round-trip bit for bit") {
  Model m;
  SolverSettings s;
  std::vector<ParticleId> loop;
  for (int i = 0; i < 20; ++i) {
    const double t = 2 * 3.141592653589793 * i / 20;
    loop.push_back(m.add_particle(Vec3(3 * std::cos(t), 2 * std::sin(t), 0.3 * std::cos(2 * t))));
  }
  m.add_beam(loop, Section{1e6, 10, 0, 0}, true);
  const auto paved = meshing::patch_by_paving(m, loop, Section{1e3, 0, 5, 0.2});
  std::vector<ParticleId> tri{m.add_particle(Vec3(10, 0, 0)), m.add_particle(Vec3(12, 0, 0)), m.add_particle(Vec3(11, 2, 1))};
  meshing::patch_from_loop(m, tri, 1, Section{2e3, 0, 0, 0});
  // A rest length that is not the current distance must survive too.
  for (Dart d : m.map.orbit(kEdgeOrbit, m.blocks[paved.patch].dart)) m.rest_length[d] *= 0.9;
  m.rebuild_elements();
  // And a pressure on a quad list (it was written twice: a file tinyxml2 refused).
  m.set_pressure(paved.patch, 250, Vec3(0, 0, 10));
  REQUIRE(m.check() == "");
  const std::string first = model_xml_string(m, s);
  CHECK(first.find("<quad a=") != std::string::npos);
  Model loaded;
  SolverSettings ls;
  load_model_xml_string(first, loaded, ls);
  CHECK(loaded.check() == "");
  CHECK(loaded.block_count(BlockKind::Patch) == 2);
  CHECK(loaded.bars.size() == m.bars.size());
  CHECK(loaded.blocks[paved.patch].pressure == 250);
  CHECK(model_xml_string(loaded, ls) == first);
}

TEST_CASE("model database: bad quad lists are refused, naming the element") {
  std::string particles = "<particles>";
  for (int i = 0; i < 6; ++i)
    particles += "<particle id=\"" + std::to_string(i) + "\" x=\"" + std::to_string(i % 3) + "\" y=\"" +
                 std::to_string(i / 3) + "\" z=\"0\"/>";
  particles += "</particles>";
  auto doc = [&](const std::string& patch) {
    return "<tendril version=\"1\">" + particles + "<blocks><patch id=\"0\" EA=\"1\">" + patch + "</patch></blocks></tendril>";
  };
  const std::string quads = "<quad a=\"0\" b=\"1\" c=\"4\" d=\"3\"/><quad a=\"1\" b=\"2\" c=\"5\" d=\"4\"/>";
  std::string edges;
  for (auto [a, b] : {std::pair{0, 1}, {1, 4}, {4, 3}, {3, 0}, {1, 2}, {2, 5}, {5, 4}})
    edges += "<edge a=\"" + std::to_string(a) + "\" b=\"" + std::to_string(b) + "\" rest=\"1\"/>";
  {
    Model m;
    SolverSettings s;
    load_model_xml_string(doc(quads + edges), m, s);
    CHECK(m.check() == "");
    CHECK(m.bars.size() == 7);
  }
  struct Case {
    std::string xml, expect;
  };
  const std::string last_edge = "<edge a=\"5\" b=\"4\" rest=\"1\"/>";
  std::string six_edges = edges;
  six_edges.erase(six_edges.find(last_edge), last_edge.size());
  const Case cases[] = {
      {doc(quads + six_edges), "no <edge a b rest> between particles 4 and 5"},
      {doc(quads + edges + "<edge a=\"0\" b=\"2\" rest=\"1\"/>"), "particles 0 and 2 are not neighbours in a quad"},
      {doc(quads + edges + "<edge a=\"0\" b=\"1\" rest=\"1\"/>"), "this edge is already given"},
      {doc("<quad a=\"0\" b=\"1\" c=\"0\" d=\"3\"/>" + edges), "repeats particle 0"},
      {doc("<quad a=\"0\" b=\"1\" c=\"9\" d=\"3\"/><edge a=\"0\" b=\"1\" rest=\"1\"/><edge a=\"1\" b=\"9\" rest=\"1\"/>"
           "<edge a=\"9\" b=\"3\" rest=\"1\"/><edge a=\"3\" b=\"0\" rest=\"1\"/>"),
       "no particle with id 9"},
      {doc(""), "<quad a b c d> children"},
      {doc("<node p=\"0\"/>"), "unknown element <node>"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.xml);
    Model m;
    SolverSettings s;
    CHECK_THROWS_WITH_AS(load_model_xml_string(c.xml, m, s, "bad.xml"), doctest::Contains(c.expect.c_str()),
                         ModelFormatError);
    CHECK(m.particles.capacity() == 0);
  }
}
