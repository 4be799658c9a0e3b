// Solver throughput: particle-iterations per second of Solver::step()
// (Leapfrog, kinetic damping) on a bar net and on a grid of 3-DOF beams, and
// the memory the model takes per particle. DESIGN "Targets": >= 30 million
// particle-iterations per second on one core for the bar net.
// First, the bar net against the memory bound (issue 18): a STREAM triad
// (a = b + s c, 24 bytes per element, best of 10) measures the bandwidth on
// 1 and 2 threads, Solver::fused_step_bytes() gives the bytes a step moves,
// their quotient the particle-iterations per second memory allows; the
// fraction is tendril's share of that bound, all in the same run.
//
//   bench_throughput [--sizes 10K,100K,1M] [--seconds 1.5] [--threads 1,2] [--bound-only]
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "io/huge_pages.hpp"
#include "bench_util.hpp"
#include "model/model.hpp"
#include "multires.hpp"
#include "physics/solver.hpp"
#include "physics/workers.hpp"

using namespace tendril;
using namespace tendril::bench;

namespace {


// Resident set size now, after handing freed heap back to the system so that
// transient build scratch does not count as model memory.
long resident_bytes() {
  malloc_trim(0);
  std::ifstream statm("/proc/self/statm");
  long pages_total = 0, pages_resident = 0;
  statm >> pages_total >> pages_resident;
  return pages_resident * sysconf(_SC_PAGESIZE);
}


// --- models ------------------------------------------------------------------

constexpr double kSpacing = 1.0;                      // m between grid particles
constexpr double kLoad = 1.0;                         // N out of plane, per interior particle
const Section kNetSection{1e5, 0, 1e3, 0};            // EA, -, prestress, -
const Section kBeamSection{1e6, 1e2, 0, 0};           // EA, EI, -, -

// An s x s planar grid of particles with its boundary locked and every
// interior particle loaded out of plane. Returns grid[r * s + c].
std::vector<ParticleId> supported_grid(Model& m, int s) {
  std::vector<ParticleId> grid;
  grid.reserve(std::size_t(s) * s);
  for (int r = 0; r < s; ++r)
    for (int c = 0; c < s; ++c) {
      ParticleId p = m.add_particle(Vec3(c * kSpacing, r * kSpacing, 0));
      grid.push_back(p);
      if (r == 0 || c == 0 || r == s - 1 || c == s - 1) m.set_lock(p, kLockTranslation);
      else m.set_load(p, Vec3(0, 0, -kLoad));
    }
  return grid;
}

void build_bar_net(Model& m, int s) { m.add_quad_grid(supported_grid(m, s), s, s, kNetSection); }

// Multi-resolution (thesis 5.5.2.3): the same net with a fraction of its
// rows passive (the last ones). Particle-iterations count the active
// particles only, so the figure shows what a passive particle and its
// elements cost: nothing, if it stays near the all-active figure.
double g_passive_fraction = 0.9;
void build_passive_net(Model& m, int s) {
  std::vector<ParticleId> grid = supported_grid(m, s);
  m.add_quad_grid(grid, s, s, kNetSection);
  const int active_rows = std::max(2, int(std::lround((1 - g_passive_fraction) * s)));
  for (int r = active_rows; r < s; ++r)
    for (int c = 0; c < s; ++c) m.set_passive(grid[r * s + c], true);
}

// Multi-resolution patch (thesis 5.5.2.3) in coarse mode: a coarse net of
// (s - 1) / 4 quads a side with its factor-4 fine patch, whose ~94 % fine-only
// particles are passive; and the coarse net alone, the active-only cost.
int coarse_side(int s) { return std::max(2, (s - 1) / 4); }
BlockId build_coarse_only_net(Model& m, int s) {
  const int n = coarse_side(s) + 1;
  return m.add_quad_grid(supported_grid(m, n), n, n, kNetSection);
}
void build_coarse_net(Model& m, int s) { build_coarse_only_net(m, s); }
void build_multires_net(Model& m, int s) { meshing::multires_patch(m, build_coarse_only_net(m, s), 4); }

// A woven grid: one beam along every row and one along every column, every
// particle a crossing shared by two beams (a flat gridshell).
void build_beam_grid(Model& m, int s) {
  std::vector<ParticleId> grid = supported_grid(m, s);
  std::vector<ParticleId> line(s);
  for (int r = 0; r < s; ++r) {
    for (int c = 0; c < s; ++c) line[c] = grid[r * s + c];
    m.add_beam(line, kBeamSection);
  }
  for (int c = 0; c < s; ++c) {
    for (int r = 0; r < s; ++r) line[r] = grid[r * s + c];
    m.add_beam(line, kBeamSection);
  }
}

// The same woven grid with every beam switched to 6 DOF (eq. 3.44-3.50):
// Beam6 elements and rotations at every particle.
void build_beam6_grid(Model& m, int s) {
  std::vector<ParticleId> grid = supported_grid(m, s);
  std::vector<ParticleId> line(s);
  std::vector<BlockId> beams;
  for (int r = 0; r < s; ++r) {
    for (int c = 0; c < s; ++c) line[c] = grid[r * s + c];
    beams.push_back(m.add_beam(line, kBeamSection));
  }
  for (int c = 0; c < s; ++c) {
    for (int r = 0; r < s; ++r) line[r] = grid[r * s + c];
    beams.push_back(m.add_beam(line, kBeamSection));
  }
  for (BlockId b : beams) m.set_beam_formulation(b, 6);
}

// The bar net's patch switched to CST form-finding (thesis 5.5.2.2): two
// triangles per quad, 1 kN/m in warp and weft; only the boundary keeps bars.
void build_cst_membrane(Model& m, int s) {
  std::vector<ParticleId> grid = supported_grid(m, s);
  const BlockId patch = m.add_quad_grid(grid, s, s, kNetSection);
  std::vector<Model::Triangle> triangles;
  for (int r = 0; r + 1 < s; ++r)
    for (int c = 0; c + 1 < s; ++c) {
      const ParticleId a = grid[r * s + c], b = grid[r * s + c + 1], cc = grid[(r + 1) * s + c + 1],
                       d = grid[(r + 1) * s + c];
      triangles.push_back({a, b, cc});
      triangles.push_back({cc, d, a});
    }
  Membrane film;
  film.mode = Membrane::FormFinding;
  film.sigma_warp = film.sigma_weft = 1e3;
  m.set_patch_formulation(patch, film, triangles);
}

struct Case {
  const char* name;
  void (*build)(Model&, int);
  const char* label = "";  // its name in --cases
};

struct Measurement {
  std::size_t particles = 0, bars = 0, hinges = 0, awake_bars = 0, capacity = 0;
  double build_s = 0;
  long rss_growth = 0;
  std::uint64_t steps = 0;
  double seconds = 0;       // CPU time of the calling thread (one thread)
  double wall_seconds = 0;  // wall time (the measure with threads)
  double step_bytes = 0;    // Solver::fused_step_bytes()
  std::string check;
};

// STREAM's triad a = b + s c over arrays far beyond the caches, split into
// equal contiguous parts over `threads` threads of the solver's pool: the
// best of 10 in GB/s (24 bytes per element, write-allocate not counted).
double triad_gbs(unsigned threads) {
  const std::size_t n = std::size_t(1) << 24;  // 128 MB per array
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  Workers pool;
  double best = 1e300;
  for (int rep = 0; rep < 10; ++rep) {
    const auto t0 = Clock::now();
    pool.run(threads, [&](unsigned t) {
      const std::size_t begin = n * t / threads, end = n * (t + 1) / threads;
      double* __restrict pa = a.data();
      const double* __restrict pb = b.data();
      const double* __restrict pc = c.data();
      for (std::size_t i = begin; i < end; ++i) pa[i] = pb[i] + 3.0 * pc[i];
    });
    best = std::min(best, seconds_since(t0));
  }
  if (a[n / 2] != 7.0) std::puts("triad: wrong result");
  return 24.0 * double(n) / best / 1e9;
}

Measurement measure(const Case& c, std::size_t requested, double target_seconds, int threads = 1) {
  Measurement r;
  const int side = std::max(3, static_cast<int>(std::lround(std::sqrt(double(requested)))));
  const long rss0 = resident_bytes();
  auto t0 = Clock::now();
  auto model = std::make_unique<Model>();
  c.build(*model, side);
  r.build_s = seconds_since(t0);
  r.rss_growth = resident_bytes() - rss0;
  r.particles = model->particles.integrated.size();  // passive particles are not integrated
  r.bars = model->bars.size();
  r.awake_bars = model->bars.awake;
  r.capacity = model->particle_count();
  r.hinges = model->hinges.size();

  Solver solver(*model);
  solver.settings.damping = Damping::Kinetic;
  solver.settings.threads = threads;
  for (int i = 0; i < 5; ++i) solver.step();  // warm-up: caches, first kinetic peaks
  // Calibrate on at least 0.2 s of steps, then time ~target_seconds.
  std::uint64_t probe = 0;
  double probed = 0;
  for (std::uint64_t batch = 1; probed < 0.2; batch *= 2) {
    t0 = Clock::now();
    for (std::uint64_t i = 0; i < batch; ++i) solver.step();
    probed += seconds_since(t0);
    probe += batch;
  }
  const double per_step = probed / probe;
  r.steps = static_cast<std::uint64_t>(std::clamp(std::ceil(target_seconds / per_step), 5.0, 1e7));

  const double cpu0 = thread_seconds();
  t0 = Clock::now();
  for (std::uint64_t i = 0; i < r.steps; ++i) solver.step();
  r.seconds = thread_seconds() - cpu0;
  r.wall_seconds = seconds_since(t0);
  r.step_bytes = solver.fused_step_bytes();
  if (!std::isfinite(solver.residual())) r.check = "residual is not finite";
  else r.check = model->check();
  return r;
}

int usage(const char* argv0, int code) {
  std::fprintf(code ? stderr : stdout,
               "usage: %s [--sizes 10K,100K,1M] [--seconds S] [--threads 1,2] [--bound-only] [--cases NAMES]\n"
               "  --sizes    particle counts (K/M suffixes; each becomes the nearest square grid)\n"
               "  --seconds  target duration of each timed run (default 1.5)\n"
               "  --threads  thread counts of the memory-bound table (default 1,2), and with --cases of a table\n"
               "             of those cases on threads (wall time)\n"
               "  --bound-only  the memory-bound table alone\n"
               "  --cases    only the case table, for these cases (e.g. beam6,cst: bar, beam, beam6, cst)\n",
               argv0);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  tendril::restart_with_huge_pages(argv);  // as tendril itself runs (io/huge_pages.hpp)
  std::vector<std::size_t> sizes{10'000, 100'000, 1'000'000};
  double target_seconds = 1.5;
  std::vector<std::size_t> thread_counts{1, 2};
  bool bound_only = false;
  std::vector<std::string> only_cases;  // --cases: the case table alone, for these
  try {
    for (int i = 1; i < argc; ++i) {
      std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
        return argv[++i];
      };
      if (a == "--sizes") sizes = parse_sizes(value());
      else if (a == "--seconds") target_seconds = std::stod(value());
      else if (a == "--bound-only") bound_only = true;
      else if (a == "--cases") only_cases = split(value());
      else if (a == "--threads") {
        thread_counts = parse_sizes(value());
        for (std::size_t t : thread_counts)
          if (t > 64) throw std::runtime_error("--threads: at most 64");
      }
      else if (a == "-h" || a == "--help") return usage(argv[0], 0);
      else throw std::runtime_error("unknown option '" + a + "'");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_throughput: %s\n", e.what());
    return usage(argv[0], 2);
  }

  const std::vector<Case> all_cases{{"bar net", build_bar_net, "bar"},
                                    {"beam grid", build_beam_grid, "beam"},
                                    {"beam6 grid", build_beam6_grid, "beam6"},
                                    {"cst membrane", build_cst_membrane, "cst"}};
  std::vector<Case> cases;
  for (const std::string& label : only_cases) {
    auto it = std::find_if(all_cases.begin(), all_cases.end(), [&](const Case& c) { return label == c.label; });
    if (it == all_cases.end()) {
      std::fprintf(stderr, "bench_throughput: unknown case '%s'\n", label.c_str());
      return usage(argv[0], 2);
    }
    cases.push_back(*it);
  }
  if (only_cases.empty()) cases = all_cases;
  std::puts("bench_throughput: Solver::step(), Leapfrog + kinetic damping");
  std::puts("  bar net   : s x s planar quad grid patch (add_quad_grid), bars EA=1e5 N, prestress 1e3 N;");
  std::puts("              boundary locked, 1 N out-of-plane load on every interior particle");
  std::puts("  beam grid : s beams along x and s along y through an s x s grid, every particle a crossing");
  std::puts("              shared by two 3-DOF spline beams (EA=1e6 N, EI=1e2 N m^2); same supports and load");
  std::puts("  beam6 grid: the beam grid with every beam 6 DOF (Beam6 elements, rotations at every particle)");
  std::puts("  cst membrane: the bar net as CST form-finding, 2 triangles per quad, 1 kN/m both ways");
  std::puts("  p-it = particle-iteration (one particle advanced one step); RSS = resident set growth while");
  std::puts("  building the model (after malloc_trim), B/particle = that growth per particle");
  std::printf("  target per timed run: %.1f s (thread CPU time), after 5 warm-up steps and >= 0.2 s of calibration steps%s\n\n", target_seconds,
#ifdef NDEBUG
              ""
#else
              "   ** WARNING: built without NDEBUG (not a Release build) **"
#endif
  );

  std::string failure;
  double triad_1 = 0;  // one thread's triad, for the case table
  if (only_cases.empty()) {  // --cases: the case table alone
    // The bar net against the memory bound: triad bandwidth, bytes per
    // particle-iteration, the bound they imply and the share of it reached,
    // with every thread count, wall time (the threads' work included).
    std::printf("bar net against the memory bound (issue 18), wall time; load average %.2f at the start\n", load_average());
    std::puts("  triad = STREAM a = b + s c, best of 10, GB/s; B/p-it = Solver::fused_step_bytes() / particles;");
    std::puts("  bound = triad / (B/p-it); fraction = measured / bound; speed-up = this row / its 1-thread row;");
    std::puts("  cpu M p-it/s = over the thread's CPU time (1 thread: what a loaded machine's time-slicing leaves out)");
    std::vector<double> triad(thread_counts.size());
    for (std::size_t t = 0; t < thread_counts.size(); ++t) {
      triad[t] = triad_gbs(unsigned(thread_counts[t]));
      if (thread_counts[t] == 1) triad_1 = triad[t];
    }
    Table bound({"particles", "threads", "triad GB/s", "B/p-it", "bound M p-it/s", "M p-it/s", "fraction", "speed-up",
                 "cpu M p-it/s"});
    for (std::size_t n : sizes) {
      double single = 0;
      for (std::size_t t = 0; t < thread_counts.size(); ++t) {
        const Measurement r = measure(Case{"bar net", build_bar_net}, n, target_seconds, int(thread_counts[t]));
        const double pit = double(r.particles) * double(r.steps) / r.wall_seconds;
        const double bytes = r.step_bytes / double(r.particles);
        const double limit = triad[t] * 1e9 / bytes;
        if (t == 0) single = pit;
        bound.add({fmt("%zu", r.particles), fmt("%zu", thread_counts[t]), fmt("%.1f", triad[t]), fmt("%.0f", bytes),
                   fmt("%.1f", limit / 1e6), fmt("%.1f", pit / 1e6), fmt("%.0f %%", 100 * pit / limit),
                   fmt("%.2f", pit / single),
                   thread_counts[t] == 1 ? fmt("%.1f", double(r.particles) * double(r.steps) / r.seconds / 1e6) : "-"});
        if (!r.check.empty() && failure.empty()) failure = fmt("bar net %zu threads %zu: ", r.particles, thread_counts[t]) + r.check;
      }
    }
    bound.print();
    std::printf("load average %.2f at the end\n", load_average());
    if (bound_only) {
      if (!failure.empty()) {
        std::printf("check: FAILED (%s)\n", failure.c_str());
        return 1;
      }
      std::puts("check: ok");
      return 0;
    }
  }
  // Each case against one thread's triad too (measured above when the
  // threads include 1): the bytes its step moves and the bandwidth that
  // makes at the measured speed.
  if (triad_1 == 0) triad_1 = triad_gbs(1);
  std::printf("\none thread, thread CPU time; B/p-it = Solver::fused_step_bytes() / particles, GB/s = B/p-it x\n"
              "p-it/s, of triad = that over one thread's triad (%.1f GB/s, this run)\n", triad_1);

  Table table({"case", "particles", "bars", "hinges", "build s", "steps", "cpu s", "M p-it/s", "ns/p-step",
               "B/p-it", "GB/s", "of triad", "RSS MB", "B/particle"});
  double bar_net_largest = -1;
  std::size_t bar_net_largest_n = 0;
  for (const Case& c : cases)
    for (std::size_t n : sizes) {
      Measurement r = measure(c, n, target_seconds);
      const double pit = double(r.particles) * double(r.steps) / r.seconds;
      const double bytes = r.step_bytes / double(r.particles);
      table.add({c.name, fmt("%zu", r.particles), fmt("%zu", r.bars), fmt("%zu", r.hinges), fmt("%.2f", r.build_s),
                 fmt("%llu", (unsigned long long)r.steps), fmt("%.2f", r.seconds), fmt("%.1f", pit / 1e6),
                 fmt("%.1f", 1e9 / pit), fmt("%.0f", bytes), fmt("%.1f", bytes * pit / 1e9),
                 fmt("%.0f %%", 100 * bytes * pit / 1e9 / triad_1), fmt("%.1f", r.rss_growth / 1048576.0),
                 fmt("%.0f", double(r.rss_growth) / double(r.particles))});
      if (c.build == build_bar_net && r.particles >= bar_net_largest_n) {
        bar_net_largest_n = r.particles;
        bar_net_largest = pit;
      }
      if (!r.check.empty() && failure.empty()) failure = std::string(c.name) + " " + fmt("%zu", r.particles) + ": " + r.check;
    }
  table.print();
  if (!only_cases.empty()) {
    // The named cases on every thread count of --threads, wall time: the
    // element loops (hinges, 6-DOF beams, CST) split by particle ownership.
    if (thread_counts.size() > 1 || (thread_counts.size() == 1 && thread_counts[0] != 1)) {
      std::printf("\nthe same cases on threads, wall time (load average %.2f); speed-up = this row / 1 thread\n",
                  load_average());
      Table threaded({"case", "particles", "threads", "steps", "wall s", "M p-it/s", "speed-up"});
      for (const Case& c : cases)
        for (std::size_t n : sizes) {
          double single = 0;
          for (std::size_t t : thread_counts) {
            const Measurement r = measure(c, n, target_seconds, int(t));
            const double pit = double(r.particles) * double(r.steps) / r.wall_seconds;
            if (t == 1) single = pit;
            threaded.add({c.name, fmt("%zu", r.particles), fmt("%zu", t), fmt("%llu", (unsigned long long)r.steps),
                          fmt("%.2f", r.wall_seconds), fmt("%.1f", pit / 1e6),
                          single > 0 ? fmt("%.2f", pit / single) : "-"});
            if (!r.check.empty() && failure.empty())
              failure = std::string(c.name) + fmt(" %zu threads %zu: ", r.particles, t) + r.check;
          }
        }
      threaded.print();
    }
    if (!failure.empty()) {
      std::printf("check: FAILED (%s)\n", failure.c_str());
      return 1;
    }
    std::puts("check: ok");
    return 0;
  }

  // Multi-resolution: the bar net with 0, 50, 90 and 99 % of its rows
  // passive; ratio = active p-it/s over the fully active net's at that size.
  std::puts("\nbar net with passive rows (thesis 5.5.2.3): p-it counts active particles only;");
  std::puts("ratio = fully active M p-it/s / this row's (1.0 = a passive particle costs nothing)");
  Table passive({"passive", "grid", "active", "awake bars", "dormant bars", "steps", "cpu s", "M p-it/s", "ratio"});
  for (std::size_t n : sizes) {
    double full = 0;
    for (double f : {0.0, 0.5, 0.9, 0.99}) {
      g_passive_fraction = f;
      const Case c{"passive net", build_passive_net};
      Measurement r = measure(c, n, target_seconds);
      const double pit = double(r.particles) * double(r.steps) / r.seconds;
      if (f == 0.0) full = pit;
      passive.add({fmt("%.0f %%", 100 * f), fmt("%zu", n), fmt("%zu", r.particles), fmt("%zu", r.awake_bars),
                   fmt("%zu", r.bars - r.awake_bars), fmt("%llu", (unsigned long long)r.steps), fmt("%.2f", r.seconds),
                   fmt("%.1f", pit / 1e6), fmt("%.2f", full / pit)});
      if (!r.check.empty() && failure.empty()) failure = fmt("passive net %.0f %% ", 100 * f) + r.check;
    }
  }
  passive.print();

  std::puts("\nmulti-resolution patch in coarse mode (factor 4): the coarse net with its passive fine patch");
  std::puts("against the coarse net alone; ratio = ns per step with the fine patch / without (1.0 = free)");
  Table multires({"fine particles", "passive", "active", "awake bars", "dormant bars", "us/step alone",
                  "us/step multires", "ratio"});
  for (std::size_t n : sizes) {
    Measurement alone = measure(Case{"coarse net", build_coarse_net}, n, target_seconds);
    Measurement coarse = measure(Case{"multires", build_multires_net}, n, target_seconds);
    const double t_alone = 1e6 * alone.seconds / double(alone.steps), t_multi = 1e6 * coarse.seconds / double(coarse.steps);
    multires.add({fmt("%zu", coarse.capacity), fmt("%zu", coarse.capacity - coarse.particles), fmt("%zu", coarse.particles),
                  fmt("%zu", coarse.awake_bars), fmt("%zu", coarse.bars - coarse.awake_bars), fmt("%.1f", t_alone),
                  fmt("%.1f", t_multi), fmt("%.2f", t_multi / t_alone)});
    if (!coarse.check.empty() && failure.empty()) failure = "multires " + coarse.check;
  }
  multires.print();
  std::printf("\nDESIGN target >= 30 M p-it/s (bar net, one core): %.1f M p-it/s at %zu particles -> %s\n",
              bar_net_largest / 1e6, bar_net_largest_n, bar_net_largest >= 30e6 ? "met" : "NOT met");
  if (!failure.empty()) {
    std::printf("check: FAILED (%s)\n", failure.c_str());
    return 1;
  }
  std::puts("check: ok");
  return 0;
}
