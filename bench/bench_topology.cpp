// The cost of one rule application including the next step, for every
// integrator, on the issue-18 net (bench_net.cpp's: s x s particles 1 m
// apart, bars on the grid edges, EA = 1e5 N, prestress 1e3 N, boundary
// locked, 1 N in -z on the interior). DESIGN principle 1: a change costs
// what it touches, so the step after it should cost within 2x of a steady
// step whatever the integrator - projective dynamics included, whose global
// matrix the change alters (projective.hpp follows it with a low-rank
// correction instead of a factorisation).
//
// Each model first steps until it is warm (the projective factorisation
// done), then alternates: a few steady steps (timed: the median is the
// steady step), one change (timed) and the step after it (timed). Changes
// (the net carries a few cables across cells for the second and third: its
// bars are a patch's, which no rule shortens one at a time):
//   cable     a new cable across a grid cell between two existing interior
//             particles (rule 6);
//   remove    one of those cables deleted (rule 7);
//   rest      one cable's rest length 1 % shorter;
//   particle  a new particle hung by a cable under an interior one (the
//             matrix grows by a row per axis);
//   passive   (only when asked for) an interior particle made passive, its
//             elements dormant (multi-resolution, thesis 5.5.2.3).
// --model beams takes a woven grid of spline beams instead (one beam along
// every row and one along every column through the same particles, EA =
// 1e5 N, EI = 10 N m^2): rest shortens a beam edge, particle inserts a
// particle on one (rule 13), and the hinges' copies follow the change too.
// --model beam6 takes the same grid with every beam 6 DOF (the 6-DOF plan
// follows the change), --model membrane the net's patch as a CST membrane
// (form-finding, two triangles a quad, 1 kN/m both ways) with the net's
// changes, which the CST plan must not derive again for.
// projective_refactor factors every change afresh: the cost before.
// The ratio is (change + step after) / steady step, medians over --reps.
// Thread CPU time, so that other processes on the machine do not count.
//
//   bench_topology [--sizes 16384,100000,1M] [--reps 5] [--changes cable,...] [--integrators leapfrog,...]
//                  [--model net|beams|beam6|membrane]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/huge_pages.hpp"
#include "bench_util.hpp"
#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using namespace tendril::bench;

