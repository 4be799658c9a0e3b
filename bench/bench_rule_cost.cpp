// Cost of one rule application on a live, integrating model (DESIGN
// principle 1 and "Targets": one rule application costs the same on 1 000
// and on 1 000 000 particles, within 2x), against the same change followed
// by a full rebuild_elements() (the approach thesis 6.1 criticises).
//
//   bench_rule_cost [--sizes 1K,10K,100K,1M] [--apps 200] [--steps-between 1] [--evict MB]
//
// Only the rule call (and, in the second variant, the rebuild) is timed; one
// Solver::step() runs between applications so the model keeps integrating and
// the caches see what a real run does to them (--steps-between 0 shows the
// cost with the model's working set left in cache). A small model stays in
// the caches through the step while a large one does not, so the sizes are
// compared warm against cold; --evict MB streams through a buffer larger
// than the last-level cache before every application, so every size is
// measured cold and the ratio shows the algorithm's growth alone.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
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



// --- the live model ------------------------------------------------------------
//
// Rows of short straight beams along x (4 particles, 3 segments of 0.25 m),
// both ends locked, 1 N downward load on the two interior particles. In a row
// the end of one beam lies 2 mm from the start of the next: rule 3 merges
// such a pair into one shared joint, rule 13 splits a random segment.

constexpr int kPerBeam = 4;
constexpr double kSegment = 0.25, kGap = 0.002, kRowPitch = 1.0;
const Section kSection{1e6, 50, 0, 0};  // EA [N], EI [N m^2]

struct LiveModel {
  std::unique_ptr<Model> model;
  std::vector<std::pair<ParticleId, ParticleId>> segments;  // consecutive beam particles
  std::vector<std::pair<ParticleId, ParticleId>> joints;    // end of a beam, start of the next
};

LiveModel build(std::size_t particles, std::uint32_t seed) {
  LiveModel live;
  live.model = std::make_unique<Model>();
  Model& m = *live.model;
  const std::size_t beams = std::max<std::size_t>(2, particles / kPerBeam);
  std::size_t cols = static_cast<std::size_t>(std::ceil(std::sqrt(double(beams))));
  cols += cols % 2;
  const double pitch = (kPerBeam - 1) * kSegment + kGap;
  std::vector<ParticleId> ps(kPerBeam), prev;
  for (std::size_t b = 0; b < beams; ++b) {
    const std::size_t row = b / cols, col = b % cols;
    for (int k = 0; k < kPerBeam; ++k) {
      ps[k] = m.add_particle(Vec3(col * pitch + k * kSegment, row * kRowPitch, 0));
      if (k == 0 || k == kPerBeam - 1) m.set_lock(ps[k], kLockTranslation);
      else m.set_load(ps[k], Vec3(0, 0, -1));
    }
    m.add_beam(ps, kSection);
    for (int k = 0; k + 1 < kPerBeam; ++k) live.segments.emplace_back(ps[k], ps[k + 1]);
    if (col > 0) live.joints.emplace_back(prev.back(), ps.front());
    prev = ps;
  }
  // Different places, deterministic order.
  std::mt19937 rng(seed);
  std::shuffle(live.segments.begin(), live.segments.end(), rng);
  std::shuffle(live.joints.begin(), live.joints.end(), rng);
  return live;
}

struct Samples {
  std::vector<double> us;
  double mean() const {
    double s = 0;
    for (double x : us) s += x;
    return us.empty() ? 0 : s / us.size();
  }
  double median() const {
    if (us.empty()) return 0;
    std::vector<double> v = us;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  }
  double max() const { return us.empty() ? 0 : *std::max_element(us.begin(), us.end()); }
};

struct Run {
  Samples rule13, rule3;
  std::string check;
};

// Applies rule 13 then rule 3 `apps` times each on a fresh live model (the
// same model and places for both variants), `steps_between` solver steps
// before every application. With `rebuild`, every application is followed by
// rebuild_elements() inside the timed region, and each rule stops early once
// `rebuild_budget` seconds were spent (the rebuild is O(n)).

// Writes one byte per cache line of `buffer`: afterwards none of the model is
// left in any cache.
void evict(std::vector<char>& buffer) {
  for (std::size_t i = 0; i < buffer.size(); i += 64) buffer[i] = static_cast<char>(buffer[i] + 1);
}

Run run(std::size_t particles, std::size_t apps, int steps_between, bool rebuild, double rebuild_budget,
        std::vector<char>& eviction) {
  LiveModel live = build(particles, 20240611u);
  Model& m = *live.model;
  Solver solver(m);
  solver.settings.damping = Damping::Kinetic;
  for (int i = 0; i < 5; ++i) solver.step();
  Run r;
  const std::size_t n13 = std::min(apps, live.segments.size());
  double spent = 0;
  for (std::size_t i = 0; i < n13; ++i) {
    for (int k = 0; k < steps_between; ++k) solver.step();
    evict(eviction);
    auto t0 = Clock::now();
    m.insert_particle(live.segments[i].first, live.segments[i].second);
    if (rebuild) m.rebuild_elements();
    const double s = seconds_since(t0);
    r.rule13.us.push_back(1e6 * s);
    spent += s;
    if (rebuild && spent > rebuild_budget && i >= 4) break;
  }
  const std::size_t n3 = std::min(apps, live.joints.size());
  spent = 0;
  std::vector<ParticleId> pair(2);
  for (std::size_t i = 0; i < n3; ++i) {
    for (int k = 0; k < steps_between; ++k) solver.step();
    pair[0] = live.joints[i].first;
    pair[1] = live.joints[i].second;
    evict(eviction);
    auto t0 = Clock::now();
    m.merge(pair);
    if (rebuild) m.rebuild_elements();
    const double s = seconds_since(t0);
    r.rule3.us.push_back(1e6 * s);
    spent += s;
    if (rebuild && spent > rebuild_budget && i >= 4) break;
  }
  for (int i = 0; i < 3; ++i) solver.step();
  if (!std::isfinite(solver.residual())) r.check = "residual is not finite";
  else r.check = m.check();
  return r;
}

