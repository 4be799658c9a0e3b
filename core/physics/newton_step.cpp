// The static Newton solver's step (integrator "newton"): one Newton
// iteration on the static residual F(x) = 0, no masses, no time.
//   K(x) dx = F(x), then x += alpha dx
// with K the exact tangent (newton.hpp). alpha: 1 when the energy still
// falls there (its slope along dx, -F(x + alpha dx) . dx, needs only the
// forces), else the minimum along dx found by regula falsi on that slope
// (flat to half its start, at most kTrials force evaluations). Far from
// equilibrium a full step overshoots (a flat prestressed net's first step
// is the linear membrane, whose bars then stretch). Halving alpha until the
// residual's 2-norm fell took alpha = 1/8 to 1/2 in the first four steps of
// the 800 x 800 net, 7 steps in all, where the energy's minimum allowed
// longer ones. When K is not positive definite (a bar in compression, a
// mechanism) or dx does not lead downhill, the step tries again with
// K + shift diag(K), shift from 1e-4 up to 1e2: a more and more
// gradient-like, shorter step. If none works, the particles stay where they
// are and the run's verdict says it stalled.
// Velocities stay zero. The residual and forces the step leaves are those at
// its end (the line search evaluated them), so a run stops on the iteration
// that reached the tolerance, not one later.
#include <cmath>
#include <string>

#include "physics/free_axes.hpp"
#include "physics/newton.hpp"
#include "physics/solver.hpp"

namespace tendril {

namespace {

// |F|^2 over the free coordinates and the largest free component's size;
// false when a force is not finite.
bool free_norms(const Particles& P, const Vec3* F, double& sum2, double& largest) {
  sum2 = 0, largest = 0;
  for (ParticleId p : P.integrated.raw()) {
    const Vec3 f = F[p].cwiseProduct(free_axes(P.lock[p]));
    if (!f.allFinite()) return false;
    sum2 += f.squaredNorm();
    largest = std::max(largest, f.squaredNorm());
  }
  largest = std::sqrt(largest);
  return true;
}

constexpr double kShifts[] = {0, 1e-4, 1e-2, 1, 1e2};
constexpr int kTrials = 6;  // force evaluations of a line search at most
// How well each iteration solves K dx = F: the step then cuts the residual
// by about this much where the tangent holds, so a few iterations reach
// 1e-6 of the load, while a looser solve would take more Newton iterations
// and a tighter one conjugate-gradient iterations that buy nothing.
constexpr double kSolveTolerance = 1e-2;

}  // namespace

Solver::NewtonWork Solver::newton_work() const {
  if (!newton_) return {};
  return {newton_->analyses(), newton_->factorizations(), newton_->iterations()};
}

const char* Solver::newton_refusal() const {
  if (const char* kind = NewtonSystem::unsupported(model_)) return kind;
  if (pressure_acts()) return "pressure or area loads";
  if (!couples().empty()) return "moments on 3-DOF beams";
  return nullptr;
}

void Solver::integrate_newton() {
  Particles& P = model_.particles;
  newton_stalled_ = false;
  if (const char* kind = newton_refusal())
    throw ModelError(std::string("solver: integrator \"newton\" has no tangent stiffness for ") + kind +
                     " yet (bars, cables and anchor, plane, line and length goals only); use another integrator for this model");
  if (!newton_) newton_ = std::make_shared<NewtonSystem>();
  compute_forces();
  double r2 = 0, largest = 0;
  if (!free_norms(P, P.force.data(), r2, largest))
    throw NumericalError("solver: a force is not finite at the start of newton step " + std::to_string(steps_) +
                         "; no particle was moved");
  residual_ = largest, torque_residual_ = 0;
  const double r0 = std::sqrt(r2);
  const std::vector<ParticleId>& integrated = P.integrated.raw();
  for (ParticleId p : integrated) P.velocity[p].setZero();
  kinetic_energy_ = 0, motion_ = 0, half_step_ = false, ke_samples_ = 0, ke_prev_ = ke_prev2_ = 0;
  if (r0 == 0) return;
  // The energy's slope along dx at x + alpha dx is -F(x + alpha dx) . dx
  // (dx is zero on locked axes); false when a force is not finite.
  auto trial = [&](double alpha, double& slope, double& norm2, double& top) {
    for (ParticleId p : integrated) xs_[p] = P.position[p] + alpha * vs_[p];
    accumulate_forces(xs_.data(), qs_.data(), Fs_.data(), Ss_.data(), Ts_.data(), Ks_.data());
    ++evaluations_;
    if (!free_norms(P, Fs_.data(), norm2, top)) return false;
    slope = 0;
    for (ParticleId p : integrated) slope -= Fs_[p].dot(vs_[p]);
    return std::isfinite(slope);
  };
  for (double shift : kShifts) {
    newton_->assemble(model_, P.position.data(), shift);
    if (!newton_->solve(model_, P.force.data(), vs_.data(), kSolveTolerance)) continue;
    double g0 = 0;
    for (ParticleId p : integrated) g0 -= P.force[p].dot(vs_[p]);
    if (!(g0 < 0)) continue;  // not downhill: K is no model of the energy here
    // alpha = 1 unless the energy rises again before it: then regula falsi
    // on the slope within [lo, hi] until it is flat to half its start.
    double lo = 0, g_lo = g0, hi = 1, g_hi = 0, alpha = 1, g = 0, s2 = 0, top = 0;
    bool found = false;
    for (int k = 0; k < kTrials; ++k) {
      const bool finite = trial(alpha, g, s2, top);
      if (finite && std::abs(g) <= 0.5 * std::abs(g0)) {
        found = true;  // nearly flat: about the minimum along dx
        break;
      }
      if (finite && g < 0) {
        if (alpha == 1) {
          found = true;  // still downhill at the full step: take it
          break;
        }
        lo = alpha, g_lo = g;
      } else {
        hi = alpha, g_hi = finite ? g : std::abs(g0);  // beyond the minimum (an overflow: far beyond)
      }
      alpha = lo + std::clamp(g_lo / (g_lo - g_hi), 0.1, 0.9) * (hi - lo);
    }
    if (!found) {
      if (!(lo > 0)) continue;  // nothing downhill found: a shorter, shifted step
      alpha = lo;
      if (!trial(alpha, g, s2, top)) continue;
    }
    for (ParticleId p : integrated) {
      P.position[p] = xs_[p];
      P.force[p] = Fs_[p];
      P.stiffness[p] = Ss_[p];
    }
    residual_ = top;
    return;
  }
  newton_stalled_ = true;
}

}  // namespace tendril
