// Residual forces and greatest direct stiffnesses (eq. 3.4) of every element
// at given positions: bars (eq. 3.32-3.35), spline-beam hinges
// (eq. 3.41-3.43) and 6-DOF beams (eq. 3.44-3.50). The integrators evaluate
// them at the step's positions and at their intermediate stages.
// Bars run chunk by chunk on the lean buffers of bar_chunks.hpp, on every
// thread; the other elements follow on one thread, in the model's order.
#include <algorithm>
#include <cmath>

#include "physics/element_forces.hpp"
#include "physics/numerical_errors.hpp"
#include "physics/solver.hpp"
#include "physics/workers.hpp"

namespace tendril {

Solver::Solver(Model& model) : model_(model), workers_(std::make_unique<Workers>()) {}
Solver::~Solver() = default;

const BarChunks& Solver::bar_chunks() const {
  if (!bar_chunks_.current(model_)) bar_chunks_.derive(model_);
  return bar_chunks_;
}

namespace {

// Bars are evaluated in blocks: the chords are gathered, then one loop
// without memory indirection or branches (vectorised: `omp simd`, with
// -fno-math-errno and -fno-trapping-math so that square roots, divisions
// and selects stay in vectors) finds each bar's length, force on i and
// stiffness, then the forces are scattered. Per bar the arithmetic is
// exactly that of one bar at a time: T / L is divided once and, with the
// default geometric factor 1, g T / L is that same quotient (1 * T is T); a
// bar of no positive length (coincident or non-finite ends) adds no force.
constexpr std::uint32_t kBarBlock = 64;

struct BarBlock {
  alignas(64) double dx[kBarBlock], dy[kBarBlock], dz[kBarBlock];
  alignas(64) double L[kBarBlock], fx[kBarBlock], fy[kBarBlock], fz[kBarBlock], s[kBarBlock];
};

// Eq. 3.32 (no tension in a slack cable), eq. 3.33's T / L and eq. 3.35.
// With GCC on x86-64 the loop is compiled three times, for AVX-512, AVX2
// and the portable SSE2, and the CPU picks one when the program starts
// (target_clones): 4 bars per instruction instead of 2, the same binary on
// every x86-64. Each lane rounds as the scalar code does (no fused
// multiply-adds: -ffp-contract=off for this file, core/CMakeLists.txt), so
// every copy gives the same numbers bit for bit.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__AVX2__)
#define TENDRIL_BAR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define TENDRIL_BAR_CLONES
#endif
template <bool kUnitFactor>
TENDRIL_BAR_CLONES void bar_block(BarBlock& b, std::uint32_t n, const double* __restrict k, const double* __restrict rest,
               const double* __restrict pre, const std::uint8_t* __restrict cable, double gf) {
#pragma omp simd
  for (std::uint32_t m = 0; m < n; ++m) {
    const double dx = b.dx[m], dy = b.dy[m], dz = b.dz[m];
    const double L = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double T0 = pre[m] + k[m] * (L - rest[m]);
    const double T = cable[m] && T0 < 0 ? 0.0 : T0;
    const double c = T / L;
    const double g = kUnitFactor ? c : gf * T / L;
    b.L[m] = L;
    b.s[m] = k[m] + (L > 0 && T > 0 ? g : 0.0);
    b.fx[m] = c * dx;
    b.fy[m] = c * dy;
    b.fz[m] = c * dz;
  }
}

// Spline-beam hinges the same way (eq. 3.41-3.43): the three chords
// gathered, one vectorised loop for lengths, stiffnesses and the two shear
// forces, then the scatter in the model's order. Term for term the
// arithmetic of hinge_forces (element_forces.hpp), Eigen's norm, cross and
// normalized written out in their order; a straight or degenerate hinge
// (no plane) gets +0 forces, as hinge_forces returns.
constexpr std::uint32_t kHingeBlock = 64;

struct HingeBlock {
  alignas(64) double ax[kHingeBlock], ay[kHingeBlock], az[kHingeBlock];
  alignas(64) double bx[kHingeBlock], by[kHingeBlock], bz[kHingeBlock];
  alignas(64) double cx[kHingeBlock], cy[kHingeBlock], cz[kHingeBlock];
  alignas(64) double EI[kHingeBlock], rest[kHingeBlock];
  alignas(64) double k[kHingeBlock], fix[kHingeBlock], fiy[kHingeBlock], fiz[kHingeBlock];
  alignas(64) double fkx[kHingeBlock], fky[kHingeBlock], fkz[kHingeBlock];
};

TENDRIL_BAR_CLONES void hinge_block(HingeBlock& h, std::uint32_t n) {
#pragma omp simd
  for (std::uint32_t m = 0; m < n; ++m) {
    const double ax = h.ax[m], ay = h.ay[m], az = h.az[m], bx = h.bx[m], by = h.by[m], bz = h.bz[m];
    const double cx = h.cx[m], cy = h.cy[m], cz = h.cz[m], EI = h.EI[m];
    const double La = std::sqrt(ax * ax + ay * ay + az * az), Lb = std::sqrt(bx * bx + by * by + bz * bz),
                 Lc = std::sqrt(cx * cx + cy * cy + cz * cz);
    const double ka = 4 * EI / (La * La * La), kb = 4 * EI / (Lb * Lb * Lb);
    h.k[m] = ka + kb;
    const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;  // a x b
    const double nn = std::sqrt(nx * nx + ny * ny + nz * nz);
    const bool bends = !(nn <= 0 || Lc <= 0);
    const double sin_alpha = nn / (La * Lb);
    const double M = EI * (2 * sin_alpha / Lc - h.rest[m]);
    // a x nrm and b x nrm, normalized (divided by their norm when it is > 0)
    const double ux = ay * nz - az * ny, uy = az * nx - ax * nz, uz = ax * ny - ay * nx;
    const double vx = by * nz - bz * ny, vy = bz * nx - bx * nz, vz = bx * ny - by * nx;
    const double zu = ux * ux + uy * uy + uz * uz, zv = vx * vx + vy * vy + vz * vz;
    const double ru = zu > 0 ? std::sqrt(zu) : 1.0, rv = zv > 0 ? std::sqrt(zv) : 1.0;
    const double Ma = M / La, Mb = M / Lb;
    h.fix[m] = bends ? Ma * (zu > 0 ? ux / ru : ux) : 0.0;
    h.fiy[m] = bends ? Ma * (zu > 0 ? uy / ru : uy) : 0.0;
    h.fiz[m] = bends ? Ma * (zu > 0 ? uz / ru : uz) : 0.0;
    h.fkx[m] = bends ? Mb * (zv > 0 ? vx / rv : vx) : 0.0;
    h.fky[m] = bends ? Mb * (zv > 0 ? vy / rv : vy) : 0.0;
    h.fkz[m] = bends ? Mb * (zv > 0 ? vz / rv : vz) : 0.0;
  }
}

}  // namespace

void Solver::chunk_bar_forces(const BarChunks::Chunk& c, const Vec3* x, Vec3* F, double* S) const {
  const Particles& P = model_.particles;
  const BarChunks& B = bar_chunks_;
  const Vec3 g = model_.gravity;
  const Vec3* load = P.load.data();
  const double *point_mass = P.point_mass.data(), *lumped_mass = P.lumped_mass.data();
  // Without gravity the weight m * (+0) is a zero (masses are finite), so
  // load + 0 gives the same values without streaming the masses (at most
  // the sign of a zero component differs, where rounding left a lumped mass
  // a hair below zero).
  const bool weightless = g.x() == 0 && g.y() == 0 && g.z() == 0 && !std::signbit(g.x()) &&
                          !std::signbit(g.y()) && !std::signbit(g.z());
  if (weightless)
    for (std::uint32_t n = c.particles_begin; n < c.particles_end; ++n) {
      const ParticleId p = B.particles[n];
      F[p] = load[p] + Vec3::Zero();
      S[p] = 0;
    }
  else
    for (std::uint32_t n = c.particles_begin; n < c.particles_end; ++n) {
      const ParticleId p = B.particles[n];
      F[p] = load[p] + (point_mass[p] + lumped_mass[p]) * g;
      S[p] = 0;
    }
  const double gf = settings.geometric_factor;
  const bool unit_factor = gf == 1;
  const ParticleId *bi = B.i.data(), *bj = B.j.data();
  BarBlock b;
  Vec3* slot_f = bar_chunks_.slot_force.data();
  double* slot_s = bar_chunks_.slot_stiffness.data();
  for (std::uint32_t e0 = c.bars_begin; e0 < c.bars_end; e0 += kBarBlock) {
    const std::uint32_t n = std::min(kBarBlock, c.bars_end - e0);
    for (std::uint32_t m = 0; m < n; ++m) {
      const Vec3 d = x[bj[e0 + m]] - x[bi[e0 + m]];
      b.dx[m] = d.x();
      b.dy[m] = d.y();
      b.dz[m] = d.z();
    }
    const double *k = B.k.data() + e0, *rest = B.rest.data() + e0, *pre = B.prestress.data() + e0;
    const std::uint8_t* cable = B.cable.data() + e0;
    if (unit_factor) bar_block<true>(b, n, k, rest, pre, cable, gf);
    else bar_block<false>(b, n, k, rest, pre, cable, gf);
    // The block's interior bars [0, interior), then its crossing ones.
    const std::uint32_t interior = std::clamp(c.crossing_begin, e0, e0 + n) - e0;
    for (std::uint32_t m = 0; m < interior; ++m) {
      const ParticleId i = bi[e0 + m], j = bj[e0 + m];
      if (b.L[m] > 0) [[likely]] {
        const Vec3 f(b.fx[m], b.fy[m], b.fz[m]);
        F[i] += f;
        F[j] -= f;
      }
      S[i] += b.s[m];
      S[j] += b.s[m];
    }
    for (std::uint32_t m = interior; m < n; ++m) {  // j is another chunk's: its share waits in the slot
      const std::uint32_t e = e0 + m;
      const ParticleId i = bi[e];
      Vec3 f = Vec3::Zero();
      if (b.L[m] > 0) [[likely]] {
        f = Vec3(b.fx[m], b.fy[m], b.fz[m]);
        F[i] += f;
      }
      S[i] += b.s[m];
      const std::uint32_t slot = c.slot_begin + (e - c.crossing_begin);
      slot_f[slot] = f;
      slot_s[slot] = b.s[m];
    }
  }
}

void Solver::chunk_inbox(const BarChunks::Chunk& c, Vec3* F, double* S) const {
  const BarChunks& B = bar_chunks_;
  for (std::uint32_t n = c.inbox_begin; n < c.inbox_end; ++n) {
    const ParticleId p = B.inbox_particle[n];
    F[p] -= B.slot_force[B.inbox_slot[n]];
    S[p] += B.slot_stiffness[B.inbox_slot[n]];
  }
}

void Solver::for_chunks(FunctionRef<void(std::uint32_t)> body, FunctionRef<void(std::uint32_t)> late) const {
  const BarChunks& B = bar_chunks_;
  const std::uint32_t n = std::uint32_t(B.chunks.size());
  const unsigned threads = unsigned(std::clamp<std::uint32_t>(std::uint32_t(settings.threads), 1, n));
  if (threads == 1) {
    for (std::uint32_t c = 0; c < n; ++c) {
      body(c);
      late(c);
    }
    return;
  }
  // Contiguous ranges of about equal particle counts.
  std::vector<std::uint32_t>& first = thread_first_chunk_;
  first.assign(threads + 1, n);  // allocates when the thread count grows only
  first[0] = 0;
  const std::size_t total = B.particles.size();
  std::uint32_t c = 0;
  for (unsigned t = 1; t < threads; ++t) {
    const std::size_t target = total * t / threads;
    while (c < n && B.chunks[c].particles_end <= target) ++c;
    first[t] = std::max(c, first[t - 1]);
  }
  bool deferred = false;
  for (unsigned t = 0; t < threads; ++t)
    for (std::uint32_t k = first[t]; k < first[t + 1]; ++k) deferred |= B.chunks[k].first_source < first[t];
  workers_->run(threads, [&](unsigned t) {
    for (std::uint32_t k = first[t]; k < first[t + 1]; ++k) {
      body(k);
      if (B.chunks[k].first_source >= first[t]) late(k);
    }
  });
  if (!deferred) return;
  workers_->run(threads, [&](unsigned t) {
    for (std::uint32_t k = first[t]; k < first[t + 1]; ++k)
      if (B.chunks[k].first_source < first[t]) late(k);
  });
}

void Solver::for_chunks(FunctionRef<void(std::uint32_t)> body) const {
  for_chunks(body, [](std::uint32_t) {});
}

void Solver::accumulate_forces(const Vec3* x, const Quat* q, Vec3* F, double* S, Vec3* T, double* K) const {
  const Particles& P = model_.particles;
  const BarChunks& B = bar_chunks();
  for_chunks([&](std::uint32_t c) { chunk_bar_forces(B.chunks[c], x, F, S); },
             [&](std::uint32_t c) { chunk_inbox(B.chunks[c], F, S); });
  for (ParticleId p : P.rotational.raw()) {
    T[p] = P.moment[p];
    K[p] = 0;
  }
  const double gf = settings.geometric_factor;
  // Only awake elements: those touching a passive particle (multi-
  // resolution, thesis 5.5.2.3) sit behind ElementBuffer::awake, unvisited.
  const Hinge* hinges = model_.hinges.awake_begin();
  const std::uint32_t n_hinges = std::uint32_t(model_.hinges.awake_end() - hinges);
  if (n_hinges > 0) {
    HingeBlock hb;
    for (std::uint32_t e0 = 0; e0 < n_hinges; e0 += kHingeBlock) {
      const std::uint32_t n = std::min(kHingeBlock, n_hinges - e0);
      for (std::uint32_t m = 0; m < n; ++m) {
        const Hinge& h = hinges[e0 + m];
        const Vec3 a = x[h.j] - x[h.i], b = x[h.k] - x[h.j], c = x[h.k] - x[h.i];
        hb.ax[m] = a.x(), hb.ay[m] = a.y(), hb.az[m] = a.z();
        hb.bx[m] = b.x(), hb.by[m] = b.y(), hb.bz[m] = b.z();
        hb.cx[m] = c.x(), hb.cy[m] = c.y(), hb.cz[m] = c.z();
        hb.EI[m] = h.EI;
        hb.rest[m] = h.rest_curvature;
      }
      hinge_block(hb, n);
      for (std::uint32_t m = 0; m < n; ++m) {
        const Hinge& h = hinges[e0 + m];
        if (!std::isfinite(hb.k[m])) [[unlikely]]
          throw_degenerate_hinge(model_, h, x);  // a zero-length link (coincident particles): stop, naming them
        const Vec3 fi(hb.fix[m], hb.fiy[m], hb.fiz[m]), fk(hb.fkx[m], hb.fky[m], hb.fkz[m]);
        S[h.j] += hb.k[m];
        F[h.i] += fi;
        F[h.k] += fk;
        F[h.j] -= fi + fk;
      }
    }
  }
  for (const Beam6* bp = model_.beam6s.awake_begin(); bp != model_.beam6s.awake_end(); ++bp) {
    const Beam6& b = *bp;
    const Beam6Ends e = beam6_ends(b, x, q, gf);
    S[b.i] += e.k;
    S[b.j] += e.k;
    K[b.i] += e.kr;
    K[b.j] += e.kr;
    F[b.i] -= e.fj;
    F[b.j] += e.fj;
    T[b.i] += e.ta;
    T[b.j] += e.tb;
  }
  accumulate_couples(x, F);  // moments on 3-DOF particles (couples.cpp)
  for (Dart d : model_.clamp_darts.raw()) {  // clamped 3-DOF beam ends (Model::set_clamp)
    if (!model_.clamp_acts(d)) continue;
    const ParticleId p = model_.dart_particle[d], q = model_.dart_particle[model_.map.alpha(0, d)];
    if (!(P.active[p] & P.active[q])) continue;  // dormant, like an element touching a passive particle
    const ClampForces f = clamp_forces(model_.clamp[d], model_.blocks[model_.dart_block[d]].section.EI, x[p], x[q]);
    F[q] += f.fq;
    F[p] -= f.fq;
    S[p] += f.k;
    S[q] += f.k;
  }
  for (const RigidJoint& j : model_.rigid_joints.raw()) {  // rigid joints of 3-DOF beams (Model::set_joint)
    if (!model_.rigid_acts(j)) continue;
    const ParticleId p = model_.dart_particle[j.a];
    const ParticleId a = model_.dart_particle[model_.map.alpha(0, j.a)], b = model_.dart_particle[model_.map.alpha(0, j.b)];
    if (!(P.active[p] & P.active[a] & P.active[b])) continue;  // dormant, like an element touching a passive particle
    const RigidJointForces f = rigid_joint_forces(model_.rigid_stiffness(j), j.angle, x[p], x[a], x[b]);
    F[a] += f.fa;
    F[b] += f.fb;
    F[p] -= f.fa + f.fb;
    S[a] += f.ka;
    S[b] += f.kb;
    S[p] += f.ka + f.kb;
  }
  if (!model_.joints.items.empty()) accumulate_joint_forces(x, F, S);
  if (!model_.goals.empty()) accumulate_goal_forces(x, F, S);
  if (!model_.csts.items.empty()) accumulate_cst_forces(x, F, S);
  accumulate_pressure_forces(x, F, S);
}

}  // namespace tendril