int usage(const char* argv0, int code) {
  std::fprintf(code ? stderr : stdout,
               "usage: %s [--sizes 1K,10K,100K,1M] [--apps N] [--steps-between K] [--rebuild-seconds S]"
               " [--evict MB]\n"
               "  --sizes            particle counts (K/M suffixes)\n"
               "  --apps             applications of each rule per size (default 200)\n"
               "  --steps-between    solver steps before each application (default 1)\n"
               "  --rebuild-seconds  time budget per rule for the patch+rebuild variant (default 4)\n"
               "  --evict            MB streamed through before every application, to measure every size\n"
               "                     with cold caches (more than the last-level cache; default 0)\n",
               argv0);
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  tendril::restart_with_huge_pages(argv);  // as tendril itself runs (io/huge_pages.hpp)
  std::vector<std::size_t> sizes{1'000, 10'000, 100'000, 1'000'000};
  std::size_t apps = 200;
  double rebuild_budget = 4.0;
  int steps_between = 1;
  std::size_t evict_mb = 0;
  try {
    for (int i = 1; i < argc; ++i) {
      std::string a = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::runtime_error(a + " needs a value");
        return argv[++i];
      };
      if (a == "--sizes") sizes = parse_sizes(value());
      else if (a == "--apps") apps = parse_count(value());
      else if (a == "--steps-between") steps_between = std::stoi(value());
      else if (a == "--rebuild-seconds") rebuild_budget = std::stod(value());
      else if (a == "--evict") evict_mb = parse_count(value());
      else if (a == "-h" || a == "--help") return usage(argv[0], 0);
      else throw std::runtime_error("unknown option '" + a + "'");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_rule_cost: %s\n", e.what());
    return usage(argv[0], 2);
  }

  std::printf("bench_rule_cost: one rule application on a live model, %d Solver::step() before each application%s\n",
              steps_between, evict_mb ? fmt(", %zu MB streamed through the caches before each", evict_mb).c_str() : "");
  std::puts("  model : rows of 4-particle spline beams (3 DOF) along x, ends locked, 1 N load on interior particles");
  std::puts("  rule 13: insert_particle in a random segment; rule 3: merge the end of a beam with the start of");
  std::puts("           the next one (2 mm apart) into a shared joint; every application at a different place");
  std::puts("  patch = the rule call alone (local buffer patch); +rebuild = rule call + full rebuild_elements()");
  std::printf("  times in microseconds; n = applications averaged (the +rebuild variant stops after %.0f s)%s\n\n",
              rebuild_budget,
#ifdef NDEBUG
              ""
#else
              "   ** WARNING: built without NDEBUG (not a Release build) **"
#endif
  );

  Table table({"size", "particles", "rule", "n", "patch us mean", "median", "max", "n", "+rebuild us mean",
               "ratio"});
  std::string failure;
  struct Flat {
    std::size_t n;
    double r13, r3;
  };
  std::vector<Flat> flat;
  for (std::size_t size : sizes) {
    std::vector<char> eviction(evict_mb << 20);
    Run local = run(size, apps, steps_between, false, rebuild_budget, eviction);
    Run full = run(size, apps, steps_between, true, rebuild_budget, eviction);
    const std::size_t particles = std::max<std::size_t>(2, size / kPerBeam) * kPerBeam;
    auto row = [&](const char* rule, const Samples& a, const Samples& b) {
      table.add({fmt("%zu", size), fmt("%zu", particles), rule, fmt("%zu", a.us.size()), fmt("%.2f", a.mean()),
                 fmt("%.2f", a.median()), fmt("%.1f", a.max()), fmt("%zu", b.us.size()), fmt("%.1f", b.mean()),
                 fmt("%.0fx", b.mean() / a.mean())});
    };
    row("13 insert_particle", local.rule13, full.rule13);
    row("3 merge", local.rule3, full.rule3);
    flat.push_back({particles, local.rule13.mean(), local.rule3.mean()});
    for (const Run* r : {&local, &full})
      if (!r->check.empty() && failure.empty()) failure = fmt("%zu particles: ", particles) + r->check;
  }
  table.print();
  if (flat.size() >= 2) {
    std::puts("");
    const Flat& base = flat.front();
    for (std::size_t i = 1; i < flat.size(); ++i) {
      const double a = flat[i].r13 / base.r13, b = flat[i].r3 / base.r3;
      std::printf("local cost %zu vs %zu particles: rule 13 %.2fx, rule 3 %.2fx -> %s (DESIGN: within 2x)\n",
                  flat[i].n, base.n, a, b, std::max(a, b) <= 2.0 ? "flat" : "NOT flat");
    }
  }
  if (!failure.empty()) {
    std::printf("check: FAILED (%s)\n", failure.c_str());
    return 1;
  }
  std::puts("check: ok");
  return 0;
}
