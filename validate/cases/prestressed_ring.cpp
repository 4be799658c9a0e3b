// Prestressed ring under out-of-plane loads (thesis 5.4.1.2, fig. 5.14;
// Adriaenssens & Barnes 2001): what Delta measures, the supports and why
// the 6-DOF ring answers the same question are in benchmark_models.hpp.
// The thesis reports Leapfrog 2.391 m and RK4 2.437 m against Barnes &
// Adriaenssens' 2.42 m for n = 8 (120 segments).
//
// Midpoint is left out: on this ring it did not converge within 2 million
// steps at 120 segments (measured: 17 s with 3 DOF, 99 s with 6 DOF), its
// fictitious masses being 48 times Leapfrog's (physics/solver.hpp) and the
// saddle's swing about the axis 2-4 soft. At n = 16 (240 segments) both
// formulations drop 2.407-2.412 m: the n = 8 figure is 0.5 % above the
// converged answer, and the reference is for n = 8.
#include <vector>

#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

Outcome run_ring(const Setting& setting) {
  PrestressedRing ring(setting.segments / 15, setting.formulation == "beam-6dof" ? 6 : 3);
  Solver solver(ring.m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-3, 2'000'000);  // 1 mN against 10 kN loads
  out.error = ring.error();
  return out;
}

}  // namespace

Case prestressed_ring_case() {
  Case c;
  c.name = "prestressed_ring";
  c.reference =
      "prestressed ring (10 m, quadrants n, 2n, 4n, 8n), 10 kN out of plane at nodes 1 and 3: Barnes & "
      "Adriaenssens' 2.42 m for n = 8; the larger error of the drops of nodes 1 and 3";
  c.resolution = "segments of the ring (15 n)";
  c.formulations = {"beam-3dof", "beam-6dof"};
  std::erase(c.integrators, Integrator::Midpoint);
  c.segments = {30, 60, 120};  // 240 costs a minute and moves the error away from the n = 8 reference
  c.quick_segments = {30, 120};
  c.defaults.formulation = "beam-3dof";
  c.defaults.segments = 120;  // n = 8, the published discretisation
  c.tolerance = 0.02;
  c.run = run_ring;
  return c;
}

}  // namespace tendril::validate
