// Rotational joints in the model database: round trip and rejection.
#include <doctest/doctest.h>

#include "io/model_xml.hpp"

using namespace tendril;

namespace {
// Two 3-particle beams crossing at their middle particle.
ParticleId crossing(Model& m) {
  ParticleId c = m.add_particle(Vec3(0, 0, 0));
  ParticleId a0 = m.add_particle(Vec3(-1, 0, 0)), a1 = m.add_particle(Vec3(1, 0, 0));
  ParticleId b0 = m.add_particle(Vec3(0, -1, 0)), b1 = m.add_particle(Vec3(0, 1, 0));
  m.add_beam({a0, c, a1}, Section{1e6, 10, 0, 0});
  m.add_beam({b0, c, b1}, Section{1e6, 10, 0, 0});
  return c;
}
}  // namespace

TEST_CASE("joints round-trip through the model database") {
  Model m;
  SolverSettings s;
  ParticleId c = crossing(m);
  m.add_joint(c, 1.25, 3e4);
  const std::string xml = model_xml_string(m, s);
  CHECK(xml.find("<joint particle=\"0\"") != std::string::npos);
  Model back;
  SolverSettings s2;
  load_model_xml_string(xml, back, s2);
  REQUIRE(back.joints.size() == 1);
  CHECK(back.joints[0].angle == 1.25);
  CHECK(back.joints[0].stiffness == 3e4);
  CHECK(model_xml_string(back, s2) == xml);
}

TEST_CASE("a bad joint is rejected naming its element, and the model stays empty") {
  Model m;
  SolverSettings s;
  crossing(m);
  m.add_joint(0, 1.0, 1e3);
  std::string xml = model_xml_string(m, s);
  std::string bad = xml;
  bad.replace(bad.find("stiffness=\"1000\""), 16, "stiffness=\"-5\"");
  Model target;
  SolverSettings s2;
  CHECK_THROWS_WITH_AS(load_model_xml_string(bad, target, s2, "j.xml"), doctest::Contains("<joint"), ModelFormatError);
  CHECK(target.particle_count() == 0);
  std::string not_crossing = xml;
  not_crossing.replace(not_crossing.find("particle=\"0\""), 12, "particle=\"1\"");
  CHECK_THROWS_WITH_AS(load_model_xml_string(not_crossing, target, s2, "j.xml"),
                       doctest::Contains("not an interior crossing"), ModelFormatError);
  CHECK(target.particle_count() == 0);
}
