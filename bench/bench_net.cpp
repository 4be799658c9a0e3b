// Time to equilibrium of the issue-18 net for every integrator, "auto" (the
// default, which takes Newton's steps for this run) first: s x s
// particles 1 m apart, a bar on every grid edge (EA = 1e5 N, prestress
// 1e3 N), the boundary locked, 1 N in -z on every interior particle. Each
// integrator starts from the flat net and steps until the residual (the
// largest force on a free axis) and motion() (the force that would stop the
// fastest particle in one step) are both below 1e-3 N, then 1e-6 N, the
// criterion of Solver::run. Wall time from the first step, so the
// projective factorisation counts; the model is built before the clock
// starts; beside it the solving thread's CPU time, which a machine shared
// with other work inflates less. A run that does not get there within --cap
// seconds reads "> cap".
//
//   bench_net [--sides 128,500] [--cap 60] [--threads 1] [--integrators leapfrog,projective,...]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "io/huge_pages.hpp"
#include "bench_util.hpp"
#include "prestressed_net.hpp"
#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using namespace tendril::bench;

namespace {

struct Variant {
  std::string label;
  Integrator integrator;
  int iterations;  // vie_iterations (constraint-based solvers; 0: the solver chooses)
};

struct Reached {
  double seconds = -1;  // -1: not within the cap
  double cpu = 0;       // the thread's CPU seconds meanwhile (a loaded machine inflates the wall time)
  std::uint64_t steps = 0;
};

struct Outcome {
  Reached coarse, fine;  // 1e-3 N, 1e-6 N
  double last_residual = 0;
  std::string error;
};

Outcome solve(int side, const Variant& v, double cap, int threads) {
  auto model = prestressed_net(side);
  Solver solver(*model);
  solver.settings.integrator = v.integrator;
  solver.settings.vie_iterations = v.iterations;
  solver.settings.threads = threads;
  Outcome o;
  const auto t0 = Clock::now();
  const double c0 = thread_seconds();
  try {
    Solver::RunScope run(solver);  // a run to equilibrium: "auto" chooses Newton here
    for (std::uint64_t steps = 1;; ++steps) {
      solver.step();
      run.stepped();
      const double t = seconds_since(t0);
      const double worst = std::max(solver.residual(), solver.motion());
      if (o.coarse.seconds < 0 && worst < 1e-3) o.coarse = {t, thread_seconds() - c0, steps};
      if (worst < 1e-6) {
        o.fine = {t, thread_seconds() - c0, steps};
        break;
      }
      if (t > cap) break;
    }
  } catch (const std::exception& e) {
    o.error = e.what();
  }
  o.last_residual = solver.residual();
  return o;
}

std::string cell(const Reached& r, double cap) {
  return r.seconds < 0 ? fmt("> %.0f s", cap) : fmt("%.3f s", r.seconds);
}
std::string cpu_cell(const Reached& r) { return r.seconds < 0 ? "-" : fmt("%.3f s", r.cpu); }
std::string steps_cell(const Reached& r) { return r.seconds < 0 ? "-" : fmt("%llu", (unsigned long long)r.steps); }

int usage(const char* argv0, int code) {
  std::fprintf(code ? stderr : stdout,
               "usage: %s [--sides 128,500] [--cap SECONDS] [--threads N] [--integrators a,b,...]\n"
               "  --sides        grid sides (s x s particles; default 128,500)\n"
               "  --cap          wall-time limit of each run (default 60 s)\n"
               "  --threads      solver threads (default 1)\n"
               "  --integrators  auto (the default: newton here), leapfrog, symplectic_euler, velocity_verlet, midpoint, rk4, vie, projective\n"
               "                 (vie_iterations = 0, the default: the solver chooses), projective1 and\n"
               "                 projective4 (1 and 4 local-global iterations per step), mixed, newton\n"
               "                 (default: all)\n",
               argv0);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  tendril::restart_with_huge_pages(argv);  // as tendril itself runs (io/huge_pages.hpp)
  std::vector<int> sides{128, 500};
  double cap = 60;
  int threads = 1;
  std::vector<Variant> variants;
  variants.push_back({"auto", Integrator::Auto, 0});  // the default
  for (Integrator i : kIntegrators) variants.push_back({integrator_name(i), i, 0});
  variants.push_back({"vie", Integrator::VariationalImplicitEuler, 0});
  variants.push_back({"projective", Integrator::ProjectiveDynamics, 0});  // the solver chooses (adaptive)
  variants.push_back({"projective1", Integrator::ProjectiveDynamics, 1});
  variants.push_back({"projective4", Integrator::ProjectiveDynamics, 4});
  variants.push_back({"mixed", Integrator::Mixed, 0});
  variants.push_back({"newton", Integrator::Newton, 0});
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
        return argv[++i];
      };
      if (a == "--sides") {
        sides.clear();
        for (const std::string& s : split(value())) sides.push_back(std::stoi(s));
      } else if (a == "--cap") cap = std::stod(value());
      else if (a == "--threads") threads = std::stoi(value());
      else if (a == "--integrators") {
        variants = chosen_by_label(variants, value());
      } else if (a == "-h" || a == "--help") return usage(argv[0], 0);
      else throw std::runtime_error("unknown option '" + a + "'");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_net: %s\n", e.what());
    return usage(argv[0], 2);
  }

  std::puts("bench_net: time to equilibrium of the issue-18 net, every integrator from the flat net");
  std::puts("  s x s particles 1 m apart, bars on the grid edges (EA = 1e5 N, prestress 1e3 N), boundary locked,");
  std::puts("  1 N in -z on every interior particle; kinetic damping, default settings (dt = 1, fictitious masses)");
  std::puts("  reached: residual (largest force on a free axis) and motion() both below the tolerance, as Solver::run");
  std::printf("  wall time from the first step (factorisations included), and the solving thread's CPU time,\n"
              "  after one untimed solve of the default's (the process's first touch of its memory);\n"
              "  cap %.0f s per run; %d thread(s)%s\n\n", cap,
              threads,
#ifdef NDEBUG
              ""
#else
              "   ** WARNING: built without NDEBUG (not a Release build) **"
#endif
  );
  bool failed = false;
  for (int side : sides) {
    std::printf("%d x %d (%d particles)\n", side, side, side * side);
    Table table({"integrator", "to 1e-3 N", "cpu", "steps", "to 1e-6 N", "cpu", "steps", "last residual N", "note"});
    // One untimed solve first (the default's, seconds at most on this net):
    // the process's first touch of its memory would otherwise fall on the
    // first row alone (0.02-0.03 s of the 128 x 128 net's 0.08 s).
    solve(side, Variant{"auto", Integrator::Auto, 0}, cap, threads);
    for (const Variant& v : variants) {
      const Outcome o = solve(side, v, cap, threads);
      std::string note = o.error.empty() ? "" : "error: " + o.error.substr(0, 60);
      if (v.integrator == Integrator::Auto) note = note.empty() ? "default" : note;
      failed |= !o.error.empty();
      table.add({v.label, cell(o.coarse, cap), cpu_cell(o.coarse), steps_cell(o.coarse), cell(o.fine, cap),
                 cpu_cell(o.fine), steps_cell(o.fine),
                 fmt("%.2e", o.last_residual), note});
    }
    table.print();
    std::printf("load average %.2f\n\n", load_average());
  }
  return failed ? 1 : 0;
}
