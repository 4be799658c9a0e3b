#pragma once
// How a run ended, and why (issue 11, "convergence that tells the truth"):
// Solver::run and m:run{} end with one of five verdicts, never with
// `converged` alone, so a run that stopped moving for a bad reason is not
// mistaken for one that found its shape.
//
//   converged  the residual and the motion (Solver::motion) are both below
//              the threshold: max(tolerance, relative * force_scale).
//   max_steps  the step limit was hit while the residual was still falling.
//   stalled    the step limit was hit and the residual had stopped falling:
//              over the second half of the run its lowest value is not
//              kStallProgress below the lowest of the first half (kinetic
//              damping resetting every few steps without progress does this,
//              and so does a residual at the floor of rounding).
//   diverged   the run was stopped because the residual grew kDivergence
//              times above its reference (the larger of the run's first
//              residual, the force scale and the tolerance, raised to the
//              residual of the first step that leaves rest and of the step
//              after any change of the model): an unstable time step or a
//              load the structure cannot carry. Positions are left finite
//              where the run stopped.
//   mechanism  the run was stopped because a particle travelled more than
//              kMechanismTravel times the model's extent since the run
//              started (or since the model last changed; the extent is
//              at least its longest element at rest) while the
//              residual stayed at least kMechanismResidual of its reference:
//              a load moving a part that nothing resists (no support along
//              it, no stiffness), which no step count would bring to rest.
//
// The force scale is the largest applied load on an integrated particle
// (its load plus its weight, m g) or support reaction (the force on its
// locked axes), at the current state: the forces the model's supports and
// loads exchange, so the residual is read against them (a beam loaded with
// 1e8 N cannot be brought below 1e-3 N by rounding, but below 1e-9 of its
// load). A prestressed model with neither loads nor supports has none (0):
// a relative tolerance alone never converges it.
#include <cstdint>
#include <string>
#include <vector>

#include "model/types.hpp"

namespace tendril {

class Model;
class Solver;

enum class Verdict { Converged, MaxSteps, Stalled, Diverged, Mechanism };
// "converged", "max_steps", "stalled", "diverged", "mechanism".
const char* verdict_name(Verdict v);

// When a run is at rest. With both, either suffices: the threshold is the
// larger of tolerance and relative * force_scale. 0 turns a rule off; at
// least one must be > 0.
struct RunLimits {
  double tolerance = 1e-3;  // absolute [N] (and [N m] for torques)
  double relative = 0;      // a fraction of the force scale
  std::uint64_t max_steps = 100000;
};

struct RunResult {
  std::uint64_t steps = 0;  // steps taken by this run
  double residual = 0;      // largest unconstrained force [N] or torque [N m]
  bool converged = false;   // verdict == Verdict::Converged
  Verdict verdict = Verdict::MaxSteps;
  double force_scale = 0;        // see above, at the run's end [N]
  double relative_residual = 0;  // residual / force_scale (infinite when the scale is 0)
  double threshold = 0;          // the threshold at the run's end [N]
  double motion = 0;             // Solver::motion at the run's end [N]
  std::uint64_t kinetic_resets = 0;  // during this run
  // stalled: the lowest residual of the first half of the run and of the
  // second; diverged: the reference the residual grew from.
  double best_before = 0, best_after = 0, reference = 0;
  std::string detail;  // diverged, mechanism: what was seen, naming a particle
};

// The classification's constants (see the header comment).
inline constexpr double kDivergence = 1e6;
inline constexpr double kStallProgress = 0.9;       // stalled: best_after >= 0.9 best_before
inline constexpr std::uint64_t kMinStallSteps = 200;  // a shorter run ends "max_steps"
inline constexpr double kMechanismTravel = 10;
inline constexpr double kMechanismResidual = 0.1;
inline constexpr std::uint64_t kMechanismCheckEvery = 64;

// The largest load, weight or support reaction on an integrated particle.
double force_scale(const Model& m, const Solver& s);

// Watches one run step by step; the run loop (Solver::run, m:run{} with its
// triggers) asks it after each step whether the model is at rest and whether
// the run must stop, and ends with finish().
class RunMonitor {
 public:
  RunMonitor(const Model& m, const Solver& s, const RunLimits& limits);
  // After each step: true when the residual and the motion are below the
  // threshold (at rest; the caller decides whether that ends the run).
  bool observe();
  // The caller changed the model between steps (a rule, a front end): the
  // divergence reference and the travel start again from there.
  void model_changed() { changed_ = true; }
  // Diverged or mechanism: the run must stop now.
  bool failed() const { return failed_; }
  const RunResult& result() const { return r_; }
  // The verdict: converged when `converged`, else what observe() found, or
  // at the step limit max_steps or stalled.
  RunResult finish(bool converged);

 private:
  void baseline();  // positions and extent the travel is measured from
  void check_mechanism();
  const Model& m_;
  const Solver& s_;
  RunLimits limits_;
  RunResult r_;
  std::uint64_t resets0_ = 0, revision_ = 0;
  double scale_ = 0;  // force scale at the last observe (relative runs) or the start
  double extent_ = 0;
  std::vector<Vec3> start_;
  bool failed_ = false, started_ = false;
  bool changed_ = false, rebaseline_ = false, resting_ = false;
};

}  // namespace tendril
