// Pressure on a patch (Model::set_pressure, pressure_forces.cpp): the side
// it pushes (towards a direction, or outward), the total force it exerts
// (the vector area of a surface depends only on its boundary, so a patch
// fixed on a flat square carries p times the square's area whatever its
// deflection), with every integrator, and the model database round trip.
#include <doctest/doctest.h>

#include <cmath>

#include "cst_scenes.hpp"
#include "io/model_xml.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using namespace tendril::test;

namespace {

Vec3 area_vector(const Model& m, const Model::Quad& q) {
  const auto& x = m.particles.position;
  return 0.5 * (x[q[2]] - x[q[0]]).cross(x[q[3]] - x[q[1]]);
}

// The sum of the supports' reactions on the square.
Vec3 total_reaction(const FlatSquare& sq, const Solver& solver) {
  Vec3 sum = Vec3::Zero();
  for (ParticleId p : sq.ps)
    if (sq.m.particles.lock[p]) sum += solver.reaction(p);
  return sum;
}

}  // namespace

TEST_CASE("pressure: the quads are oriented towards the given side, or outward") {
  FlatSquare sq(4, 1.0);
  sq.m.set_pressure(sq.patch, 100, Vec3(0, 0, -1));
  const auto down = sq.m.pressure_quads(sq.patch);
  REQUIRE(down.size() == 16u);
  for (const auto& q : down) CHECK(area_vector(sq.m, q).z() == doctest::Approx(-1.0 / 16));
  sq.m.set_pressure(sq.patch, 100, Vec3(0, 0, 1));
  for (const auto& q : sq.m.pressure_quads(sq.patch)) CHECK(area_vector(sq.m, q).z() == doctest::Approx(1.0 / 16));

  Tube tube(12, 4);  // outward: away from the axis
  tube.m.set_pressure(tube.patch, 1);
  const auto faces = tube.m.pressure_quads(tube.patch);
  REQUIRE(faces.size() == 48u);
  for (const auto& q : faces) {
    Vec3 mid = Vec3::Zero();
    for (ParticleId p : q) mid += 0.25 * tube.m.particles.position[p];
    mid.z() = 0;
    CHECK(area_vector(tube.m, q).dot(mid) > 0);
  }
  tube.m.set_pressure(tube.patch, 0);
  CHECK(tube.m.pressure_quads(tube.patch).empty());
  CHECK_THROWS_WITH(tube.m.set_pressure(tube.patch, NAN), "pressure: the pressure must be a finite number [Pa]");
}

TEST_CASE("pressure: the supports of a flat square carry p times its area, with every integrator") {
  for (Integrator integrator : {Integrator::Leapfrog, Integrator::VariationalImplicitEuler, Integrator::ProjectiveDynamics, Integrator::Mixed}) {
    FlatSquare sq(8, 2.0);  // bars, EA = 1e3 N: it deflects by ~0.2 m
    sq.m.set_pressure(sq.patch, 50, Vec3(0, 0, 1));
    Solver solver(sq.m);
    solver.settings.integrator = integrator;
    const RunResult r = solver.run(1e-7, 500000);
    REQUIRE(r.converged);
    const Vec3 reactions = total_reaction(sq, solver);
    INFO(integrator_name(integrator));
    CHECK(reactions.z() == doctest::Approx(-50 * 4.0).epsilon(1e-6));
    CHECK(std::abs(reactions.x()) < 1e-6);
    CHECK(sq.m.particles.position[sq.ps[4 * 9 + 4]].z() > 0.05);  // the centre went up
  }
}

TEST_CASE("pressure: the model database keeps it") {
  FlatSquare sq(2, 1.0);
  sq.m.set_pressure(sq.patch, -12.5, Vec3(0, 1, 0));
  SolverSettings settings;
  Model back;
  SolverSettings s2;
  load_model_xml_string(model_xml_string(sq.m, settings), back, s2);
  BlockId patch = kNone;
  for (BlockId b : back.live_blocks())
    if (back.blocks[b].kind == BlockKind::Patch) patch = b;
  REQUIRE(patch != kNone);
  CHECK(back.blocks[patch].pressure == -12.5);
  CHECK(back.blocks[patch].pressure_towards == Vec3(0, 1, 0));
}

// An area load q along d (Model::set_area_load, snow): each quad carries
// q |A . d|, so a patch held along its boundary carries q times the
// boundary's area projected along d, whatever its deflection — q A cos(theta)
// on a square tilted by theta under snow — with every integrator.
TEST_CASE("area load: a square tilted by 30 degrees carries q A cos(theta) of snow, with every integrator") {
  const double theta = std::acos(-1.0) / 6, q = 40;
  for (Integrator integrator : {Integrator::Leapfrog, Integrator::VariationalImplicitEuler, Integrator::ProjectiveDynamics, Integrator::Mixed}) {
    FlatSquare sq(8, 2.0);
    for (ParticleId p : sq.ps) {  // tilt about x
      const Vec3 x = sq.m.particles.position[p];
      sq.m.particles.position[p] = Vec3(x.x(), x.y() * std::cos(theta), x.y() * std::sin(theta));
    }
    sq.m.set_area_load(sq.patch, q, Vec3(0, 0, -2));  // kept as a unit vector
    CHECK(sq.m.blocks[sq.patch].area_load_direction == Vec3(0, 0, -1));
    Solver solver(sq.m);
    solver.settings.integrator = integrator;
    const RunResult r = solver.run(1e-7, 500000);
    REQUIRE(r.converged);
    const Vec3 reactions = total_reaction(sq, solver);
    INFO(integrator_name(integrator));
    CHECK(reactions.z() == doctest::Approx(q * 4.0 * std::cos(theta)).epsilon(1e-6));
    CHECK(std::abs(reactions.x()) < 1e-6);
    CHECK(std::abs(reactions.y()) < 1e-6);  // a dead load: no component across the slope
    CHECK(sq.m.particles.position[sq.at(4, 4)].z() < std::sin(theta) - 0.05);  // the middle sagged
  }
}

TEST_CASE("area load: the model database keeps it; it is refused off a patch or without a direction") {
  FlatSquare sq(2, 1.0);
  sq.m.set_area_load(sq.patch, 7.5, Vec3(1, 0, -1));
  SolverSettings settings;
  Model back;
  SolverSettings s2;
  const std::string xml = model_xml_string(sq.m, settings);
  load_model_xml_string(xml, back, s2);
  CHECK(back.blocks[sq.patch].area_load == 7.5);
  CHECK(back.blocks[sq.patch].area_load_direction.isApprox(Vec3(1, 0, -1).normalized(), 1e-15));
  CHECK(model_xml_string(back, s2) == xml);
  CHECK_THROWS_WITH_AS(sq.m.set_area_load(sq.patch, 1, Vec3::Zero()), "area_load: the direction must be a finite, non-zero vector",
                       ModelError);
  const BlockId cable = sq.m.add_cable(sq.ps[0], sq.ps[8], Section{1, 0, 0, 0});
  CHECK_THROWS_WITH_AS(sq.m.set_area_load(cable, 1, Vec3(0, 0, -1)),
                       ("area_load: block " + std::to_string(cable) + " is not a patch").c_str(), ModelError);
  sq.m.set_area_load(sq.patch, 0, Vec3(0, 0, -1));  // removed
  CHECK(sq.m.area_load_quads(sq.patch).empty());
}
