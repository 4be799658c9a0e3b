// A flat disc membrane of equal stress sigma = 1 kN/m inside a ring beam of
// radius R = 1 m (3 DOF, built round at rest, EA = 1e6 N, EI = 1e3 N m^2,
// a third of its in-plane buckling load 3 EI / R^3): the ring carries the
// compression N = sigma R and shortens by N / EA, so its radius changes by
// -sigma R^2 / EA. (Its bending resists the change of curvature: it takes
// a part EI / (EA R^2) = 0.1 % of the load.) The
// error is the larger of those of N (the mean axial force of the ring's
// segments) and of the radius change. The polygon of n segments carries
// sigma times its apothem, R cos(pi / n): 0.12 % below sigma R at n = 64.
// The patch's edge bars (its boundary cables, here on the ring) have
// EA = 1e-3 N, next to nothing.
#include <cmath>

#include "case.hpp"
#include "cases/soap_film.hpp"
#include "cases/disc_mesh.hpp"

namespace tendril::validate {

namespace {

constexpr double kSigma = 1e3, kRadius = 1, kEA = 1e6, kEI = 1e3;

Outcome run_ring(const Setting& setting) {
  Model m;
  const DiscMesh d = disc_mesh(m, setting.segments / 4, kRadius);
  const BlockId ring = m.add_beam(d.boundary, Section{kEA, kEI, 0, 0}, true);
  m.set_rest_shape(ring, RestShape::Current);
  const BlockId patch = m.add_quad_grid(d.grid, d.n + 1, d.n + 1, Section{1e-3, 0, 0, 0});
  m.set_lock(d.centre(), kLockTranslation);  // no rigid-body motion: the disc is symmetric about it
  for (ParticleId p : d.grid) m.set_lock(p, kLockZ);
  make_soap_film(m, patch, kSigma, d.triangles);
  Solver solver(m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-6, 2'000'000);
  double N = 0, radius = 0;
  const std::vector<ParticleId> path = m.particles_of(ring);
  for (std::size_t k = 0; k < path.size(); ++k) {
    const Vec3& a = m.particles.position[path[k]];
    const Vec3& b = m.particles.position[path[(k + 1) % path.size()]];
    const double rest = m.edge_rest_length(path[k], path[(k + 1) % path.size()]);
    N += kEA * ((b - a).norm() / rest - 1) / double(path.size());
    radius += a.norm() / double(path.size());
  }
  const double force_error = relative_error(-N, kSigma * kRadius);
  const double radius_error = relative_error(radius - kRadius, -kSigma * kRadius * kRadius / kEA);
  out.error = std::max(force_error, radius_error);
  return out;
}

}  // namespace

Case membrane_ring_case() {
  Case c;
  c.name = "membrane_ring";
  c.reference = "equal-stress CST disc in a ring beam: ring force sigma R, radius change -sigma R^2 / EA";
  c.resolution = "segments of the ring";
  c.formulations = {"cst"};
  c.segments = {32, 64, 128};
  c.quick_segments = {32, 64};
  c.defaults.formulation = "cst";
  c.defaults.segments = 64;
  c.tolerance = 0.005;
  c.run = run_ring;
  return c;
}

}  // namespace tendril::validate
