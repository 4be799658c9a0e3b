#pragma once
// A validation case of `tendril validate`: a scene with a known answer, run at
// several resolutions with every applicable integrator and formulation, so
// the error it reaches can be weighed against the time it costs.
//
// Adding a case is adding one file, validate/cases/NAME.cpp (NAME a C++
// identifier), that defines `Case NAME_case()` in this namespace; the build
// finds it and registry.hpp lists it (file-name order). A sketch (the real
// one: cases/prestressed_ring.cpp; models shared with the tests go in
// benchmark_models.hpp):
//
//   Case ring_case() {
//     Case c;
//     c.name = "ring";
//     c.reference = "prestressed ring under out-of-plane loads: Barnes & Adriaenssens, 2.42 m";
//     c.resolution = "segments of the ring";
//     c.formulations = {"beam-6dof"};
//     c.segments = {16, 32, 64};
//     c.quick_segments = {16};
//     c.defaults.formulation = "beam-6dof";
//     c.defaults.segments = 16;            // defaults.solver: Leapfrog, kinetic
//     c.tolerance = 0.02;
//     c.run = [](const Setting& s) {
//       Model m;  // ... built with s.segments, in s.formulation
//       Solver solver(m);
//       solver.settings = s.solver;
//       Outcome out = relax(solver, 1e-3, 1'000'000);
//       out.error = relative_error(measured, exact);
//       return out;
//     };
//     return c;
//   }
//
// The registry checks each case on first use (defaults inside its lists,
// a positive tolerance, a unique name) and throws std::logic_error naming it.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "physics/solver.hpp"

namespace tendril::validate {

// The explicit integrators, then the constraint-based ones.
std::vector<Integrator> all_integrators();

// A case names its integrators (the matrix's columns): Leapfrog where it
// does not say, not the scene default "auto", which is Leapfrog or Newton.
inline SolverSettings leapfrog_settings() {
  SolverSettings s;
  s.integrator = Integrator::Leapfrog;
  return s;
}

// One point of a case's matrix.
struct Setting {
  std::string formulation;  // one of Case::formulations
  int segments = 0;         // one of Case::segments (what it counts: Case::resolution)
  SolverSettings solver = leapfrog_settings();  // integrator, damping, dt, ...
};

struct Outcome {
  double error = 0;  // relative, against the reference (0.01 = 1 %)
  std::uint64_t steps = 0;
  std::uint64_t force_evaluations = 0;
  double wall_ms = 0;  // relaxation only: building the model is not timed
  bool converged = false;
};

struct Case {
  std::string name;       // what `--case` selects and the plot is named after
  std::string reference;  // what the error is measured against, in a line
  std::string resolution;  // what `segments` counts, e.g. "segments over the strut"
  std::vector<std::string> formulations;
  // Every explicit and constraint-based integrator unless a case says otherwise.
  std::vector<Integrator> integrators = all_integrators();
  std::vector<int> segments;        // the full run
  // --quick (CI): every formulation and integrator at the coarsest, the
  // defaults at all (runner.hpp's matrix). Must hold the default's.
  std::vector<int> quick_segments;
  Setting defaults;        // Leapfrog, kinetic damping, the published resolution
  double tolerance = 0;    // relative error allowed under `defaults`
  // Builds the model for the setting, relaxes it and measures the error.
  // Deterministic: the same setting gives the same outcome (but for wall_ms).
  std::function<Outcome(const Setting&)> run;
};

// Relaxes with solver.run(tolerance, max_steps) and fills everything but the
// error: steps, force evaluations, wall time of the run, convergence.
Outcome relax(Solver& solver, double tolerance, std::uint64_t max_steps);

// Load steps, each relaxed from the last equilibrium: for every k, set(k)
// applies the load, relax(solver, tolerance, max_steps) runs, and error(k)
// measures; the outcome adds up the runs and keeps the largest error.
Outcome relax_load_steps(Solver& solver, const std::vector<int>& steps, const std::function<void(int)>& set,
                         const std::function<double(int)>& error, double tolerance, std::uint64_t max_steps);

// |measured / exact - 1|
double relative_error(double measured, double exact);

}  // namespace tendril::validate
