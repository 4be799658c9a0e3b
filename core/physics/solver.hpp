#pragma once
// Dynamic relaxation on the model's flat buffers (thesis 3.2): forces from
// elements and loads, lumped masses (fictitious, eq. 3.4, or physical), an
// explicit time integrator for translation (eq. 3.9-3.15) and viscous
// (eq. 3.26) or kinetic damping (eq. 3.28-3.31).
// Particles on 6-DOF beams also rotate (eq. 3.16-3.25, 3.27-3.28): torques,
// inertias (eq. 3.49-3.50 with eq. 3.4), angular velocities in global
// coordinates and frames updated by the rotation of eq. 3.16-3.17, in every
// integrator. That work runs over Particles::rotational only.
// Multi-resolution (thesis 5.5.2.3): a step visits Particles::integrated and
// the awake part of each ElementBuffer (awake_begin() to awake_end()) only,
// so passive particles and their elements cost nothing. A new integrator
// loops the same way: `for (ParticleId p : model.particles.integrated.raw())`.
// The step allocates nothing once the scratch buffers match the particle
// capacity, and reads the topology only through the buffers.
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "model/model.hpp"
#include "physics/bar_chunks.hpp"
#include "physics/beam6_chunks.hpp"
#include "physics/beam6_plan.hpp"
#include "physics/chunk_balance.hpp"
#include "physics/cst_chunks.hpp"
#include "physics/cst_plan.hpp"
#include "physics/element_shares.hpp"
#include "physics/hinge_chunks.hpp"
#include "physics/run_verdict.hpp"
#include "physics/workers.hpp"

