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

void Solver::chunk_bar_forces(const BarChunks::Chunk& c, const Vec3* x, Vec3* F, double* S) const {
  const Particles& P = model_.particles;
  const BarChunks& B = bar_chunks_;
  const Vec3 g = model_.gravity;
  const Vec3* load = P.load.data();
  const double *point_mass = P.point_mass.data(), *lumped_mass = P.lumped_mass.data();
  for (std::uint32_t n = c.particles_begin; n < c.particles_end; ++n) {
    const ParticleId p = B.particles[n];
    F[p] = load[p] + (point_mass[p] + lumped_mass[p]) * g;
    S[p] = 0;
  }
  const double gf = settings.geometric_factor;
  const ParticleId *bi = B.i.data(), *bj = B.j.data();
  const double *bk = B.k.data(), *rest = B.rest.data(), *pre = B.prestress.data();
  const std::uint8_t* cable = B.cable.data();
  // One bar: its tension (eq. 3.32, none in a slack cable), its force on i
  // (eq. 3.33) and the direct stiffness of both ends (eq. 3.35).
  auto bar = [&](std::uint32_t e, Vec3& f, double& s) {
    const Vec3 d = x[bj[e]] - x[bi[e]];
    const double L = d.norm();
    const double k = bk[e];
    double T = pre[e] + k * (L - rest[e]);
    if (cable[e] && T < 0) T = 0;
    s = k + (L > 0 && T > 0 ? gf * T / L : 0.0);
    if (!(L > 0)) return false;
    f = (T / L) * d;
    return true;
  };
  Vec3 f;
  double s;
  for (std::uint32_t e = c.bars_begin; e < c.crossing_begin; ++e) {
    if (bar(e, f, s)) {
      F[bi[e]] += f;
      F[bj[e]] -= f;
    }
    S[bi[e]] += s;
    S[bj[e]] += s;
  }
  Vec3* slot_f = bar_chunks_.slot_force.data() + c.slot_begin;
  double* slot_s = bar_chunks_.slot_stiffness.data() + c.slot_begin;
  for (std::uint32_t e = c.crossing_begin; e < c.bars_end; ++e, ++slot_f, ++slot_s) {
    if (bar(e, f, s)) F[bi[e]] += f;
    else f.setZero();
    S[bi[e]] += s;
    *slot_f = f;
    *slot_s = s;
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
  for (const Hinge* hp = model_.hinges.awake_begin(); hp != model_.hinges.awake_end(); ++hp) {
    const Hinge& h = *hp;
    const HingeForces f = hinge_forces(h, x);
    if (!std::isfinite(f.ka + f.kb)) [[unlikely]]
      throw_degenerate_hinge(model_, h, x);  // a zero-length link (coincident particles): stop, naming them
    S[h.j] += f.ka + f.kb;
    F[h.i] += f.fi;
    F[h.k] += f.fk;
    F[h.j] -= f.fi + f.fk;
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
  if (!model_.joints.items.empty()) accumulate_joint_forces(x, F, S);
  if (!model_.goals.empty()) accumulate_goal_forces(x, F, S);
  if (!model_.csts.items.empty()) accumulate_cst_forces(x, F, S);
}

}  // namespace tendril
