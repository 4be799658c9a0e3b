// How the time to equilibrium grows with the model (issue 18): the
// prestressed net of bench_net (particles 1 m apart, a bar on every grid
// edge, EA = 1e5 N, prestress 1e3 N, boundary locked, 1 N in -z on every
// interior particle) at s x s particles, s = sqrt(size), solved from the
// flat net until the residual and motion() are below a tolerance relative
// to the nodal load (1e-3: 1e-3 N), as Solver::run judges it. Per size: the
// time (the thread's CPU time, and the wall time), the steps, the cost per
// step and, for Newton, its linear-algebra work; then the exponent of a
// least-squares fit t ~ n^p over the sizes that converged. Each size is
// solved --repeat times (default 3) and its median time counts: on a
// shared machine one slow run of the smallest size moved p by 0.2.
// Goal (issue 18): p <= 1.2, 160K particles in <= 2 s, 1M in <= 20 s.
//
//   bench_scaling [--sizes 10K,40K,160K,640K,1M] [--integrators newton,...] [--tolerance 1e-3] [--cap 120]
//                 [--repeat 3]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "io/huge_pages.hpp"
#include "bench_util.hpp"
#include "prestressed_net.hpp"
#include "model/model.hpp"
#include "physics/newton.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using namespace tendril::bench;