namespace tendril {

enum class Damping { None, Viscous, Kinetic };
const char* damping_name(Damping d);

// Force evaluations per step: Leapfrog 1 (eq. 3.11-3.12), SymplecticEuler 1
// (v += dt a, then x += dt v, no half-step start), VelocityVerlet 2 (the
// start-of-step forces are recomputed because rules and scripts may change
// the model between steps), Midpoint 2, RK4 4 (eq. 3.13-3.15).
// Leapfrog's and Symplectic Euler's velocities lag the positions by half a
// step; the others' are at the step's end. Switching converts them.
// The constraint-based solvers (thesis 3.3.5, vie.cpp, projective.cpp,
// mixed.cpp) take vie_iterations local-global iterations per step:
// VariationalImplicitEuler averages the projections per particle (eq. 3.63),
// ProjectiveDynamics solves the prefactored global system instead, Mixed runs
// Leapfrog far from equilibrium and VIE (or projective dynamics, see
// mixed_implicit) near it (5.4.2.2).
// Newton is static: each step one Newton iteration on the residual with the
// exact tangent stiffness and a line search (newton.hpp, newton_step.cpp);
// no masses, velocities zero. Bars, cables and anchor, plane, line and
// length goals only: a model with any other element refuses it with an
// error naming the element kind.
// Auto, the default: Leapfrog for a step in time, the static Newton solver
// for a run to equilibrium where it is safe (Solver::RunScope says when).
enum class Integrator { Leapfrog, SymplecticEuler, VelocityVerlet, Midpoint, RK4, VariationalImplicitEuler,
                        ProjectiveDynamics, Mixed, Newton, Auto };
// The explicit integrators (eq. 3.9-3.25).
inline constexpr std::array<Integrator, 5> kIntegrators = {Integrator::Leapfrog, Integrator::SymplecticEuler,
                                                          Integrator::VelocityVerlet, Integrator::Midpoint,
                                                          Integrator::RK4};
inline constexpr std::array<Integrator, 3> kConstraintIntegrators = {
    Integrator::VariationalImplicitEuler, Integrator::ProjectiveDynamics, Integrator::Mixed};
inline constexpr std::array<Integrator, 1> kStaticIntegrators = {Integrator::Newton};
// "leapfrog", "symplectic_euler", "velocity_verlet", "midpoint", "rk4",
// "vie", "projective", "mixed", "newton", "auto".
const char* integrator_name(Integrator i);
std::optional<Integrator> parse_integrator(std::string_view name);
int force_evaluations_per_step(Integrator i);
// Eq. 3.4 bounds the stiffest mode at omega dt <= 2, Leapfrog's limit, also
// Velocity Verlet's; RK4 is stable (and damps) up to 2 sqrt(2): all 1.
// Symplectic Euler 2: its first kick from rest is a whole step, so twice the
// mass makes its first move Leapfrog's, F / S (with 1, repeated kinetic
// resets diverge). Midpoint 48: it amplifies every undamped oscillation
// (|R|^2 = 1 + (omega dt)^4 / 4); only small steps between kinetic resets
// keep it bounded.
double fictitious_mass_scale(Integrator i);

// Fictitious: M = mass_factor * fictitious_mass_scale(integrator) * dt^2/2 * S
// (eq. 3.4), tuned for stability, so dt only scales time. Physical: M = point
// mass + lumped element mass, for true dynamics; every integrated particle
// with a free axis needs one (mass_factor does not apply).
enum class MassMode { Fictitious, Physical };
const char* mass_mode_name(MassMode m);  // "fictitious", "physical"
std::optional<MassMode> parse_mass_mode(std::string_view name);

// vie_iterations = 0: VIE's count, and projective dynamics' adaptive rule.
inline constexpr int kVieIterations = 4;
inline constexpr int kAdaptiveIterations = 16;
inline constexpr double kAdaptiveTolerance = 1e-3;

struct SolverSettings {
  double dt = 1.0;                // time step; fictitious masses scale with dt^2 (eq. 3.4)
  Damping damping = Damping::Kinetic;
  // C of eq. 3.26. Viscous damping is the force -c M v with c = C / dt:
  // Leapfrog and Symplectic Euler use eq. 3.26 (its trapezoidal form),
  // Velocity Verlet the trapezoidal rule too, Midpoint and RK4 add it to the
  // acceleration of every stage.
  double viscous = 0.1;
  double geometric_factor = 1.0;  // g of eq. 3.35
  double mass_factor = 1.0;       // extra safety on eq. 3.4 (>= 1); fictitious masses only
  // Switchable between steps. Kinetic damping works with all: Leapfrog and
  // Symplectic Euler (the same kick-drift recurrence) move back to Barnes'
  // interpolated peak (eq. 3.29-3.31); the others stay at the step's start
  // (the discrete peak). Velocities are zeroed.
  Integrator integrator = Integrator::Auto;
  MassMode mass_mode = MassMode::Fictitious;
  // Constraint-based solvers: local-global iterations per step, and their
  // time step. vie_iterations = 0 (the default) lets the solver choose:
  // VIE takes kVieIterations; projective dynamics adapts (projective.cpp):
  // one iteration in form-finding (fictitious masses), where the momentum
  // carried to the next step does the inner iterations' work (to 1e-6 N on
  // the 128 x 128 net: 157 global solves with one, 336 with four), and in
  // dynamics (physical masses) as many as bring the last correction below
  // kAdaptiveTolerance of the step's displacement, at most
  // kAdaptiveIterations. A number fixes the count for both.
  // Fictitious masses always follow eq. 3.4 at dt, so a vie_dt above dt
  // weakens the momentum term M / vie_dt^2 of eq. 3.57. vie_dt = 0 means dt
  // with physical masses (true dynamics) and 100 dt with fictitious ones
  // (form-finding: the momentum term 1e-4 of its explicit weight, the
  // fastest measured, see bench_constraint_solvers).
  int vie_iterations = 0;
  double vie_dt = 0;
  // Mixed: the implicit phase (VariationalImplicitEuler, the thesis', or
  // ProjectiveDynamics) once the residual fell below mixed_switch times its
  // peak in the Leapfrog phase; Leapfrog again when it grows above twice
  // the residual the implicit phase started from (a load or topology change).
  double mixed_switch = 0.01;
  Integrator mixed_implicit = Integrator::VariationalImplicitEuler;
  // Threads of a step (1 to 64). The work is split into chunks fixed by the
  // model (bar_chunks.hpp) and summed in chunk order, so the results are the
  // same, bit for bit, for every thread count.
  int threads = 1;
};

// Thrown when a force or position stops being finite, at the step's start or
// at any stage of it. The step that found it moved no particle.
struct NumericalError : ModelError {
  using ModelError::ModelError;
};

class ProjectiveSystem;  // projective.hpp
class NewtonSystem;      // newton.hpp

class Solver {
 public:
  explicit Solver(Model& model);
  ~Solver();
  SolverSettings settings;
  // With settings.threads > 1, the fewest awake elements (bars, hinges,
  // 6-DOF beams and CST triangles together) of a model whose force pass
  // runs on the threads (the bar-only Leapfrog step always does): below it
  // handing the particles' forces from core to core costs more than the
  // threads save (on two threads, grids of 10K particles ran 0.6-0.9x as
  // fast, 40K elements of a beam grid 0.75x, grids of 100K particles 0.85-
  // 1.7x). The numbers are the same either way.
  std::uint32_t element_threads_from = 65536;

