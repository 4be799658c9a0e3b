#include "physics/run_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "model/model.hpp"
#include "physics/free_axes.hpp"
#include "physics/numerical_errors.hpp"
#include "physics/solver.hpp"

namespace tendril {

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::Converged: return "converged";
    case Verdict::MaxSteps: return "max_steps";
    case Verdict::Stalled: return "stalled";
    case Verdict::Diverged: return "diverged";
    case Verdict::Mechanism: return "mechanism";
  }
  return "?";
}

namespace {

// The loads and weights are what the solver starts every particle's force
// from (forces.cpp); the force on a locked axis is minus its reaction
// (Solver::reaction), read from the forces of the last evaluation.
double largest_force(const Model& m, bool reactions) {
  const Particles& P = m.particles;
  const Vec3 g = m.gravity;
  const bool weight = !g.isZero();
  double top2 = 0;
  for (ParticleId p : P.integrated.raw()) {
    Vec3 applied = P.load[p];
    if (weight) applied += (P.point_mass[p] + P.lumped_mass[p]) * g;
    top2 = std::max(top2, applied.squaredNorm());
    if (reactions && (P.lock[p] & kLockTranslation)) {
      const Vec3 locked = Vec3::Ones() - free_axes(P.lock[p]);
      top2 = std::max(top2, P.force[p].cwiseProduct(locked).squaredNorm());
    }
  }
  return std::sqrt(top2);
}

}  // namespace

double force_scale(const Model& m, const Solver&) { return largest_force(m, true); }

RunMonitor::RunMonitor(const Model& m, const Solver& s, const RunLimits& limits)
    : m_(m), s_(s), limits_(limits), resets0_(s.kinetic_resets()) {
  // The scale of the forces as the run starts (the forces of the last
  // evaluation; a model never stepped has none yet: its loads still count).
  scale_ = force_scale(m, s);
  baseline();
}

void RunMonitor::baseline() {
  const Particles& P = m_.particles;
  start_.assign(P.position.raw().begin(), P.position.raw().end());
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo = Vec3::Constant(inf), hi = Vec3::Constant(-inf);
  for (ParticleId p : P.integrated.raw()) lo = lo.cwiseMin(P.position[p]), hi = hi.cwiseMax(P.position[p]);
  // The model's size is also its longest element at rest (a cable whose
  // ends start at one point), and 1 mm at least, as runaway.cpp.
  double longest = 1e-3;
  for (const Bar& b : m_.bars.items) longest = std::max(longest, b.rest_length);
  for (const Beam6& b : m_.beam6s.items) longest = std::max(longest, b.rest_length);
  extent_ = lo.x() <= hi.x() ? std::max((hi - lo).maxCoeff(), longest) : longest;
  revision_ = m_.revision;
}

bool RunMonitor::observe() {
  ++r_.steps;
  r_.residual = s_.residual();
  r_.motion = s_.motion();
  if (limits_.relative > 0) scale_ = force_scale(m_, s_);
  r_.threshold = std::max(limits_.tolerance, limits_.relative * scale_);
  const bool at_rest = r_.residual < r_.threshold && r_.motion < r_.threshold;

  // Stalled is judged at the limit from the two halves of the run.
  if (r_.steps <= limits_.max_steps / 2)
    r_.best_before = r_.steps == 1 ? r_.residual : std::min(r_.best_before, r_.residual);
  else
    r_.best_after = r_.steps == limits_.max_steps / 2 + 1 ? r_.residual : std::min(r_.best_after, r_.residual);

  // Diverged: measured from the first step's residual, the force scale and
  // the tolerance; raised to the residual of the first step that leaves rest
  // (a model at rest, or with nothing on it yet, has no measure of its
  // forces) and of every step after a change of the model (a topology
  // change, or a rule or a front end that changed it: a grown or driven
  // model pulls harder, which is no instability).
  if (!started_) {
    started_ = true;
    r_.reference = std::max({r_.residual, scale_, limits_.tolerance});
  }
  if (m_.revision != revision_ || changed_ || (resting_ && !at_rest)) {
    r_.reference = std::max(r_.reference, r_.residual);
    if (m_.revision != revision_ || changed_) rebaseline_ = true;  // the travel too, at the next check
    revision_ = m_.revision;
    changed_ = false;
  }
  resting_ = at_rest;
  if (!(r_.residual <= kDivergence * r_.reference)) {
    // A rule may have loaded the model more since; not the reactions,
    // which grow with the divergence itself.
    r_.reference = std::max(r_.reference, largest_force(m_, false));
    if (!(r_.residual <= kDivergence * r_.reference)) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "the residual grew to %.3g N, %.3g times its reference %.3g N", r_.residual,
                    r_.residual / r_.reference, r_.reference);
      r_.detail = buf;
      r_.verdict = Verdict::Diverged;
      failed_ = true;
      return false;
    }
  }
  if (!at_rest && r_.steps % kMechanismCheckEvery == 0) check_mechanism();
  return at_rest;
}

void RunMonitor::check_mechanism() {
  if (rebaseline_) {
    baseline();
    rebaseline_ = false;
    return;
  }
  if (r_.residual < kMechanismResidual * r_.reference) return;  // settling: the residual fell
  const Particles& P = m_.particles;
  ParticleId far = kNone;
  double travel2 = 0;
  for (ParticleId p : P.integrated.raw()) {
    if (p >= start_.size()) continue;
    const double d2 = (P.position[p] - start_[p]).squaredNorm();
    if (d2 > travel2) travel2 = d2, far = p;
  }
  const double travel = std::sqrt(travel2);
  if (far == kNone || travel <= kMechanismTravel * extent_) return;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "%s travelled %.3g m, %.3g times the model's extent of %.3g m, with the residual still %.3g N: "
                "nothing resists the load along its path (no support, no stiffness)",
                describe_particle(m_, far).c_str(), travel, travel / extent_, extent_, r_.residual);
  r_.detail = buf;
  r_.verdict = Verdict::Mechanism;
  failed_ = true;
}

RunResult RunMonitor::finish(bool converged) {
  r_.converged = converged;
  r_.kinetic_resets = s_.kinetic_resets() - resets0_;
  r_.force_scale = force_scale(m_, s_);
  r_.relative_residual = r_.force_scale > 0 ? r_.residual / r_.force_scale : std::numeric_limits<double>::infinity();
  if (r_.steps == 0) r_.relative_residual = 0;
  if (converged) r_.verdict = Verdict::Converged;
  else if (!failed_) {
    // At the step limit: stalled when the second half of the run did not
    // lower the residual by kStallProgress (a run too short to tell ends
    // max_steps).
    const bool stalled = r_.steps >= kMinStallSteps && r_.steps > limits_.max_steps / 2 &&
                         r_.best_after >= kStallProgress * r_.best_before;
    r_.verdict = stalled ? Verdict::Stalled : Verdict::MaxSteps;
  }
  return r_;
}

}  // namespace tendril
