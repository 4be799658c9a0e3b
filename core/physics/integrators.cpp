// Explicit time integrators for translation (thesis 3.2.5) and rotation
// (3.2.6). Each starts from the forces, torques, masses and inertias of the
// step's start (Solver::step) and ends with the kinetic-energy bookkeeping of
// eq. 3.28. Locked axes have zero acceleration and zero velocity. The
// multi-stage methods evaluate their stages on scratch buffers and write the
// model only once every stage and the new state were finite, so a
// NumericalError leaves positions, frames and velocities as they were.
// Leapfrog and Symplectic Euler kick in place: a kick that overflows (a time
// step beyond the stability limit) resets the velocities before it throws;
// positions and frames stay as they were.
// Rotation mirrors translation with x -> R, v -> w, F/M -> T/I and the drift
// x + h v -> R_T(h w) R (eq. 3.16-3.17); it runs over the rotating particles.
// Translation runs over Particles::integrated (the active particles) only:
// a passive particle is never read or written, and no awake element reads
// one (ElementBuffer), so stage buffers need no values for it.
#include <algorithm>
#include <cmath>

#include "model/frames.hpp"
#include "physics/frame_drift.hpp"
#include "physics/free_axes.hpp"
#include "physics/lanes.hpp"
#include "physics/numerical_errors.hpp"
#include "physics/simd_clones.hpp"
#include "physics/solver.hpp"