  void step();
  // The values of steps() at which a step failed (threw). A failed step may
  // have changed the model - velocities reset, forces of the positions it
  // started from - so the trace journals it (`failed_step`, io/trace.hpp)
  // and a replay takes it again, failing the same way.
  const std::vector<std::uint64_t>& failed_steps() const { return failed_; }
  // Whether the k-th failed step was one "auto" took as Newton's (the
  // journal says so: `failed_step as=newton`, replayed by step_auto_newton).
  bool failed_as_newton(std::size_t k) const { return failed_newton_[k]; }
  // Integrator Auto: the steps it took as Newton's, in runs to equilibrium,
  // as ranges [first, end) of steps(), in order (a journal writes them as
  // "newton_steps N"); and one such step, as a replay takes it again.
  struct StepRange {
    std::uint64_t first, end;
  };
  const std::vector<StepRange>& auto_newton_steps() const { return auto_newton_steps_; }
  void step_auto_newton();
  // Steps until both the residual and motion() are below `tolerance` [N], or
  // `max_steps` were taken. With the integrator Auto, the steps are Newton's
  // while newton_refusal() is null, the masses fictitious and the damping
  // kinetic (a form-finding run, not dynamics), until Newton converges,
  // stalls or took kAutoNewtonSteps; then Leapfrog's from where it left.
  // `progress` (if set) is called every `progress_every` steps.
  RunResult run(double tolerance, std::uint64_t max_steps,
                const std::function<void(const RunResult&)>& progress = {}, std::uint64_t progress_every = 1000);
  // The same with a relative tolerance too; ends early when the run
  // diverges or finds a mechanism (run_verdict.hpp says how it is judged).
  RunResult run(const RunLimits& limits, const std::function<void(const RunResult&)>& progress = {},
                std::uint64_t progress_every = 1000);

  // Residual forces, torques and direct stiffnesses at the current positions
  // and frames.
  void compute_forces();
  // Largest unconstrained force [N] or torque [N m] at the start of the last
  // step; Newton's at its end (its line search evaluated it).
  double residual() const { return residual_; }
  double torque_residual() const { return torque_residual_; }  // the torques alone
  double kinetic_energy() const { return kinetic_energy_; }  // eq. 3.28, rotation included
  // Largest M |v| / dt or I |w| / dt: the force (torque) that would stop the
  // fastest particle in one step.
  double motion() const { return motion_; }
  std::uint64_t steps() const { return steps_; }
  double time() const { return time_; }
  std::uint64_t kinetic_resets() const { return resets_; }
  std::uint64_t force_evaluations() const { return evaluations_; }  // a local step counts as one
  // Mixed: "leapfrog", "vie" or "projective", the phase of the last step;
  // Auto: "leapfrog" or "newton", the integrator of the last step; else the integrator's name.
  const char* phase() const;
  // Why the Newton solver cannot take this model ("hinges (3-DOF spline
  // beams)", "pressure or area loads", ...), or nullptr.
  const char* newton_refusal() const;
  static constexpr int kAutoNewtonSteps = 50;
  // A run to equilibrium, for as long as it lives: with the integrator
  // Auto, its steps are Newton's where auto_newton_applies() and `statics`
  // (a run with rules between its steps that count them or watch the
  // motion passes false), Leapfrog's once Newton stalled or took
  // kAutoNewtonSteps since the model last changed; a change (a rule, a
  // front end) decides again. run() holds one; a caller that drives step()
  // itself holds its own and calls stepped() after each step and whatever
  // it changed after it.
  class RunScope {
   public:
    explicit RunScope(Solver& s, bool statics = true);
    ~RunScope();
    RunScope(const RunScope&) = delete;
    RunScope& operator=(const RunScope&) = delete;
    void stepped();

