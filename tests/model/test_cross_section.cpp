// Cross-sections (model/cross_section.hpp) against their textbook formulas,
// and the material table's entries (model/materials.hpp).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "model/cross_section.hpp"
#include "model/materials.hpp"
#include "model/types.hpp"

using namespace tendril;

TEST_CASE("sections: rod, tube and rectangle") {
  const double pi = std::numbers::pi;
  const CrossSection rod = rod_section(0.02);
  CHECK(rod.A == doctest::Approx(pi * 1e-4));
  CHECK(rod.Iy == doctest::Approx(pi * 1.6e-7 / 64));
  CHECK(rod.J == doctest::Approx(2 * rod.Iy));
  CHECK(rod.Wy == doctest::Approx(pi * 8e-6 / 32));  // pi d^3 / 32
  const CrossSection tube = tube_section(0.05, 0.004);
  CHECK(tube.A == doctest::Approx(pi * (0.05 * 0.05 - 0.042 * 0.042) / 4));
  CHECK(tube.Iz == doctest::Approx(pi * (std::pow(0.05, 4) - std::pow(0.042, 4)) / 64));
  CHECK(tube_section(0.02, 0.01).Iy == doctest::Approx(rod.Iy));  // a wall of half the diameter is a rod
  const CrossSection rect = rect_section(0.1, 0.2);
  CHECK(rect.Iy == doctest::Approx(0.1 * 0.008 / 12));
  CHECK(rect.Iz == doctest::Approx(0.2 * 0.001 / 12));
  CHECK(rect.Wy == doctest::Approx(0.1 * 0.04 / 6));  // b h^2 / 6
  // Saint-Venant: a square 0.1406 a^4 (exact), a thin strip a c^3 / 3.
  CHECK(rect_section(1, 1).J == doctest::Approx(0.1406).epsilon(0.002));
  CHECK(rect_section(1, 0.01).J == doctest::Approx(0.01 * 0.01 * 0.01 / 3).epsilon(0.01));
  CHECK_THROWS_WITH_AS(tube_section(0.02, 0.011), "section.tube: 't' must be at most half of 'd' (a wall, not more than a rod)",
                       ModelError);
  CHECK_THROWS_WITH_AS(rod_section(-1), "section.rod: 'd' must be a finite length > 0 [m]", ModelError);
  CHECK_THROWS_AS(rect_section(0.1, NAN), ModelError);
}

TEST_CASE("materials: every entry complete, with a source") {
  for (const Material& m : materials()) {
    INFO(m.name);
    CHECK(m.E > m.G);
    CHECK(m.G > 0);
    CHECK(m.density > 0);
    CHECK(m.strength > 0);
    CHECK(!m.source.empty());
  }
  REQUIRE(find_material("steel"));
  CHECK(find_material("steel")->E == 210e9);
  CHECK(find_material("nothing") == nullptr);
  for (const Fabric& f : fabrics()) {
    INFO(f.name);
    CHECK(f.Et_warp >= f.Et_weft);
    CHECK(f.strength_warp > 0);
    CHECK(f.weight > 0);
    CHECK(!f.source.empty());
  }
}
