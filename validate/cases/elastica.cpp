// Pin-ended strut of thesis 5.4.1.2 (Adriaenssens & Barnes 2001) at an end
// slope of 80 degrees, with 3-DOF spline beams and 6-DOF beams, against the
// exact inextensible elastica (the model: benchmark_models.hpp).
#include <algorithm>

#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

constexpr double kTheta0Deg = 80;

Outcome run_elastica(const Setting& setting) {
  Elastica strut(kTheta0Deg, setting.segments);  // even segments: a particle at mid-span
  if (setting.formulation == "beam-6dof") strut.m.set_beam_formulation(strut.beam, 6);
  Solver solver(strut.m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-3, 2'000'000);  // 1 mN against P = 12.8 kN
  out.error = std::max(strut.deflection_error(), strut.load_error(solver));
  return out;
}

}  // namespace

Case elastica_case() {
  Case c;
  c.name = "elastica";
  c.reference =
      "pin-ended strut, thesis 5.4.1.2, end slope 80 deg: exact elastica; "
      "max of mid-span deflection and axial load errors";
  c.resolution = "segments of the strut";
  c.formulations = {"beam-3dof", "beam-6dof"};
  c.segments = {16, 32, 64, 128};
  c.quick_segments = {16, 64};
  c.defaults.formulation = "beam-3dof";
  c.defaults.segments = 64;
  c.tolerance = 0.01;
  c.run = run_elastica;
  return c;
}

}  // namespace tendril::validate