   private:
    void choose();
    Solver& s_;
    bool statics_;
    std::uint64_t revision_;
    int newton_steps_ = 0;
  };
  // ProjectiveDynamics: how often its global matrix was factored.
  std::uint64_t factorizations() const;
  // ProjectiveDynamics: how many topology or parameter changes it followed
  // without a factorisation (projective.hpp: a low-rank correction).
  std::uint64_t projective_updates() const;
  // Newton: the work of its linear solves so far (newton.hpp).
  struct NewtonWork {
    std::uint64_t analyses = 0, factorizations = 0, iterations = 0;  // symbolic, numeric (3 axes: 1), CG
  };
  NewtonWork newton_work() const;
  // Off: every change is factored afresh (the same matrix; what the tests
  // compare the low-rank correction with).
  void set_projective_low_rank(bool on) { projective_low_rank_ = on; }
  // The force the supports exert on a locked particle (minus the residual
  // force along its locked axes) at the start of the last step.
  Vec3 reaction(ParticleId p) const;
  // The moment the supports exert on a rotation-locked particle.
  Vec3 reaction_moment(ParticleId p) const;
  // Forgets velocities and the kinetic-energy history (after a topology change
  // that invalidates them, or on request).
  void reset_motion();
  // The bytes a step of the fused kernel (Leapfrog or Symplectic Euler over
  // bars, hinges, 6-DOF beams and CST triangles alone) streams, counted as
  // STREAM counts them: every array a pass reads or writes counts once per
  // pass, write-allocate not counted, reuse within a chunk free. 0 when the
  // step does not take that kernel.
  // bench_throughput divides the triad bandwidth by it: the memory bound.
  double fused_step_bytes() const;