namespace tendril {

namespace {
// Eq. 3.17: the frame q turned by the rotation vector r (global axes).
inline Quat turned(const Vec3& r, const Quat& q) { return Quat(rotation_of(r) * q).normalized(); }

// A particle's physical mass as the step uses it: 1 kg for a massless
// particle locked on every axis (it does not move), else its mass (0 or less
// is refused by the caller, as prepare_masses does).
inline double physical_mass(double point, double lumped, const Vec3& free) {
  const double m = point + lumped;
  return m > 0 || !free.isZero() ? m : 1.0;
}

// The free axes of each translation (or, shifted, rotation) lock.
const Vec3 free_of[8] = {free_axes(0), free_axes(1), free_axes(2), free_axes(3),
                         free_axes(4), free_axes(5), free_axes(6), free_axes(7)};

// Every term finite: x - x is 0 for a finite x, NaN for an infinite or NaN
// one, and a NaN stays in the sum.
inline bool all_finite(const Vec3& f, double s) {
  return (f.x() - f.x()) + (f.y() - f.y()) + (f.z() - f.z()) + (s - s) == 0;
}
}  // namespace

// Leapfrog (eq. 3.11-3.12, with eq. 3.26) and Symplectic Euler are the same
// kick-drift recurrence: the new velocity moves the particle, so it lags the
// positions by half a step, and eq. 3.29-3.31 hold for both. They differ in
// the first kick from velocities at the step's time (at rest, or left by a
// synchronous integrator): Leapfrog is not self-starting and kicks half a
// step, Symplectic Euler kicks a whole one.
// (Mixed's Leapfrog phase: the masses were prepared.)
void Solver::integrate_leapfrog() { kick_drift(half_step_, false); }

// v' = keep v + first B dt / M F: eq. 3.11 (first = 1/2 for Leapfrog's
// start), with eq. 3.26's A and B when viscous.
Solver::Kick Solver::kick(bool whole_kick) const {
  double A = 1, B = 1;
  if (settings.damping == Damping::Viscous) {  // eq. 3.26
    A = (1 - settings.viscous / 2) / (1 + settings.viscous / 2);
    B = (1 + A) / 2;
  }
  return {whole_kick ? 1.0 : 0.5, whole_kick ? A : 1.0, B};
}

// Eq. 3.29-3.31: the fraction q of the last step back to the interpolated
// kinetic-energy peak.
double Solver::peak_fraction(double ke) const {
  if (ke_samples_ < 2) return 0;
  const double G = ke_prev2_ - ke_prev_, H = ke_prev_ - ke;
  return H - G != 0 ? H / (H - G) : 0.0;
}

// `prepare`: the masses of eq. 3.4 (or the physical ones) found in the
// kick's pass, as fused_kick_drift does for bars alone, each particle's
// force, stiffness and mass checked and used while in the cache; the
// arithmetic of prepare_masses then the kick. A force or mass the step
// cannot use is found after some velocities were kicked: they are reset,
// prepare_masses names the particle at fault, and no particle was moved.
namespace {

// One kind of motion's kick (translation: v, F, S, M over the integrated
// particles; rotation: w, T, K, I over the rotating ones), every pointer a
// local and the free axes of a lock looked up.
struct KickPass {
  const ParticleId* ids;
  std::uint32_t n;
  const std::uint8_t* active;  // rotation: only active particles turn; translation: null
  const std::uint8_t* lock;
  int lock_shift;  // 0: translation's lock bits, 3: rotation's
  const Vec3* F;   // force or torque
  const double* S;  // stiffness (fictitious masses)
  const double *point_mass, *lumped_mass;  // physical: the mass's parts (rotation: the inertia and null)
  double* mass;                            // the mass used, written when prepared
  Vec3* v;
  double mass_scale, keep, first_B_dt;  // first_B_dt = first * B * dt
};
struct KickTotals {
  double ke = 0, momentum2 = 0, residual2 = 0;
  bool bad = false;
};

// kPrepare: each mass found as prepare_masses finds it (eq. 3.4, or the
// physical one: 1 for a massless particle locked on every axis) and its
// force, stiffness and mass checked; else the masses are read.
template <bool kPrepare, bool kPhysical>
TENDRIL_SIMD_CLONES KickTotals kick_pass(const KickPass& a, KickTotals t) {
  const ParticleId* __restrict ids = a.ids;
  const std::uint8_t* __restrict active = a.active;
  const std::uint8_t* __restrict lock = a.lock;
  const Vec3* __restrict F = a.F;
  const double* __restrict S = a.S;
  const double* point_mass = a.point_mass;
  const double* __restrict lumped_mass = a.lumped_mass;
  double* mass = a.mass;
  Vec3* __restrict v = a.v;
  const double mass_scale = a.mass_scale, keep = a.keep, first_B_dt = a.first_B_dt;
  const int shift = a.lock_shift;
  for (std::uint32_t n = 0; n < a.n; ++n) {
    const ParticleId p = ids[n];
    if (active && !active[p]) continue;
    const std::uint8_t locked = (lock[p] >> shift) & kLockTranslation;
    const Vec3 f = F[p];
    double M;
    if constexpr (kPrepare) {
      const double s = S[p];
      if constexpr (kPhysical) {
        const double m = lumped_mass ? point_mass[p] + lumped_mass[p] : point_mass[p];
        M = m > 0 || locked != kLockTranslation ? m : 1.0;
      } else {
        M = mass_scale * s;
      }
      if (!all_finite(f, s) || !(M > 0)) [[unlikely]] {
        t.bad = true;
        continue;
      }
      mass[p] = M;
      t.residual2 = std::max(t.residual2, locked == 0 ? f.squaredNorm() : f.cwiseProduct(free_of[locked]).squaredNorm());
    } else {
      M = mass[p];
    }
    Vec3 vn = keep * v[p] + (first_B_dt / M) * f;  // eq. 3.11 / 3.26, 3.21 / 3.27
    if (locked != 0) vn = vn.cwiseProduct(free_of[locked]);  // free on every axis: times 1 changes nothing
    v[p] = vn;
    const double v2 = vn.squaredNorm();
    t.ke += M * v2;  // eq. 3.28
    t.momentum2 = std::max(t.momentum2, M * M * v2);
  }
  return t;
}

// The kinetic energy goes on from `so_far` (rotation after translation, as
// one sum); the largest terms are kept apart.
KickTotals kick_pass(const KickPass& a, bool prepare, bool physical, double so_far) {
  const KickTotals start{so_far, 0, 0, false};
  if (!prepare) return kick_pass<false, false>(a, start);
  return physical ? kick_pass<true, true>(a, start) : kick_pass<true, false>(a, start);
}

}  // namespace

// A half element of line mass mu and length L turning about its node:
// mu L^3 / 24, the same about every axis (isotropic, thesis 3.2.4.2).
void Solver::sum_rotary_inertia() {
  for (ParticleId p : model_.particles.rotational.raw()) inertia_[p] = 0;
  for (const Beam6* b = model_.beam6s.awake_begin(); b != model_.beam6s.awake_end(); ++b) {
    const double I = b->line_mass * b->rest_length * b->rest_length * b->rest_length / 24;
    inertia_[b->i] += I;
    inertia_[b->j] += I;
  }
}

// Past a kinetic peak the frames turn back by the interpolation of their
// rotation vector that moves the positions back (eq. 3.29-3.31).
void Solver::turn_frames_back(double q) {
  Particles& P = model_.particles;
  const std::uint8_t *active = P.active.data(), *lock = P.lock.data();
  const Vec3* T = P.torque.data();
  Vec3* w = P.angular_velocity.data();
  Quat* R = P.orientation.data();
  const double dt = settings.dt;
  for (ParticleId p : P.rotational.raw()) {
    if (!active[p]) continue;
    const Vec3 Tf = T[p].cwiseProduct(free_rotation_axes(lock[p]));
    R[p] = turned(-dt * q * w[p] + 0.5 * dt * dt * q * Tf / inertia_[p], R[p]);
    w[p].setZero();
  }
}

// `prepare`: the masses of eq. 3.4 (or the physical ones) found in the
// kick's pass, as fused_kick_drift does for bars alone, each particle's
// force, stiffness and mass checked and used while in the cache; the
// arithmetic of prepare_masses then the kick. A force or mass the step
// cannot use is found after some velocities were kicked: they are reset,
// prepare_masses names the particle at fault, and no particle was moved.
void Solver::kick_drift(bool whole_kick, bool prepare) {
  Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  const std::uint8_t* lock = P.lock.data();
  const std::vector<ParticleId>& integrated = P.integrated.raw();
  const double dt = settings.dt;
  const Kick kick_factors = kick(whole_kick);
  const double first = kick_factors.first, keep = kick_factors.keep, B = kick_factors.B;
  const bool physical = settings.mass_mode == MassMode::Physical;
  const double mass_scale =
      settings.mass_factor * fictitious_mass_scale(settings.integrator) * 0.5 * settings.dt * settings.dt;  // eq. 3.4
  Vec3* v = P.velocity.data();
  const Vec3* F = P.force.data();
  const double* mass = mass_.data();
  const KickTotals moved = kick_pass({integrated.data(), std::uint32_t(integrated.size()), nullptr, lock, 0, F,
                                      P.stiffness.data(), P.point_mass.data(), P.lumped_mass.data(), mass_.data(), v,
                                      mass_scale, keep, first * B * dt},
                                     prepare, physical, 0.0);
  const std::vector<ParticleId>& rotating = P.rotational.raw();
  Vec3* w = P.angular_velocity.data();
  const Vec3* T = P.torque.data();
  if (prepare && physical && !rotating.empty()) sum_rotary_inertia();
  const KickTotals rotated = kick_pass({rotating.data(), std::uint32_t(rotating.size()), active, lock, 3, T,
                                        P.rot_stiffness.data(), inertia_.data(), nullptr, inertia_.data(), w,
                                       mass_scale, keep, first * B * dt},
                                      prepare, physical, moved.ke);
  if (moved.bad || rotated.bad) [[unlikely]] {
    reset_motion();
    prepare_masses();  // throws, naming the first particle at fault
    throw NumericalError("solver: a force or mass is not usable at step " + std::to_string(steps_) +
                         "; velocities were reset, no particle was moved");
  }
  if (prepare) {
    torque_residual_ = std::sqrt(rotated.residual2);
    residual_ = std::max(std::sqrt(moved.residual2), torque_residual_);
  }
  const double ke = rotated.ke, momentum2 = std::max(moved.momentum2, rotated.momentum2);
  if (!std::isfinite(ke)) [[unlikely]] {  // beyond the stability limit: the kick overflowed
    const NumericalError e =
        non_finite_motion(model_, nullptr, v, w, settings, steps_, "velocities were reset, no particle was moved");
    reset_motion();
    throw e;
  }
  Vec3* x = P.position.data();
  Quat* R = P.orientation.data();
  if (kinetic_peak_passed(ke)) {
    // Peak passed: move back to the interpolated peak (eq. 3.29-3.31), stop.
    // Frames turn back by the same interpolation of their rotation vector.
    const double q = peak_fraction(ke);
    for (ParticleId p : integrated) {
      const Vec3 Ff = F[p].cwiseProduct(free_axes(lock[p]));
      x[p] += dt * v[p] - dt * (1 + q) * v[p] + 0.5 * dt * dt * q * Ff / mass[p];
      v[p].setZero();
    }
    turn_frames_back(q);
    record_reset();
    return;
  }
  for (ParticleId p : integrated) x[p] += dt * v[p];  // eq. 3.12
  drift_frames(rotating.data(), std::uint32_t(rotating.size()), active, dt, w, R);  // eq. 3.19, turned in blocks
  record_energy(ke, momentum2);
  half_step_ = true;
}

namespace {

// fused_kick_drift's kick of one chunk's particles, with every pointer a
// local (no reloads through captured references) and the free axes of a
// lock looked up; the arithmetic of kick_drift, term for term. Scalar, but
// in three copies (simd_clones.hpp): the AVX copies' three-operand forms
// and 4-lane loads of the sums take a fifth fewer instructions.
struct KickArgs {
  const std::uint8_t* lock;
  const double *point_mass, *lumped_mass;
  double* S;
  Vec3* F;
  Vec3 *v, *x, *xn;
  double mass_scale, keep, first_B_dt, dt;  // first_B_dt = first * B * dt
};
struct KickSums {
  double ke = 0, momentum2 = 0, residual2 = 0;
  bool bad = false;
};

template <bool kPhysical, bool kDrift>
TENDRIL_SIMD_CLONES KickSums kick_particles(const ParticleId* __restrict ids, std::uint32_t begin, std::uint32_t end,
                                            const KickArgs& a, const ForceSum* __restrict forces, ParticleId base,
                                            KickSums sums = {}) {
  const std::uint8_t* __restrict lock = a.lock;
  double* __restrict S = a.S;
  Vec3* __restrict F = a.F;
  Vec3* __restrict v = a.v;
  const Vec3* __restrict x = a.x;
  Vec3* __restrict xn = a.xn;
  const double mass_scale = a.mass_scale, keep = a.keep, first_B_dt = a.first_B_dt, dt = a.dt;
  for (std::uint32_t n = begin; n < end; ++n) {
    const ParticleId p = ids[n];
    const ForceSum sum = forces[p - base];
    const Vec3 f(sum[0], sum[1], sum[2]);
    const double s = sum[3];
    F[p] = f;
    S[p] = s;
    const std::uint8_t locked = lock[p] & kLockTranslation;
    double M;
    if constexpr (kPhysical) {
      M = physical_mass(a.point_mass[p], a.lumped_mass[p], free_of[locked]);
    } else {
      M = mass_scale * s;
    }
    if (!all_finite(f, s) || !(M > 0)) [[unlikely]] {
      sums.bad = true;
      continue;
    }
    Vec3 vn = keep * v[p] + (first_B_dt / M) * f;  // eq. 3.11 / 3.26
    if (locked == 0) [[likely]] {  // free on every axis: times 1 changes nothing
      sums.residual2 = std::max(sums.residual2, f.squaredNorm());
    } else {
      const Vec3 free = free_of[locked];
      sums.residual2 = std::max(sums.residual2, f.cwiseProduct(free).squaredNorm());
      vn = vn.cwiseProduct(free);
    }
    v[p] = vn;
    const double v2 = vn.squaredNorm();
    sums.ke += M * v2;  // eq. 3.28
    sums.momentum2 = std::max(sums.momentum2, M * M * v2);
    if constexpr (kDrift) xn[p] = x[p] + dt * vn;  // eq. 3.12, taken only if the step is an ordinary one
  }
  return sums;
}

// A vector's row of four lanes, the fourth 0. (Filled by reference: a
// 32-byte vector returned by value draws GCC's ABI warning in the portable
// copy, inlined or not.)
[[gnu::always_inline]] inline void load_row(Lanes& row, const Vec3& a) { row = Lanes{a.x(), a.y(), a.z(), 0.0}; }

// kick_particles<false, kDrift> four particles at a time, each in a lane:
// the sums' rows and the velocities are turned into columns, the division,
// the velocities' update, the checks and the norms take one vector operation
// for four particles, and the results are turned back into rows. Each lane
// computes what the scalar loop computes, operation for operation; the
// kinetic energy is added lane after lane, in the particles' order; the
// maxima do not depend on the order. A group with a locked axis, a force
// that is not finite or a mass that is not positive goes through the
// scalar loop, which finds what is wrong as before. (Measured in stop 37:
// a fifth fewer instructions in the kick; callgrind, docs/performance.md.)
template <bool kDrift>
TENDRIL_SIMD_CLONES KickSums kick_particles_in_lanes(const ParticleId* __restrict ids, std::uint32_t begin,
                                                     std::uint32_t end, const KickArgs& a,
                                                     const ForceSum* __restrict forces, ParticleId base) {
  const std::uint8_t* __restrict lock = a.lock;
  double* __restrict S = a.S;
  Vec3* __restrict F = a.F;
  Vec3* __restrict v = a.v;
  const Vec3* __restrict x = a.x;
  Vec3* __restrict xn = a.xn;
  const double mass_scale = a.mass_scale, keep = a.keep, first_B_dt = a.first_B_dt, dt = a.dt;
  KickSums sums;
  Lanes most_residual2 = {0, 0, 0, 0}, most_momentum2 = {0, 0, 0, 0};  // lane by lane, reduced at the end
  std::uint32_t n = begin;
  for (; n + 4 <= end; n += 4) {
    const ParticleId p[4] = {ids[n], ids[n + 1], ids[n + 2], ids[n + 3]};
    if ((lock[p[0]] | lock[p[1]] | lock[p[2]] | lock[p[3]]) & kLockTranslation) {
      sums = kick_particles<false, kDrift>(ids, n, n + 4, a, forces, base, sums);
      continue;
    }
    // The four particles' sums, one row each, become the columns x, y, z and S.
    Lanes fx = forces[p[0] - base], fy = forces[p[1] - base], fz = forces[p[2] - base], s = forces[p[3] - base];
    transpose(fx, fy, fz, s);
    const Lanes M = mass_scale * s;
    const LaneBits usable = ((fx - fx) + (fy - fy) + (fz - fz) + (s - s) == 0) & (M > 0);
    if (!(usable[0] & usable[1] & usable[2] & usable[3])) [[unlikely]] {
      sums = kick_particles<false, kDrift>(ids, n, n + 4, a, forces, base, sums);
      continue;
    }
#pragma GCC unroll 4
    for (int l = 0; l < 4; ++l) {
      const ForceSum& row = forces[p[l] - base];
      F[p[l]] = Vec3(row[0], row[1], row[2]);
      S[p[l]] = row[3];
    }
    Lanes vx, vy, vz, unused;
    load_row(vx, v[p[0]]), load_row(vy, v[p[1]]), load_row(vz, v[p[2]]), load_row(unused, v[p[3]]);
    transpose(vx, vy, vz, unused);  // the same for the velocities
    const Lanes A = first_B_dt / M;
    vx = keep * vx + A * fx;  // eq. 3.11 / 3.26
    vy = keep * vy + A * fy;
    vz = keep * vz + A * fz;
    const Lanes residual2 = fx * fx + fy * fy + fz * fz;
    const Lanes v2 = vx * vx + vy * vy + vz * vz;
    const Lanes ke = M * v2;  // eq. 3.28
    const Lanes momentum2 = M * M * v2;
    most_residual2 = most_residual2 < residual2 ? residual2 : most_residual2;
    most_momentum2 = most_momentum2 < momentum2 ? momentum2 : most_momentum2;
    sums.ke = sums.ke + ke[0] + ke[1] + ke[2] + ke[3];
    Lanes rows[4] = {vx, vy, vz, Lanes{0, 0, 0, 0}};
    transpose(rows[0], rows[1], rows[2], rows[3]);  // back to one particle a row
#pragma GCC unroll 4
    for (int l = 0; l < 4; ++l) {
      const Vec3 vn(rows[l][0], rows[l][1], rows[l][2]);
      v[p[l]] = vn;
      if constexpr (kDrift) xn[p[l]] = x[p[l]] + dt * vn;  // eq. 3.12
    }
  }
  for (int l = 0; l < 4; ++l) {
    sums.residual2 = std::max(sums.residual2, most_residual2[l]);
    sums.momentum2 = std::max(sums.momentum2, most_momentum2[l]);
  }
  return kick_particles<false, kDrift>(ids, n, end, a, forces, base, sums);
}

// fused_kick_drift's move back to the kinetic peak (eq. 3.29-3.31) of one
// chunk's particles, kick_drift's arithmetic term for term, with the
// kick's local pointers and copies (a lambda reloaded its captured
// pointers after every store).
template <bool kPhysical>
TENDRIL_SIMD_CLONES void peak_back_particles(const ParticleId* __restrict ids, std::uint32_t begin,
                                             std::uint32_t end, const KickArgs& a, double q) {
  const std::uint8_t* __restrict lock = a.lock;
  const double* __restrict S = a.S;
  const Vec3* __restrict F = a.F;
  Vec3* __restrict v = a.v;
  Vec3* __restrict x = a.x;
  const double mass_scale = a.mass_scale, dt = a.dt;
  for (std::uint32_t n = begin; n < end; ++n) {
    const ParticleId p = ids[n];
    const Vec3 free = free_of[lock[p] & kLockTranslation];
    const Vec3 Ff = F[p].cwiseProduct(free);
    const double M = kPhysical ? physical_mass(a.point_mass[p], a.lumped_mass[p], free) : mass_scale * S[p];
    x[p] += dt * v[p] - dt * (1 + q) * v[p] + 0.5 * dt * dt * q * Ff / M;
    v[p].setZero();
  }
}

}  // namespace

bool Solver::fused_kick_drift_applies() const {
  // Auto, read between steps (fused_step_bytes): what its next step takes.
  const Integrator i = settings.integrator == Integrator::Auto ? auto_choice_ : settings.integrator;
  return (i == Integrator::Leapfrog || i == Integrator::SymplecticEuler) && model_.joints.items.empty() &&
         model_.goals.empty() && couples().empty() && model_.clamp_darts.empty() && model_.rigid_joints.empty() &&
         !pressure_acts();
}

// kick_drift for a model of bars, spline-beam hinges, 6-DOF beams and CST
// triangles alone, without a separate force pass: each chunk's particles
// (and rotating particles) are kicked as soon as their forces are complete
// (its own bars, its inbox, its hinges, its 6-DOF elements, then its
// triangles and projected corners), while they are still in the cache. The
// arithmetic is kick_drift's; sums over particles (kinetic energy) are
// gathered per chunk and added in chunk order. A force, stiffness or mass
// the step cannot use is found only after some velocities were kicked:
// the velocities are reset, prepare_masses names the particle as for the
// other integrators, and no particle was moved.
// When every particle slot is integrated (no passive or free slot whose
// position would have to be carried over), the drift happens in the same
// pass: each kicked particle's new position x + dt v goes into xs_, the
// bars keep reading the old ones, and xs_ becomes the model's positions by
// a swap once the step is known to be an ordinary one. A kinetic peak or an
// error leaves the old positions as they were, so every path computes what
// the two-pass form computes, bit for bit.
// A hinge that cannot be evaluated (a zero-length link) is found after
// some velocities were kicked: they are reset and it is named, as the
// element pass names it, no particle moved.
void Solver::fused_kick_drift(bool whole_kick) {
  Particles& P = model_.particles;
  const BarChunks& chunks = bar_chunks();
  const bool hinged = model_.hinges.awake > 0, membranes = model_.csts.awake > 0;
  const bool rotating = !P.rotational.empty();
  if (hinged) hinge_chunks();
  if (membranes) prepare_cst_chunks();
  if (rotating) prepare_beam6_chunks();
  chunk_sums_.resize(chunks.chunks.size());
  const bool one_pass = P.integrated.size() == P.capacity();
  if (one_pass && xs_.size() != P.capacity()) xs_.resize(P.capacity());
  Vec3* xn = one_pass ? xs_.data() : nullptr;
  const bool physical = settings.mass_mode == MassMode::Physical;
  const double mass_scale =
      settings.mass_factor * fictitious_mass_scale(settings.integrator) * 0.5 * settings.dt * settings.dt;  // eq. 3.4
  const double dt = settings.dt;
  const Kick kick_factors = kick(whole_kick);
  const double first = kick_factors.first, keep = kick_factors.keep, B = kick_factors.B;
  const std::uint8_t* lock = P.lock.data();
  const double *point_mass = P.point_mass.data(), *lumped_mass = P.lumped_mass.data();
  Vec3 *F = P.force.data(), *v = P.velocity.data(), *x = P.position.data();
  double* S = P.stiffness.data();
  const KickArgs args{lock, point_mass, lumped_mass, S, F, v, x, xn, mass_scale, keep, first * B * dt, dt};
  // Rotation: the torques, kicked as kick_drift kicks them.
  const std::uint8_t* active = P.active.data();
  Vec3 *T = P.torque.data(), *w = P.angular_velocity.data();
  double* K = P.rot_stiffness.data();
  Quat* R = P.orientation.data();
  if (rotating && physical) sum_rotary_inertia();
  const std::uint64_t pass = new_chunk_pass();
  auto kick_chunk = [&](std::uint32_t c) {
    const BarChunks::Chunk& ch = chunks.chunks[c];
    ForceSum* sums = chunk_force_sums(c, x, pass);
    const std::uint32_t bad_hinge = hinged ? chunk_hinge_sums(c, x, sums) : kNone;
    if (bad_hinge != kNone) [[unlikely]] {
      chunk_sums_[c] = {0, 0, 0, false, bad_hinge};
      return;
    }
    ForceSum* turns = rotating ? chunk_beam6_sums(c, x, R, sums) : nullptr;
    if (membranes) chunk_cst_sums(c, x, sums);
    const ParticleId base = ParticleId(c) << chunks.shift;
    const ParticleId* ids = chunks.particles.data();
    const std::uint32_t b = ch.particles_begin, e = ch.particles_end;
    const KickSums k = physical ? (xn ? kick_particles<true, true>(ids, b, e, args, sums, base)
                                      : kick_particles<true, false>(ids, b, e, args, sums, base))
                                : (xn ? kick_particles_in_lanes<true>(ids, b, e, args, sums, base)
                                      : kick_particles_in_lanes<false>(ids, b, e, args, sums, base));
    ChunkSums out{k.ke, k.momentum2, k.residual2, k.bad, kNone, 0.0};
    if (rotating) {
      const ElementShares& share = rotating_chunk_shares_;
      const ParticleId* rids = rotating_by_chunk_.data() + share.begin[c];
      const std::uint32_t nr = share.begin[c + 1] - share.begin[c];
      for (std::uint32_t n = 0; n < nr; ++n) {
        const ParticleId p = rids[n];
        const ForceSum& t = turns[p - base];
        T[p] = Vec3(t[0], t[1], t[2]);
        K[p] = t[3];
      }
      double* inertia = inertia_.data();
      const KickTotals r =
          kick_pass({rids, nr, active, lock, 3, T, K, inertia, nullptr, inertia, w, mass_scale, keep, first * B * dt},
                    true, physical, k.ke);
      out.ke = r.ke;
      out.momentum2 = std::max(out.momentum2, r.momentum2);
      out.bad |= r.bad;
      out.torque2 = r.residual2;
    }
    chunk_sums_[c] = out;
  };
  for_chunks([&](std::uint32_t c) { chunk_bar_sums(c, x, pass, true); }, kick_chunk);
  ++evaluations_;
  double ke = 0, momentum2 = 0, residual2 = 0, torque2 = 0;
  bool bad = false;
  std::uint32_t bad_hinge = kNone;
  for (const ChunkSums& s : chunk_sums_) {
    ke += s.ke;
    momentum2 = std::max(momentum2, s.momentum2);
    residual2 = std::max(residual2, s.residual2);
    torque2 = std::max(torque2, s.torque2);
    bad |= s.bad;
    bad_hinge = std::min(bad_hinge, s.bad_hinge);
  }
  if (bad_hinge != kNone) [[unlikely]] {
    reset_motion();
    throw_degenerate_hinge(model_, model_.hinges.awake_begin()[bad_hinge], x,
                           "velocities were reset, no particle was moved");
  }
  if (bad) [[unlikely]] {
    reset_motion();
    prepare_masses();  // throws, naming the first particle at fault
    throw NumericalError("solver: a force or mass is not usable at step " + std::to_string(steps_) +
                         "; velocities were reset, no particle was moved");
  }
  torque_residual_ = std::sqrt(torque2);
  residual_ = std::max(std::sqrt(residual2), torque_residual_);
  if (!std::isfinite(ke)) [[unlikely]] {  // beyond the stability limit: the kick overflowed
    const NumericalError e = non_finite_motion(model_, nullptr, v, rotating ? w : nullptr, settings, steps_,
                                               "velocities were reset, no particle was moved");
    reset_motion();
    throw e;
  }
  if (kinetic_peak_passed(ke)) {  // eq. 3.29-3.31, as kick_drift
    const double q = peak_fraction(ke);
    for_chunks([&](std::uint32_t c) {
      const BarChunks::Chunk& ch = chunks.chunks[c];
      const ParticleId* ids = chunks.particles.data();
      if (physical) peak_back_particles<true>(ids, ch.particles_begin, ch.particles_end, args, q);
      else peak_back_particles<false>(ids, ch.particles_begin, ch.particles_end, args, q);
    });
    if (rotating) turn_frames_back(q);
    record_reset();
    return;
  }
  if (one_pass)
    std::swap(P.position.raw(), xs_);  // the drift was done in the kick's pass
  else
    for_chunks([&](std::uint32_t c) {
      const BarChunks::Chunk& ch = chunks.chunks[c];
      for (std::uint32_t n = ch.particles_begin; n < ch.particles_end; ++n) {
        const ParticleId p = chunks.particles[n];
        x[p] += dt * v[p];  // eq. 3.12
      }
    });
  if (rotating)  // eq. 3.19, turned in blocks, each chunk's frames on the thread that kicked them
    for_chunks([&](std::uint32_t c) {
      const std::vector<std::uint32_t>& begin = rotating_chunk_shares_.begin;
      drift_frames(rotating_by_chunk_.data() + begin[c], begin[c + 1] - begin[c], active, dt, w, R);
    });
  record_energy(ke, momentum2);
  half_step_ = true;
}

// The traffic of fused_kick_drift, pass by pass (keep in step with it).
double Solver::fused_step_bytes() const {
  if (!fused_kick_drift_applies()) return 0;
  const BarChunks& B = bar_chunks();
  const Particles& P = model_.particles;
  const double particles = double(B.particles.size()), bars = double(B.bar_count()),
               crossing = double(B.crossing_count());
  const Vec3 g = model_.gravity;
  const bool masses = settings.mass_mode == MassMode::Physical || !(g.x() == 0 && g.y() == 0 && g.z() == 0 &&
                                                                    !std::signbit(g.x()) && !std::signbit(g.y()) &&
                                                                    !std::signbit(g.z()));
  const bool one_pass = P.integrated.size() == P.capacity();
  // Forces and kick, per particle: its id, load, point and lumped mass (the
  // weight or the physical mass, else not read), force and stiffness
  // written, lock, position gathered by the bars, velocity read and
  // written, in one pass the new position written.
  const double kick = particles * (4 + 24 + (masses ? 16 : 0) + 24 + 8 + 1 + 24 + 24 + 24 + (one_pass ? 24 : 0));
  // Per bar its ends, k, rest length, prestress, and its cable flag in a
  // chunk with cables (a block of bars that share them: the first's); per
  // crossing bar its slot written, then read through the inbox (particle,
  // slot).
  double constants = 0;
  for (const BarChunks::Chunk& c : B.chunks)
    for (std::uint32_t e0 = c.bars_begin; e0 < c.bars_end; e0 += BarChunks::kBlock) {
      const double n = std::min(BarChunks::kBlock, c.bars_end - e0), per_bar = c.cables ? 32 : 24;
      constants += (B.same_block(c, e0) ? 1 : n) * per_bar;
    }
  const double elements = bars * (4 + 4) + constants + crossing * (24 + 8 + 4 + 4 + 24 + 8);
  // Per hinge of a chunk its ends, EI and rest curvature (hinge_chunks.hpp;
  // a block of hinges that share them: the first's).
  double hinges = 0;
  if (model_.hinges.awake > 0) {
    const HingeChunks& H = hinge_chunks();
    hinges = double(H.item_count()) * (4 + 4 + 4);
    for (std::size_t c = 0; c < H.begin.size(); ++c)
      for (std::uint32_t e0 = H.begin[c]; e0 < H.end[c]; e0 += HingeChunks::kBlock)
        hinges += 16 * (H.same_block(std::uint32_t(c), e0) ? 1.0 : std::min(HingeChunks::kBlock, H.end[c] - e0));
  }
  // Per triangle of a chunk its index and the plan's ends, stresses,
  // G-string density, flags and slots; per projected corner its index,
  // particle, flag and sums read and cleared (cst_plan.hpp).
  double membranes = 0;
  if (model_.csts.awake > 0) {
    prepare_cst_chunks();
    membranes = double(cst_chunks_.triangle_count()) * (4 + 12 + 16 + 8 + 1 + 12 + 1) +
                double(cst_chunks_.corner_count()) * (4 + 4 + 1 + 72 + 72);
  }
  // Per 6-DOF element of a chunk the chunk plan's ends, beam-end frames
  // and constants (a block in a run of the same frames or constants reads
  // one entry's), both nodes' frames gathered; per rotating
  // particle its moment, torque and rotational stiffness written, inertia,
  // angular velocity read and written, then the drift: angular velocity
  // read, frame read and written (beam6_plan.hpp).
  double six_dof = 0;
  if (!P.rotational.empty()) {
    prepare_beam6_chunks();
    const Beam6Chunks& B = beam6_chunks_;
    for (std::size_t c = 0; c < B.begin.size(); ++c) six_dof += B.plan.step_bytes(B.begin[c], B.end[c] - B.begin[c]);
    six_dof += double(B.entry_count()) * 64 +
              double(P.rotational.size()) * (4 + 1 + 1 + 24 + 24 + 8 + 8 + 24 + 24 + 24 + 32 + 32);
  }
  // Two passes: id, position read and written, velocity read.
  const double drift = one_pass ? 0 : particles * (4 + 24 + 24 + 24);
  return kick + elements + hinges + membranes + six_dof + drift;
}

void Solver::synchronize_velocities() {
  if (!half_step_) return;
  // Leapfrog left v(t - dt/2); the synchronous methods start from v(t).
  Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  const std::uint8_t* lock = P.lock.data();
  Vec3* vel = P.velocity.data();
  const Vec3* force = P.force.data();
  const double h = 0.5 * settings.dt;
  for (ParticleId p : P.integrated.raw())
    vel[p] = (vel[p] + (h / mass_[p]) * force[p]).cwiseProduct(free_axes(lock[p]));
  Vec3* w = P.angular_velocity.data();
  const Vec3* T = P.torque.data();
  for (ParticleId p : P.rotational.raw())
    if (active[p]) w[p] = (w[p] + (h / inertia_[p]) * T[p]).cwiseProduct(free_rotation_axes(lock[p]));
  half_step_ = false;
}

void Solver::integrate_velocity_verlet() {
  // x' = x + dt v + dt^2/2 a;  v' = v + dt/2 (a + a'), with the damping force
  // -c M v taken by the same trapezoidal rule (C = c dt):
  //   v_half = (1 - C/2) v + dt/2 a,  x' = x + dt v_half,
  //   v' = (v_half + dt/2 a') / (1 + C/2).
  synchronize_velocities();
  Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  const std::uint8_t* lock = P.lock.data();
  const std::vector<ParticleId>& integrated = P.integrated.raw();
  const double dt = settings.dt, h = 0.5 * dt, C = viscous_rate();
  const Vec3 *x = P.position.data(), *v = P.velocity.data(), *F = P.force.data();
  const double* mass = mass_.data();
  for (ParticleId p : integrated) {
    const Vec3 free = free_axes(lock[p]);
    vs_[p] = ((1 - C / 2) * v[p] + (h / mass[p]) * F[p]).cwiseProduct(free);
    xs_[p] = x[p] + dt * vs_[p];
  }
  const std::vector<ParticleId>& rotating = P.rotational.raw();
  const Quat* R = P.orientation.data();
  const Vec3 *w = P.angular_velocity.data(), *T = P.torque.data();
  const double* inertia = inertia_.data();
  for (ParticleId p : rotating) {
    if (!active[p]) {
      qs_[p] = R[p];
      continue;
    }
    ws_[p] = ((1 - C / 2) * w[p] + (h / inertia[p]) * T[p]).cwiseProduct(free_rotation_axes(lock[p]));
    qs_[p] = turned(dt * ws_[p], R[p]);
  }
  stage_forces();
  double ke = 0, momentum2 = 0;
  for (ParticleId p : integrated) {
    const double M = mass[p];
    vs_[p] = (vs_[p] + (h / M) * Fs_[p].cwiseProduct(free_axes(lock[p]))) / (1 + C / 2);
    ke += M * vs_[p].squaredNorm();
    momentum2 = std::max(momentum2, M * M * vs_[p].squaredNorm());
  }
  for (ParticleId p : rotating) {
    if (!active[p]) continue;
    const double I = inertia[p];
    ws_[p] = (ws_[p] + (h / I) * Ts_[p].cwiseProduct(free_rotation_axes(lock[p]))) / (1 + C / 2);
    ke += I * ws_[p].squaredNorm();
    momentum2 = std::max(momentum2, I * I * ws_[p].squaredNorm());
  }
  commit(xs_.data(), vs_.data(), qs_.data(), ws_.data(), ke, momentum2);
}

void Solver::integrate_midpoint() {
  // Explicit midpoint (RK2): the state at t + dt/2 from the slopes at t, then
  // the whole step with the slopes at t + dt/2. Acceleration a = F/M - c v.
  synchronize_velocities();
  Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  const std::uint8_t* lock = P.lock.data();
  const std::vector<ParticleId>& integrated = P.integrated.raw();
  const double dt = settings.dt, h = 0.5 * dt, c = viscous_rate() / dt;
  const Vec3 *x = P.position.data(), *v = P.velocity.data(), *F = P.force.data();
  const double* mass = mass_.data();
  for (ParticleId p : integrated) {
    const Vec3 free = free_axes(lock[p]);
    const Vec3 v0 = v[p].cwiseProduct(free);
    const Vec3 a0 = F[p].cwiseProduct(free) / mass[p] - c * v0;
    xs_[p] = x[p] + h * v0;
    vs_[p] = v0 + h * a0;
  }
  const std::vector<ParticleId>& rotating = P.rotational.raw();
  const Quat* R = P.orientation.data();
  const Vec3 *w = P.angular_velocity.data(), *T = P.torque.data();
  const double* inertia = inertia_.data();
  for (ParticleId p : rotating) {
    if (!active[p]) {
      qs_[p] = R[p];
      continue;
    }
    const Vec3 free = free_rotation_axes(lock[p]);
    const Vec3 w0 = w[p].cwiseProduct(free);
    const Vec3 a0 = T[p].cwiseProduct(free) / inertia[p] - c * w0;
    qs_[p] = turned(h * w0, R[p]);
    ws_[p] = w0 + h * a0;
  }
  stage_forces();
  double ke = 0, momentum2 = 0;
  for (ParticleId p : integrated) {
    const Vec3 free = free_axes(lock[p]);
    const double M = mass[p];
    const Vec3 am = Fs_[p].cwiseProduct(free) / M - c * vs_[p];
    xs_[p] = x[p] + dt * vs_[p];
    vs_[p] = v[p].cwiseProduct(free) + dt * am;
    ke += M * vs_[p].squaredNorm();
    momentum2 = std::max(momentum2, M * M * vs_[p].squaredNorm());
  }
  for (ParticleId p : rotating) {
    if (!active[p]) continue;
    const Vec3 free = free_rotation_axes(lock[p]);
    const double I = inertia[p];
    const Vec3 am = Ts_[p].cwiseProduct(free) / I - c * ws_[p];
    qs_[p] = turned(dt * ws_[p], R[p]);
    ws_[p] = w[p].cwiseProduct(free) + dt * am;
    ke += I * ws_[p].squaredNorm();
    momentum2 = std::max(momentum2, I * I * ws_[p].squaredNorm());
  }
  commit(xs_.data(), vs_.data(), qs_.data(), ws_.data(), ke, momentum2);
}

void Solver::integrate_rk4() {
  // Eq. 3.13-3.15: L_j are the velocity estimates, K_j the accelerations
  // a = F/M - c v at (x + h_j L_{j-1}, L_j); sum_x_ and sum_v_ gather
  // L1 + 2 L2 + 2 L3 + L4 and K1 + 2 K2 + 2 K3 + K4. vs_ holds the current L.
  synchronize_velocities();
  Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  const std::uint8_t* lock = P.lock.data();
  const std::vector<ParticleId>& integrated = P.integrated.raw();
  const double dt = settings.dt, c = viscous_rate() / dt;
  const Vec3 *x = P.position.data(), *v = P.velocity.data(), *F = P.force.data();
  const double* mass = mass_.data();
  for (ParticleId p : integrated) {  // j = 1
    const Vec3 free = free_axes(lock[p]);
    const Vec3 L1 = v[p].cwiseProduct(free);
    const Vec3 K1 = F[p].cwiseProduct(free) / mass[p] - c * L1;
    sum_x_[p] = L1;
    sum_v_[p] = K1;
    xs_[p] = x[p] + (0.5 * dt) * L1;
    vs_[p] = L1 + (0.5 * dt) * K1;
  }
  // Rotation, eq. 3.22-3.25: L_R are angular velocities, K_R angular
  // accelerations at the frames R_T(h L_R) R.
  const std::vector<ParticleId>& rotating = P.rotational.raw();
  const Quat* R = P.orientation.data();
  const Vec3 *w = P.angular_velocity.data(), *T = P.torque.data();
  const double* inertia = inertia_.data();
  for (ParticleId p : rotating) {
    if (!active[p]) {
      qs_[p] = R[p];
      continue;
    }
    const Vec3 free = free_rotation_axes(lock[p]);
    const Vec3 L1 = w[p].cwiseProduct(free);
    const Vec3 K1 = T[p].cwiseProduct(free) / inertia[p] - c * L1;
    sum_r_[p] = L1;
    sum_w_[p] = K1;
    qs_[p] = turned((0.5 * dt) * L1, R[p]);
    ws_[p] = L1 + (0.5 * dt) * K1;
  }
  // j = 2, 3: weight 2; the next stage sits at h = dt/2, then dt.
  for (double h : {0.5 * dt, dt}) {
    stage_forces();
    for (ParticleId p : integrated) {
      const Vec3 free = free_axes(lock[p]);
      const Vec3 L = vs_[p];
      const Vec3 K = Fs_[p].cwiseProduct(free) / mass[p] - c * L;
      sum_x_[p] += 2 * L;
      sum_v_[p] += 2 * K;
      xs_[p] = x[p] + h * L;
      vs_[p] = v[p].cwiseProduct(free) + h * K;
    }
    for (ParticleId p : rotating) {
      if (!active[p]) continue;
      const Vec3 free = free_rotation_axes(lock[p]);
      const Vec3 L = ws_[p];
      const Vec3 K = Ts_[p].cwiseProduct(free) / inertia[p] - c * L;
      sum_r_[p] += 2 * L;
      sum_w_[p] += 2 * K;
      qs_[p] = turned(h * L, R[p]);
      ws_[p] = w[p].cwiseProduct(free) + h * K;
    }
  }
  stage_forces();  // j = 4
  double ke = 0, momentum2 = 0;
  for (ParticleId p : integrated) {
    const Vec3 free = free_axes(lock[p]);
    const double M = mass[p];
    const Vec3 L = vs_[p];
    const Vec3 K = Fs_[p].cwiseProduct(free) / M - c * L;
    xs_[p] = x[p] + (dt / 6) * (sum_x_[p] + L);                  // eq. 3.14
    vs_[p] = v[p].cwiseProduct(free) + (dt / 6) * (sum_v_[p] + K);  // eq. 3.13
    ke += M * vs_[p].squaredNorm();
    momentum2 = std::max(momentum2, M * M * vs_[p].squaredNorm());
  }
  for (ParticleId p : rotating) {
    if (!active[p]) continue;
    const Vec3 free = free_rotation_axes(lock[p]);
    const double I = inertia[p];
    const Vec3 L = ws_[p];
    const Vec3 K = Ts_[p].cwiseProduct(free) / I - c * L;
    qs_[p] = turned((dt / 6) * (sum_r_[p] + L), R[p]);              // eq. 3.22-3.23
    ws_[p] = w[p].cwiseProduct(free) + (dt / 6) * (sum_w_[p] + K);  // eq. 3.24
    ke += I * ws_[p].squaredNorm();
    momentum2 = std::max(momentum2, I * I * ws_[p].squaredNorm());
  }
  commit(xs_.data(), vs_.data(), qs_.data(), ws_.data(), ke, momentum2);
}

void Solver::commit(const Vec3* xn, const Vec3* vn, const Quat* qn, const Vec3* wn, double ke, double momentum2) {
  Particles& P = model_.particles;
  const std::uint8_t* active = P.active.data();
  const std::vector<ParticleId>& integrated = P.integrated.raw();
  Vec3 *pos = P.position.data(), *vel = P.velocity.data(), *w = P.angular_velocity.data();
  Quat* R = P.orientation.data();
  const std::vector<ParticleId>& rotating = P.rotational.raw();
  bool finite = std::isfinite(ke);
  for (std::size_t k = 0; k < integrated.size() && finite; ++k)
    finite = xn[integrated[k]].allFinite() && vn[integrated[k]].allFinite();
  for (ParticleId p : rotating)
    if (active[p]) finite = finite && qn[p].coeffs().allFinite() && wn[p].allFinite();
  if (!finite) [[unlikely]]  // checked before anything is written: the model stays as it was
    throw non_finite_motion(model_, xn, vn, rotating.empty() ? nullptr : wn, settings, steps_,
                            "no particle was moved");
  if (kinetic_peak_passed(ke)) {  // stay at the step's start: the discrete peak
    for (ParticleId p : integrated) vel[p].setZero();
    for (ParticleId p : rotating)
      if (active[p]) w[p].setZero();
    record_reset();
    return;
  }
  for (ParticleId p : integrated) {
    pos[p] = xn[p];
    vel[p] = vn[p];
  }
  for (ParticleId p : rotating) {
    if (!active[p]) continue;
    R[p] = qn[p];
    w[p] = wn[p];
  }
  record_energy(ke, momentum2);
}

}  // namespace tendril