namespace {

constexpr double kLoad = 1.0;  // N per interior particle (prestressed_net.hpp)

struct Variant {
  std::string label;
  Integrator integrator;
  int iterations;
  int multigrid_rows = NewtonSystem::multigrid_rows;  // newton: axis blocks this large take the multigrid cycle
};

struct Outcome {
  bool converged = false;
  double cpu = 0, wall = 0, residual = 0;
  std::uint64_t steps = 0;
  Solver::NewtonWork work;
  std::string error;
};

Outcome solve(int side, const Variant& v, double tolerance, double cap) {
  auto model = prestressed_net(side);
  Solver solver(*model);
  solver.settings.integrator = v.integrator;
  solver.settings.vie_iterations = v.iterations;
  NewtonSystem::multigrid_rows = v.multigrid_rows;
  Outcome o;
  const double c0 = thread_seconds();
  const auto t0 = Clock::now();
  try {
    Solver::RunScope run(solver);  // a run to equilibrium: "auto" takes Newton's steps here
    for (;;) {
      solver.step();
      run.stepped();
      ++o.steps;
      if (std::max(solver.residual(), solver.motion()) < tolerance) {
        o.converged = true;
        break;
      }
      if (seconds_since(t0) > cap) break;
    }
  } catch (const std::exception& e) {
    o.error = e.what();
  }
  o.cpu = thread_seconds() - c0;
  o.wall = seconds_since(t0);
  o.residual = solver.residual();
  o.work = solver.newton_work();
  return o;
}

// p of t = c n^p, least squares on the logarithms; NaN for fewer than two points.
double fitted_exponent(const std::vector<double>& n, const std::vector<double>& t) {
  if (n.size() < 2) return std::nan("");
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < n.size(); ++k) {
    const double x = std::log(n[k]), y = std::log(t[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double m = double(n.size());
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

int usage(const char* argv0, int code) {
  std::fprintf(code ? stderr : stdout,
               "usage: %s [--sizes 10K,40K,160K,640K,1M] [--integrators newton,projective1,...] [--tolerance 1e-3]\n"
               "          [--cap SECONDS] [--multigrid-rows ROWS] [--repeat N]\n"
               "  --sizes        particles (an s x s net, s = round(sqrt(size)))\n"
               "  --integrators  newton (default), auto (tendril's default: newton's steps here), newton_factors (no multigrid),\n"
               "                 leapfrog, projective (4 iterations per step,\n"
               "                 as before vie_iterations = 0 became the default), projective1 (one iteration per step)\n"
               "  --tolerance    residual relative to the nodal load of 1 N (default 1e-3)\n"
               "  --cap          wall-time limit of each run (default 120 s)\n"
               "  --multigrid-rows  newton: axis blocks this large or larger take the multigrid cycle (default 4000)\n"
               "  --repeat       runs of each size, the median timed (default 3)\n",
               argv0);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  tendril::restart_with_huge_pages(argv);  // as tendril itself runs (io/huge_pages.hpp)
  std::vector<std::size_t> sizes{10000, 40000, 160000, 640000, 1000000};
  double tolerance = 1e-3, cap = 120;
  int repeat = 3;
  std::vector<Variant> known{{"newton", Integrator::Newton, 4},
                                   {"auto", Integrator::Auto, 0},
                                   {"newton_factors", Integrator::Newton, 4, std::numeric_limits<int>::max()},
                                   {"leapfrog", Integrator::Leapfrog, 4},
                                   {"projective", Integrator::ProjectiveDynamics, 4},
                                   {"projective1", Integrator::ProjectiveDynamics, 1}};
  std::vector<Variant> variants;
  std::string chosen = "newton";
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
        return argv[++i];
      };
      if (a == "--sizes") sizes = parse_sizes(value());
      else if (a == "--tolerance") tolerance = std::stod(value());
      else if (a == "--cap") cap = std::stod(value());
      else if (a == "--repeat") repeat = std::max(1, std::stoi(value()));
      else if (a == "--multigrid-rows") known[0].multigrid_rows = std::stoi(value());
      else if (a == "--integrators") chosen = value();
      else if (a == "-h" || a == "--help") return usage(argv[0], 0);
      else throw std::runtime_error("unknown option '" + a + "'");
    }
    variants = chosen_by_label(known, chosen);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_scaling: %s\n", e.what());
    return usage(argv[0], 2);
  }

  std::puts("bench_scaling: time to equilibrium of the issue-18 net as it grows (1 m spacing, EA = 1e5 N,");
  std::puts("  prestress 1e3 N, boundary locked, 1 N in -z per interior particle), from the flat net until the");
  std::printf("  residual and motion() are below %.0e of the nodal load (%.0e N); one thread; cap %.0f s per run%s\n",
              tolerance, tolerance * kLoad, cap,
#ifdef NDEBUG
              ""
#else
              "   ** WARNING: built without NDEBUG (not a Release build) **"
#endif
  );
  std::printf("  time: the thread's CPU time (the wall time beside it: the machine is shared), the median of %d\n"
              "    runs of each size (cpu range: the fastest and slowest)\n",
              repeat);
  std::printf("  newton: axis blocks of %d rows or more take the multigrid cycle, smaller ones their factors\n",
              NewtonSystem::multigrid_rows);
  std::puts("    (newton_factors: the factors at every size); preconditioners: the factorisations or hierarchies built");
  std::puts("  goal (issue 18): exponent <= 1.2, 160K particles in <= 2 s, 1M in <= 20 s\n");
  bool failed = false;
  for (const Variant& v : variants) {
    std::printf("%s\n", v.label.c_str());
    Table table({"particles", "side", "cpu s", "cpu range s", "wall s", "steps", "ms/step", "ns/particle-step", "preconditioners",
                 "CG iterations", "residual N", "note"});
    std::vector<double> ns, ts;
    std::string met160 = "not run", met1M = "not run";
    for (std::size_t size : sizes) {
      const int side = int(std::lround(std::sqrt(double(size))));
      const double n = double(side) * side;
      std::vector<Outcome> runs;
      for (int r = 0; r < repeat; ++r) {
        runs.push_back(solve(side, v, tolerance * kLoad, cap));
        if (!runs.back().error.empty() || !runs.back().converged) break;  // a failure is not timed again
      }
      std::sort(runs.begin(), runs.end(), [](const Outcome& a, const Outcome& b) { return a.cpu < b.cpu; });
      const Outcome& o = runs[runs.size() / 2];
      std::string note = o.error.empty() ? (o.converged ? "" : "not converged (cap)") : "error: " + o.error.substr(0, 60);
      failed |= !o.error.empty();
      if (o.converged) ns.push_back(n), ts.push_back(o.cpu);
      if (size == 160000) met160 = o.converged && o.cpu <= 2 ? "met" : "missed";
      if (size == 1000000) met1M = o.converged && o.cpu <= 20 ? "met" : "missed";
      const bool newton = v.integrator == Integrator::Newton || v.integrator == Integrator::Auto;
      table.add({fmt("%.0f", n), fmt("%d", side), fmt("%.3f", o.cpu),
                 fmt("%.3f-%.3f", runs.front().cpu, runs.back().cpu), fmt("%.3f", o.wall),
                 fmt("%llu", (unsigned long long)o.steps), fmt("%.2f", 1e3 * o.cpu / double(std::max<std::uint64_t>(o.steps, 1))),
                 fmt("%.0f", 1e9 * o.cpu / double(std::max<std::uint64_t>(o.steps, 1)) / n),
                 newton ? fmt("%llu", (unsigned long long)o.work.factorizations) : "-",
                 newton ? fmt("%llu", (unsigned long long)o.work.iterations) : "-", fmt("%.2e", o.residual), note});
      std::fflush(stdout);
    }
    table.print();
    const double p = fitted_exponent(ns, ts);
    std::printf("fitted exponent (cpu time ~ n^p over %zu converged sizes): p = %.2f  [goal <= 1.2: %s]\n", ns.size(),
                p, std::isnan(p) ? "n/a" : p <= 1.2 ? "met" : "missed");
    std::printf("160K <= 2 s: %s; 1M <= 20 s: %s; load average %.2f\n\n", met160.c_str(), met1M.c_str(),
                load_average());
  }
  return failed ? 1 : 0;
}