 private:
  // forces.cpp: forces F and stiffnesses S at positions x; torques T and
  // rotational stiffnesses K (rotating particles only) at frames q.
  void accumulate_forces(const Vec3* x, const Quat* q, Vec3* F, double* S, Vec3* T, double* K) const;
  // The lean bars (bar_chunks.hpp), derived again when the model changed.
  const BarChunks& bar_chunks() const;
  // A chunk's particles' sums (force, stiffness) in this thread's scratch,
  // indexed from the chunk's first id: their loads and weights and the
  // chunk's bars at x (body; fill_slots: its crossing bars' slots too),
  // then the slots of the crossing bars into it (chunk_force_sums, late).
  // A pass is a number from new_chunk_pass; the late part takes the sums the
  // body left on its thread in the same pass, or evaluates them again.
  static std::uint64_t new_chunk_pass();
  ForceSum* chunk_bar_sums(std::uint32_t c, const Vec3* x, std::uint64_t pass, bool fill_slots) const;
  ForceSum* chunk_force_sums(std::uint32_t c, const Vec3* x, std::uint64_t pass) const;
  // The chunk's spline-beam hinges (hinge_chunks.hpp, derived beforehand by
  // hinge_chunks()) at x added into its sums after chunk_force_sums: the
  // index among the awake hinges of the first it cannot evaluate (it adds
  // none from there), else kNone.
  const HingeChunks& hinge_chunks() const;
  std::uint32_t chunk_hinge_sums(std::uint32_t c, const Vec3* x, ForceSum* sums) const;
  // The same for the CST triangles and their projected corners
  // (cst_forces.cpp), after the hinges; prepare_cst_chunks derives what
  // the chunks share out beforehand.
  void prepare_cst_chunks() const;
  void chunk_cst_sums(std::uint32_t c, const Vec3* x, ForceSum* sums) const;
  // The same for the 6-DOF beams (after the hinges, before the triangles):
  // their forces into the chunk's sums, their torques into this thread's
  // torque sums (returned, indexed as the sums), which start at the
  // moments of the chunk's rotating particles; prepare_beam6_chunks derives
  // the chunks' shares of the elements and of the rotating particles.
  void prepare_beam6_chunks() const;
  ForceSum* chunk_beam6_sums(std::uint32_t c, const Vec3* x, const Quat* q, ForceSum* sums) const;
  const std::vector<ParticleId>& chunk_bounds() const;  // each chunk's first id, and the end
  // body(c) then late(c) for every chunk, the chunks split over the threads
  // in contiguous ranges sized by the threads' measured speeds
  // (ChunkBalance); a chunk whose inbox draws on an earlier thread's range
  // runs late(c) after its thread's range, once the bodies it draws on are
  // done.
  // `threaded` false: on the calling thread alone.
  void for_chunks(FunctionRef<void(std::uint32_t)> body, FunctionRef<void(std::uint32_t)> late,
                  bool threaded = true) const;
  // The same body(c) for every chunk, in parallel.
  void for_chunks(FunctionRef<void(std::uint32_t)> body) const;
  // The element loops on threads (ElementShares): how many, and the
  // particle ids each owns, those of its chunks (contiguous ranges of about
  // equal particle counts, fixed: the shares are derived again when they
  // move).
  unsigned element_threads() const;
  bool elements_on_threads() const;  // element_threads() > 1 and element_threads_from reached
  const std::vector<ParticleId>& element_bounds() const;
  // Leapfrog and Symplectic Euler over bars, spline-beam hinges, 6-DOF
  // beams and CST triangles alone: forces and the kick in one pass per
  // chunk, then the drift (integrators.cpp).
  bool fused_kick_drift_applies() const;
  void fused_kick_drift(bool whole_kick);
  void sum_rotary_inertia();        // the physical inertia of the rotating particles
  void turn_frames_back(double q);  // past a kinetic peak, by the fraction q of the step
  void accumulate_joint_forces(const Vec3* x, Vec3* F, double* S) const;  // joints.cpp
  void accumulate_goal_forces(const Vec3* x, Vec3* F, double* S) const;   // goal_forces.cpp
  void accumulate_cst_forces(const Vec3* x, Vec3* F, double* S) const;    // cst_forces.cpp
  // Pressure on patches (pressure_forces.cpp); S may be null (the
  // constraint solvers take it as an external force).
  void accumulate_pressure_forces(const Vec3* x, Vec3* F, double* S) const;
  bool pressure_acts() const;  // a patch under pressure (derives the quads when the model changed)
  // couples.cpp: external moments on particles without rotations (3-DOF
  // beams) as force couples across their beam segments, at positions x;
  // scale multiplies each force (dt^2 / m and the free axes: add_couples_to_x0).
  struct Couple {
    ParticleId p, q;  // the moment's particle and the segment's other end (a particle's couples are consecutive)
  };
  const std::vector<Couple>& couples() const;  // derived again when the model or a moment changed
  void accumulate_couples(const Vec3* x, Vec3* F) const;
  void add_couples_to_x0(double dt);  // implicit integrators: into x0_
  void size_scratch();
  // runaway.cpp: every kRunawayCheckEvery steps, one pass over the positions
  // stops (NumericalError naming the particle) a model whose extent grew a
  // millionfold since the last topology change, or that left kMaxCoordinate.
  static constexpr std::uint64_t kRunawayCheckEvery = 64;
  void check_runaway();
  struct RunawayReference {
    std::uint64_t revision = ~std::uint64_t(0);  // the model revision it was measured at
    std::uint64_t step = 0;
    double extent = 0;  // the largest side of the box around every particle [m]
    Vec3 centre = Vec3::Zero();
  } runaway_;
  void prepare_masses();  // mass_, inertia_ and residual_; throws before anything moves
  void stage_forces();    // forces at xs_ into Fs_, Ss_; throws if not finite
  double viscous_rate() const;  // c * dt = C when viscous, else 0
  // integrators.cpp
  void integrate_leapfrog();
  // Both; Leapfrog's first kick from v(t) is half a step. `prepare`: the
  // masses of prepare_masses found in the kick's pass (take_step skips it).
  void kick_drift(bool whole_kick, bool prepare);
  struct Kick {
    double first, keep, B;
  };
  Kick kick(bool whole_kick) const;
  double peak_fraction(double ke) const;
  void integrate_velocity_verlet();
  void integrate_midpoint();
  void integrate_rk4();
  void synchronize_velocities();  // Leapfrog's v(t - dt/2) -> v(t)
  // vie.cpp, projective.cpp, mixed.cpp
  double vie_dt() const {
    if (settings.vie_dt > 0) return settings.vie_dt;
    return settings.mass_mode == MassMode::Physical ? settings.dt : 100 * settings.dt;
  }
  void integrate_vie();
  // The projections of every element at (x, q): pulls into Fs_, weights into
  // Ss_, turns into Ts_ and rotational weights into Ks_.
  void local_step(const Vec3* x, const Quat* q);
  void rotation_global_step(double inv_dt2);  // eq. 3.63 for the frames, VIE and PD alike
  void integrate_projective();
  void integrate_mixed();
  void integrate_newton();  // newton_step.cpp
  bool newton_stalled_ = false;  // the last Newton step found no downhill step and moved nothing
  // Auto: what a step resolves to (Newton only inside a run that chose it),
  // and what the last step ran as.
  Integrator auto_choice_ = Integrator::Leapfrog, auto_last_ = Integrator::Leapfrog;
  std::vector<StepRange> auto_newton_steps_;
  bool auto_newton_applies() const;
  void start_implicit_step(double dt);  // x0 of eq. 3.57 into x0_, first guess into xs_, qs_
  void finish_implicit_step(double dt);  // velocities (eq. 3.64), kinetic damping, commit
  // Ends a step of a synchronous integrator whose new state is (xn, vn) and,
  // for rotating particles, (qn, wn).
  void commit(const Vec3* xn, const Vec3* vn, const Quat* qn, const Vec3* wn, double ke, double momentum2);
  // Kinetic damping: the kinetic energy `ke` of the new velocities is below
  // (or, for the synchronous methods, not above) the previous step's.
  bool kinetic_peak_passed(double ke) const;
  void record_energy(double ke, double momentum2);
  void record_reset();
  void count_step(double dt);  // this solver's step and time, and the model's (Model::steps, time)