namespace {

// The model a change is made in: the bar net, a woven grid of spline
// beams, the same grid of 6-DOF beams, or the net's patch as a CST membrane.
enum class Kind { Net, Beams, Beam6, Membrane };
const char* kind_name(Kind k) {
  return k == Kind::Net ? "net" : k == Kind::Beams ? "beams" : k == Kind::Beam6 ? "beam6" : "membrane";
}

struct Net {
  std::unique_ptr<Model> model;
  Kind kind = Kind::Net;
  bool beams() const { return kind == Kind::Beams || kind == Kind::Beam6; }
  int side = 0;
  std::vector<ParticleId> grid;
  std::vector<BlockId> rest, removed;  // the cables a change shortens or deletes, one per rep
  ParticleId at(int r, int c) const { return grid[std::size_t(r) * side + c]; }
};

// The rep-th change's cell (its lower left interior particle), spread over
// the net; `kind` shifts it so that different changes touch different places.
std::pair<int, int> place(int s, int rep, int kind) {
  return {1 + (7 + 13 * rep + 3 * kind) % (s - 3), 1 + (5 + 29 * rep + 11 * kind) % (s - 3)};
}

Net build_net(int s, int reps, Kind kind) {
  Net n;
  n.model = std::make_unique<Model>();
  n.kind = kind;
  n.side = s;
  Model& m = *n.model;
  n.grid.reserve(std::size_t(s) * s);
  for (int r = 0; r < s; ++r)
    for (int c = 0; c < s; ++c) {
      const ParticleId p = m.add_particle(Vec3(c, r, 0));
      n.grid.push_back(p);
      if (r == 0 || c == 0 || r == s - 1 || c == s - 1) m.set_lock(p, kLockTranslation);
      else m.set_load(p, Vec3(0, 0, -1));
    }
  if (n.beams()) {
    std::vector<ParticleId> line(std::size_t(s), 0);
    std::vector<BlockId> beams;
    for (int r = 0; r < s; ++r) {
      for (int c = 0; c < s; ++c) line[std::size_t(c)] = n.at(r, c);
      beams.push_back(m.add_beam(line, Section{1e5, 10, 0, 0}));
    }
    for (int c = 0; c < s; ++c) {
      for (int r = 0; r < s; ++r) line[std::size_t(r)] = n.at(r, c);
      beams.push_back(m.add_beam(line, Section{1e5, 10, 0, 0}));
    }
    if (kind == Kind::Beam6)
      for (BlockId b : beams) m.set_beam_formulation(b, 6);
  } else {
    const BlockId patch = m.add_quad_grid(n.grid, s, s, Section{1e5, 0, 1e3, 0});
    if (kind == Kind::Membrane) {  // bench_throughput's CST membrane: 2 triangles a quad, 1 kN/m both ways
      std::vector<Model::Triangle> triangles;
      for (int r = 0; r + 1 < s; ++r)
        for (int c = 0; c + 1 < s; ++c) {
          triangles.push_back({n.at(r, c), n.at(r, c + 1), n.at(r + 1, c + 1)});
          triangles.push_back({n.at(r + 1, c + 1), n.at(r + 1, c), n.at(r, c)});
        }
      Membrane film;
      film.mode = Membrane::FormFinding;
      film.sigma_warp = film.sigma_weft = 1e3;
      m.set_patch_formulation(patch, film, triangles);
    }
  }
  // Cables across cells, for the changes to shorten or delete (the net's
  // bars are a patch's, whose rest lengths no rule changes one at a time).
  for (int rep = 0; rep < reps; ++rep) {
    const auto [r, c] = place(s, rep, 1);
    n.rest.push_back(m.add_cable(n.at(r, c + 1), n.at(r + 1, c), Section{1e5, 0, 0, 0}));
    const auto [r2, c2] = place(s, rep, 2);
    n.removed.push_back(m.add_cable(n.at(r2, c2 + 1), n.at(r2 + 1, c2), Section{1e5, 0, 0, 0}));
  }
  return n;
}

struct Variant {
  std::string label;
  Integrator integrator;
  Integrator implicit = Integrator::VariationalImplicitEuler;  // Mixed's implicit phase
  bool low_rank = true;  // false: projective factors every change afresh (what it did before)
};

enum class Change { Cable, Remove, Rest, Particle, Passive };
const char* change_name(Change c) {
  return c == Change::Cable    ? "cable"
         : c == Change::Remove ? "remove"
         : c == Change::Rest   ? "rest"
         : c == Change::Particle ? "particle"
                                 : "passive";
}

// The rep-th change of its kind: a different place each time.
void apply(Net& n, Change kind, int rep) {
  Model& m = *n.model;
  const auto [r, c] = place(n.side, rep, 0);
  switch (kind) {
    case Change::Cable: m.add_cable(n.at(r, c), n.at(r + 1, c + 1), Section{1e5, 0, 0, 0}); break;
    case Change::Remove: m.delete_cable(n.removed[rep]); break;
    case Change::Rest: {
      const auto [r1, c1] = place(n.side, rep, 1);
      // the beam edge to the cable's right end's left on its row, else the cable
      const ParticleId a = n.at(r1, c1 + 1), b = n.beams() ? n.at(r1, c1) : n.at(r1 + 1, c1);
      m.set_rest_length(a, b, 0.99 * m.edge_rest_length(a, b));
      break;
    }
    case Change::Passive:  // multi-resolution (thesis 5.5.2.3): an interior particle and its elements leave the step
      m.set_passive(n.at(r, c), true);
      break;
    case Change::Particle: {
      if (n.beams()) {
        m.insert_particle(n.at(r, c), n.at(r, c + 1));
        break;
      }
      const ParticleId a = n.at(r, c);
      const ParticleId p = m.add_particle(m.particles.position[a] + Vec3(0, 0, -0.5));
      m.add_cable(a, p, Section{1e5, 0, 0, 0});
      break;
    }
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

struct Row {
  double steady = 0, rule = 0, after = 0;
  std::uint64_t factorizations = 0, updates = 0;
  std::string error;
};

Row measure(int side, Kind model, const Variant& v, Change kind, int reps) {
  Net net = build_net(side, reps, model);
  Solver solver(*net.model);
  solver.settings.integrator = v.integrator;
  solver.settings.mixed_implicit = v.implicit;
  solver.set_projective_low_rank(v.low_rank);
  if (v.integrator == Integrator::Mixed) solver.settings.mixed_switch = 1;  // the implicit phase at once
  Row row;
  try {
    for (int k = 0; k < 3; ++k) solver.step();  // warm: factored, caches filled
    const std::uint64_t f0 = solver.factorizations(), u0 = solver.projective_updates();
    std::vector<double> steady, rule, after;
    for (int rep = 0; rep < reps; ++rep) {
      for (int k = 0; k < 2; ++k) {
        const double t0 = thread_seconds();
        solver.step();
        steady.push_back(thread_seconds() - t0);
      }
      const double t0 = thread_seconds();
      apply(net, kind, rep);
      const double t1 = thread_seconds();
      solver.step();
      const double t2 = thread_seconds();
      rule.push_back(t1 - t0);
      after.push_back(t2 - t1);
    }
    row.steady = median(steady);
    row.rule = median(rule);
    row.after = median(after);
    row.factorizations = solver.factorizations() - f0;
    row.updates = solver.projective_updates() - u0;
  } catch (const std::exception& e) {
    row.error = e.what();
  }
  return row;
}

std::string ms(double s) { return fmt("%.2f ms", 1e3 * s); }

int usage(const char* argv0, int code) {
  std::fprintf(code ? stderr : stdout,
               "usage: %s [--sizes 16K,100K] [--reps N] [--changes cable,remove,rest,particle] [--integrators a,b,...]\n"
               "  --sizes        particle counts (K/M suffixes; the nearest square net; default 16384,100000), e.g. 1M\n"
               "  --reps         changes of each kind per integrator and size (default 5; medians)\n"
               "  --changes      cable, remove, rest, particle (default: these four), passive\n"
               "  --integrators  leapfrog, symplectic_euler, velocity_verlet, midpoint, rk4, vie, projective,\n"
               "                 projective_refactor (every change factored afresh: the cost before the low-rank\n"
               "                 correction), mixed (its implicit phase VIE), mixed_projective (default: all)\n"
               "  --model        net (default), beams (a woven grid of spline beams: rest shortens a beam edge,\n"
               "                 particle inserts a particle on one), beam6 (the same grid, 6-DOF beams) or\n"
               "                 membrane (the net's patch as a CST membrane, the net's changes)\n",
               argv0);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  tendril::restart_with_huge_pages(argv);  // as tendril itself runs (io/huge_pages.hpp)
  std::vector<std::size_t> sizes{16384, 100000};  // 128 x 128 (the 16K) and 316 x 316
  int reps = 5;
  Kind model = Kind::Net;
  std::vector<Change> changes{Change::Cable, Change::Remove, Change::Rest, Change::Particle};
  std::vector<Variant> variants;
  for (Integrator i : kIntegrators) variants.push_back({integrator_name(i), i});
  variants.push_back({"vie", Integrator::VariationalImplicitEuler});
  variants.push_back({"projective", Integrator::ProjectiveDynamics});
  variants.push_back({"projective_refactor", Integrator::ProjectiveDynamics, Integrator::VariationalImplicitEuler,
                      false});
  variants.push_back({"mixed", Integrator::Mixed});
  variants.push_back({"mixed_projective", Integrator::Mixed, Integrator::ProjectiveDynamics});
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
        return argv[++i];
      };
      if (a == "--sizes") sizes = parse_sizes(value());
      else if (a == "--reps") reps = std::max(1, std::stoi(value()));
      else if (a == "--model") {
        const std::string name = value();
        bool known = false;
        for (Kind k : {Kind::Net, Kind::Beams, Kind::Beam6, Kind::Membrane})
          if (name == kind_name(k)) model = k, known = true;
        if (!known) throw std::runtime_error("unknown model '" + name + "'");
      }
      else if (a == "--changes") {
        changes.clear();
        for (const std::string& name : split(value())) {
          if (name == "cable") changes.push_back(Change::Cable);
          else if (name == "remove") changes.push_back(Change::Remove);
          else if (name == "rest") changes.push_back(Change::Rest);
          else if (name == "particle") changes.push_back(Change::Particle);
          else if (name == "passive") changes.push_back(Change::Passive);
          else throw std::runtime_error("unknown change '" + name + "'");
        }
      } else if (a == "--integrators") {
        variants = chosen_by_label(variants, value());
      } else if (a == "-h" || a == "--help") return usage(argv[0], 0);
      else throw std::runtime_error("unknown option '" + a + "'");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_topology: %s\n", e.what());
    return usage(argv[0], 2);
  }

  std::puts("bench_topology: one rule application and the step after it, against a steady step (issue 18)");
  if (model == Kind::Beams || model == Kind::Beam6) {
    std::puts(model == Kind::Beam6 ? "  a woven grid of 6-DOF beams (Beam6 elements, rotations at every particle):"
                                   : "  a woven grid of spline beams:");
    std::puts("  a woven grid: s x s particles 1 m apart, a spline beam along every row and column (EA = 1e5 N,");
    std::puts("  EI = 10 N m^2), boundary locked, 1 N in -z on the interior; default settings");
    std::puts("  changes: cable = a new cable across a grid cell; remove = one such cable deleted;");
    std::puts("           rest = a beam edge's rest length -1 %; particle = a particle inserted on a beam edge (rule 13)");
  } else {
    if (model == Kind::Membrane)
      std::puts("  the net's patch as a CST membrane (form-finding, 2 triangles a quad, 1 kN/m both ways):");
    std::puts("  the issue-18 net: s x s particles 1 m apart, bars on the grid edges (EA = 1e5 N, prestress 1e3 N),");
    std::puts("  boundary locked, 1 N in -z on the interior; default settings (mixed: mixed_switch 1, implicit at once)");
    std::puts("  changes: cable = a new cable across a grid cell; remove = one such cable deleted;");
    std::puts("           rest = one such cable's rest length -1 %;");
    std::puts("           particle = a new particle on a cable (the matrix grows by a row per axis)");
  }
  std::printf("  medians of %d changes, thread CPU time; ratio = (change + step after) / steady step\n", reps);
  std::printf("  goal: ratio <= 2 for every integrator (DESIGN principle 1)%s\n\n",
#ifdef NDEBUG
              ""
#else
              "   ** WARNING: built without NDEBUG (not a Release build) **"
#endif
  );
  bool failed = false;
  for (std::size_t size : sizes) {
    const int side = std::max(4, int(std::lround(std::sqrt(double(size)))));
    std::printf("%d x %d (%d particles)\n", side, side, side * side);
    Table table({"integrator", "change", "steady step", "change", "step after", "ratio", "goal", "factorisations",
                 "updates"});
    for (const Variant& v : variants)
      for (Change c : changes) {
        const Row r = measure(side, model, v, c, reps);
        if (!r.error.empty()) {
          failed = true;
          table.add({v.label, change_name(c), "error: " + r.error.substr(0, 60), "", "", "", "", "", ""});
          continue;
        }
        const double ratio = (r.rule + r.after) / r.steady;
        const bool implicit_pd = v.integrator == Integrator::ProjectiveDynamics ||
                                 (v.integrator == Integrator::Mixed && v.implicit == Integrator::ProjectiveDynamics);
        table.add({v.label, change_name(c), ms(r.steady), ms(r.rule), ms(r.after), fmt("%.2f", ratio),
                   ratio <= 2 ? "ok" : "MISSED", implicit_pd ? fmt("%llu", (unsigned long long)r.factorizations) : "-",
                   implicit_pd ? fmt("%llu", (unsigned long long)r.updates) : "-"});
      }
    table.print();
    std::printf("load average %.2f\n\n", load_average());
  }
  return failed ? 1 : 0;
}
