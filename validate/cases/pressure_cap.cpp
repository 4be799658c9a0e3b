// A soap film under pressure (Laplace): an equal-stress CST membrane
// (sigma = 1 N/m both ways) on a circle of radius 1, its boundary fixed,
// form-found from the flat disc under a pressure p = 1 Pa (Model::
// set_pressure, a follower load) is a spherical cap of radius rho = 2 sigma
// / p = 2 m, rise rho - sqrt(rho^2 - 1) = 2 - sqrt(3) at the centre.
// Resolution: quads along a side of the disc mesh (disc_mesh.hpp).
#include <cmath>

#include "case.hpp"
#include "cases/soap_film.hpp"
#include "cases/disc_mesh.hpp"

namespace tendril::validate {

namespace {

constexpr double kSigma = 1, kPressure = 1, kRadius = 1;

Outcome run_cap(const Setting& setting) {
  Model m;
  const DiscMesh d = disc_mesh(m, setting.segments, kRadius);
  for (ParticleId p : d.boundary) m.set_lock(p, kLockTranslation);
  const BlockId patch = m.add_quad_grid(d.grid, d.n + 1, d.n + 1, Section{1, 0, 0, 0});
  make_soap_film(m, patch, kSigma, d.triangles);
  m.set_pressure(patch, kPressure, Vec3(0, 0, 1));
  Solver solver(m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-9, 2'000'000);  // pulls of ~sigma h ~ 0.03 N
  const double rho = 2 * kSigma / kPressure;
  out.error = relative_error(m.particles.position[d.centre()].z(), rho - std::sqrt(rho * rho - kRadius * kRadius));
  return out;
}

}  // namespace

Case pressure_cap_case() {
  Case c;
  c.name = "pressure_cap";
  c.reference = "equal-stress CST disc of radius 1 under 1 Pa, from flat: spherical cap of radius 2 sigma / p, rise";
  c.resolution = "quads along a side of the disc";
  c.formulations = {"cst"};
  c.segments = {8, 16, 32};
  c.quick_segments = {8, 16};
  c.defaults.formulation = "cst";
  c.defaults.segments = 16;
  c.tolerance = 0.005;
  c.run = run_cap;
  return c;
}

}  // namespace tendril::validate