  Model& model_;
  double residual_ = 0, torque_residual_ = 0, motion_ = 0;
  double kinetic_energy_ = 0;
  double ke_prev_ = 0, ke_prev2_ = 0;  // E and D of eq. 3.29
  int ke_samples_ = 0;
  bool half_step_ = false;  // velocities are Leapfrog's, half a step behind the positions
  std::uint64_t steps_ = 0, resets_ = 0, evaluations_ = 0;
  std::vector<std::uint64_t> failed_;
  std::vector<bool> failed_newton_;  // per failed step: taken as Newton's by "auto"
  void take_step();
  double time_ = 0;
  // Scratch, sized to the particle capacity (on growth only, never per step).
  std::vector<double> mass_;       // M of this step, per particle
  std::vector<Vec3> xs_, Fs_, vs_;  // stage positions, forces, velocities
  std::vector<double> Ss_;         // stage stiffnesses (unused but written)
  std::vector<Vec3> sum_x_, sum_v_;  // RK4's weighted sums of L and K (eq. 3.13-3.14)
  // Rotation, read and written for rotating particles only.
  std::vector<double> inertia_;     // I of this step (eq. 3.50 with eq. 3.4, or physical)
  std::vector<Quat> qs_;            // stage frames
  std::vector<Vec3> Ts_, ws_;       // stage torques, angular velocities
  std::vector<double> Ks_;          // stage rotational stiffnesses (unused but written)
  std::vector<Vec3> sum_r_, sum_w_;  // RK4's sums of L_R and K_R (eq. 3.22-3.24)
  // cst_forces.cpp: the triangles as the step reads them, and the element
  // pass's sums of the projected corners, one per slot (scratch, zero
  // between calls; the fused step sums a chunk's in a scratch of its own).
  mutable CstPlan cst_plan_;
  mutable CstChunks cst_chunks_;  // the same chunk by chunk, for the fused step
  mutable std::vector<CstCornerSums> cst_corner_sums_;
  // The oriented quads of every patch under pressure, with their pressure,
  // derived again when the model's revision moves.
  struct PressureQuad {
    Model::Quad q;
    double p;                          // [Pa] or, for an area load, [N/m^2]
    Vec3 along = Vec3::Zero();         // an area load's unit direction; zero: a pressure
  };
  mutable std::vector<PressureQuad> pressure_quads_;
  mutable std::uint64_t pressure_revision_ = ~std::uint64_t(0);
  std::vector<double> cst_weight_;   // local step: the CST stiffnesses
  std::vector<Vec3> x0_, r0_;        // implicit: x0 of eq. 3.57, and its rotation vector from the frame
  std::shared_ptr<ProjectiveSystem> projective_;  // projective.hpp, built on first use
  std::shared_ptr<NewtonSystem> newton_;          // newton.hpp, built on first use
  mutable BarChunks bar_chunks_;
  mutable HingeChunks hinge_chunks_;
  mutable Beam6Plan beam6_plan_;  // forces.cpp: the 6-DOF elements as the step reads them
  mutable Beam6Plan beam6_thread_plan_;  // the same in the order of beam6_shares_' items
  mutable Beam6Chunks beam6_chunks_;      // the same chunk by chunk, for the fused step
  mutable std::vector<Couple> couples_;
  mutable std::pair<std::uint64_t, std::uint64_t> couples_at_{~0ull, ~0ull};  // model revision, moment revision
  std::unique_ptr<Workers> workers_;
  // Per chunk: what a pass reduces, padded so threads do not share a line.
  struct alignas(64) ChunkSums {
    double ke = 0, momentum2 = 0, residual2 = 0;
    bool bad = false;  // a force, stiffness or mass the step cannot use
    std::uint32_t bad_hinge = kNone;  // the first hinge it cannot evaluate (chunk_hinge_sums)
    double torque2 = 0;               // the largest free torque squared
  };
  std::vector<ChunkSums> chunk_sums_;
  mutable ChunkBalance owner_split_;    // element_bounds: each thread's range, equal shares
  mutable ChunkBalance chunk_balance_;  // for_chunks: each thread's range, by measured speed
  mutable std::vector<double> thread_busy_;  // for_chunks: each thread's busy seconds in the last run
  mutable std::vector<std::atomic<std::uint64_t>> chunk_done_;  // for_chunks: the round of each chunk's last body
  mutable std::uint64_t chunk_round_ = 0;
  mutable std::vector<ParticleId> element_bound_;            // element_bounds
  mutable ElementShares hinge_shares_, beam6_shares_, cst_shares_;
  // The fused step's shares of the rotating particles by chunk (and their
  // ids, chunk by chunk).
  mutable ElementShares rotating_chunk_shares_;
  mutable std::vector<ParticleId> rotating_by_chunk_;
  mutable std::uint64_t rotating_caught_up_ = ~std::uint64_t(0);  // when rotating_chunk_shares_ read the list
  mutable std::vector<ParticleId> chunk_bound_;  // chunk_bounds
  mutable std::vector<std::uint32_t> thread_bad_hinge_;  // per thread: its first degenerate hinge
  bool projective_low_rank_ = true;
  bool mixed_implicit_ = false;      // Mixed: in its implicit phase
  double mixed_peak_ = 0, mixed_entry_ = 0;
};

}  // namespace tendril
