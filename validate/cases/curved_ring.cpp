// A thin ring built curved at rest (3 DOF, rest = "current";
// benchmark_models.hpp) squeezed by P = 1 mN along a diameter: the diameter
// shortens by delta = P R^3 / EI (pi/4 - 2/pi) (Roark, thin ring under a
// diametral load). The error is |measured / delta - 1|.
#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

Outcome run_ring(const Setting& setting) {
  SqueezedRing ring(setting.segments);
  Solver solver(ring.m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-9, 2'000'000);  // 1e-6 of P
  out.error = ring.error();
  return out;
}

}  // namespace

Case curved_ring_case() {
  Case c;
  c.name = "curved_ring";
  c.reference = "ring curved at rest (3 DOF) under a diametral load: delta = P R^3 / EI (pi/4 - 2/pi)";
  c.resolution = "segments of the ring";
  c.formulations = {"beam-3dof"};
  c.segments = {32, 64, 128};
  c.quick_segments = {32, 64};
  c.defaults.formulation = "beam-3dof";
  c.defaults.segments = 64;
  c.tolerance = 0.01;
  c.run = run_ring;
  return c;
}

}  // namespace tendril::validate
