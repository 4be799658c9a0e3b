// The constraint-based solvers against Leapfrog: steps, local steps (force
// evaluations), factorisations and wall time to each validation case's own
// tolerance, with its default resolution; then the largest stable time step
// of every integrator on a hanging chain with physical masses.
//
//   bench_constraint_solvers [--case NAME]...
#include <cstring>
#include <string>
#include <vector>

#include "io/huge_pages.hpp"
#include "bench_util.hpp"
#include "registry.hpp"
#include "runner.hpp"

using namespace tendril;
using namespace tendril::bench;

namespace {

struct Variant {
  std::string name;
  Integrator integrator;
  Integrator implicit = Integrator::VariationalImplicitEuler;
  int iterations = 4;
};

const std::vector<Variant> kVariants = {
    {"leapfrog", Integrator::Leapfrog},
    {"vie x1", Integrator::VariationalImplicitEuler, Integrator::VariationalImplicitEuler, 1},
    {"vie x4", Integrator::VariationalImplicitEuler},
    {"projective x1", Integrator::ProjectiveDynamics, Integrator::VariationalImplicitEuler, 1},
    {"projective x4", Integrator::ProjectiveDynamics},
    {"mixed (vie)", Integrator::Mixed},
    {"mixed (projective)", Integrator::Mixed, Integrator::ProjectiveDynamics},
};

void compare(const validate::Case& c) {
  Table t({"case", "solver", "segments", "error %", "steps", "evaluations", "wall ms", ""});
  for (const Variant& v : kVariants) {
    validate::Setting s = c.defaults;
    s.solver.integrator = v.integrator;
    s.solver.mixed_implicit = v.implicit;
    s.solver.vie_iterations = v.iterations;
    try {
      const validate::Outcome o = c.run(s);
      t.add({c.name, v.name, fmt("%d", s.segments), fmt("%.3g", 100 * o.error), fmt("%llu", (unsigned long long)o.steps),
             fmt("%llu", (unsigned long long)o.force_evaluations), fmt("%.3g", o.wall_ms),
             o.converged ? "" : "not converged"});
    } catch (const std::exception& e) {
      t.add({c.name, v.name, fmt("%d", s.segments), "-", "-", "-", "-", e.what()});
    }
  }
  t.print();
  std::puts("");
}

// A chain of 40 cables, 12 m over a 10 m span, 2 kg/m (0.6 kg per particle),
// EA = 100 kN: k = EA / L0 = 333 kN/m, so Leapfrog's bound is
// 2 / sqrt(4 k / m) = 1.34 ms. Stable: 20000 steps without a non-finite force
// and with the residual below its start.
bool stable(Integrator integrator, double dt) {
  Model m;
  m.gravity = Vec3(0, 0, -9.81);
  std::vector<ParticleId> ps;
  const int n = 40;
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n;
    ps.push_back(m.add_particle(Vec3(10 * s, 0, -2 * s * (1 - s))));
  }
  for (int i = 0; i < n; ++i) m.add_cable(ps[i], ps[i + 1], Section{1e5, 0, 0, 2}, 12.0 / n);
  m.set_lock(ps.front(), kLockTranslation);
  m.set_lock(ps.back(), kLockTranslation);
  Solver s(m);
  s.settings.integrator = integrator;
  s.settings.mass_mode = MassMode::Physical;
  s.settings.dt = dt;
  try {
    s.step();
    const double start = s.residual();
    const RunResult r = s.run(1e-6, 20'000);
    return r.converged || r.residual < start;
  } catch (const NumericalError&) {
    return false;
  }
}

void largest_stable_steps() {
  Table t({"integrator", "largest stable dt [ms]", "x Leapfrog's bound 1.34 ms"});
  // Mixed is left out: its explicit phase is Leapfrog's.
  std::vector<Integrator> all(kIntegrators.begin(), kIntegrators.end());
  all.push_back(Integrator::VariationalImplicitEuler);
  all.push_back(Integrator::ProjectiveDynamics);
  for (Integrator i : all) {
    const double cap = 10;  // s
    double lo = 1e-5, hi = cap;
    std::string label;
    if (stable(i, hi)) {
      lo = hi;
      label = ">= ";
    } else {
      for (int k = 0; k < 30 && hi / lo > 1.01; ++k) {
        const double mid = std::sqrt(lo * hi);
        (stable(i, mid) ? lo : hi) = mid;
      }
    }
    t.add({integrator_name(i), label + fmt("%.4g", 1e3 * lo), fmt("%.3g", lo / 1.34e-3)});
  }
  t.print();
}

}  // namespace

int main(int argc, char** argv) {
  tendril::restart_with_huge_pages(argv);  // as tendril itself runs (io/huge_pages.hpp)
  std::vector<std::string> names;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--case") == 0 && k + 1 < argc) names.push_back(argv[++k]);
    else {
      std::fprintf(stderr, "usage: bench_constraint_solvers [--case NAME]...\n");
      return 2;
    }
  }
  if (names.empty()) names = {"elastica", "catenary", "catenoid", "two_bar_truss", "end_moment_circle"};
  std::puts("To each case's tolerance at its default resolution; fictitious masses (vie_dt = 100 dt).\n");
  for (const std::string& n : names) {
    const validate::Case* c = validate::find_case(n);
    if (!c) {
      std::fprintf(stderr, "bench_constraint_solvers: no case '%s'\n", n.c_str());
      return 2;
    }
    compare(*c);
  }
  std::puts("Hanging chain, physical masses (mass_mode = \"physical\", vie_dt = dt):");
  largest_stable_steps();
}
