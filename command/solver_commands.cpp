// The solver's settings and gravity, solver steps, and a model database to
// start from.
#include "command/declare.hpp"
#include "io/model_xml.hpp"
#include "physics/settings_check.hpp"
#include "physics/solver.hpp"

namespace tendril::command {

namespace {

enum SettingParam { kDt, kDamping, kViscous, kGeometricFactor, kMassFactor, kIntegrator, kMassMode, kVieIterations,
                    kVieDt, kMixedSwitch, kMixedImplicit };

// In the order of SettingParam.
const char* const kSettingNames[] = {"dt",           "damping",  "viscous",        "geometric_factor",
                                     "mass_factor",  "integrator", "mass_mode",    "vie_iterations",
                                     "vie_dt",       "mixed_switch", "mixed_implicit"};

// The given keys replace the solver's values, all checked before any is set.
Result apply_settings(Target& t, Args& a) {
  SolverSettings s = t.solver.settings;
  auto given = [&](SettingParam k) { return a[k].given; };
  if (given(kDt)) s.dt = a[kDt].number;
  if (given(kDamping)) {
    const std::string& d = a[kDamping].word;
    s.damping = d == "kinetic" ? Damping::Kinetic : d == "viscous" ? Damping::Viscous : Damping::None;
  }
  if (given(kViscous)) s.viscous = a[kViscous].number;
  if (given(kGeometricFactor)) s.geometric_factor = a[kGeometricFactor].number;
  if (given(kMassFactor)) s.mass_factor = a[kMassFactor].number;
  if (given(kIntegrator)) s.integrator = *parse_integrator(a[kIntegrator].word);
  if (given(kMassMode)) s.mass_mode = *parse_mass_mode(a[kMassMode].word);
  if (given(kVieIterations)) s.vie_iterations = int(a[kVieIterations].id);
  if (given(kVieDt)) s.vie_dt = a[kVieDt].number;
  if (given(kMixedSwitch)) s.mixed_switch = a[kMixedSwitch].number;
  if (given(kMixedImplicit)) s.mixed_implicit = *parse_integrator(a[kMixedImplicit].word);
  if (auto bad = check_settings(s)) {
    std::size_t k = 0;
    while (k < a.size() && bad->key != kSettingNames[k]) ++k;
    throw ArgumentError(k, bad->message);
  }
  t.solver.settings = s;
  return nothing();
}

}  // namespace

void declare_solver(std::vector<Command>& out) {
  const std::vector<const char*> integrators = {"auto", "leapfrog",   "symplectic_euler", "velocity_verlet", "midpoint",
                                                "rk4",  "vie",        "projective",       "mixed",           "newton"};
  Command settings{"settings", "the solver's settings (only the keys given change; all are checked first)",
                   Effect::Setting,
                   {{"dt", Type::Number, "time step (> 0)", {}, {}, true},
                    {"damping", Type::Word, "", {}, {"kinetic", "viscous", "none"}, true},
                    {"viscous", Type::Number, "C of eq. 3.26, in [0, 2)", {}, {}, true},
                    {"geometric_factor", Type::Number, "g of eq. 3.35 (>= 0)", {}, {}, true},
                    {"mass_factor", Type::Number, "safety on the fictitious masses (>= 1)", {}, {}, true},
                    {"integrator", Type::Word, "", {}, integrators, true},
                    {"mass_mode", Type::Word, "", {}, {"fictitious", "physical"}, true},
                    {"vie_iterations", Type::Count, "local-global iterations per step (0: the solver chooses)", {0, kMaxVieIterations}, {}, true},
                    {"vie_dt", Type::Number, "the constraint solvers' time step (>= 0; 0: dt)", {}, {}, true},
                    {"mixed_switch", Type::Number, "mixed: the residual ratio to switch at, in (0, 1)", {}, {}, true},
                    {"mixed_implicit", Type::Word, "mixed: the implicit phase", {}, {"vie", "projective"}, true}},
                   Returns::Nothing, apply_settings};
  settings.keyed = true;
  out.push_back(std::move(settings));
  out.push_back({"gravity", "the acceleration of gravity on physical masses [m/s^2]", Effect::Setting,
                 {{"g", Type::Vector, "[m/s^2]"}}, Returns::Nothing,
                 [](Target& t, Args& a) {
                   t.model.gravity = a[0].vector;
                   return nothing();
                 },
                 0, Returns::Vector, [](Target& t, const Args&) { return vector_result(t.model.gravity); }});
  Command steps{"steps", "solver steps (the journal writes the steps taken before each line)", Effect::Steps,
                {{"n", Type::Count, "steps", {0, 9007199254740992.0}}}, Returns::Nothing, [](Target& t, Args& a) {
                  for (std::uint64_t k = 0; k < a[0].id; ++k) t.solver.step();
                  return nothing();
                }};
  steps.lua = "";  // m:step and m:run drive the solver from Lua
  out.push_back(std::move(steps));
  // The steps of "auto" are Leapfrog's, except in a run to equilibrium that
  // took Newton's: the journal says which, so that a replay takes the same.
  Command newton_steps{"newton_steps", "solver steps the integrator \"auto\" took as Newton's, in a run to equilibrium",
                       Effect::Steps, {{"n", Type::Count, "steps", {0, 9007199254740992.0}}}, Returns::Nothing,
                       [](Target& t, Args& a) {
                         for (std::uint64_t k = 0; k < a[0].id; ++k) t.solver.step_auto_newton();
                         return nothing();
                       }};
  newton_steps.lua = "";
  out.push_back(std::move(newton_steps));
  // A step that threw may still have changed the model (velocities reset,
  // forces of the positions it started from): the journal says where one
  // failed, and a replay takes that step again, which fails the same way.
  Command failed_step{"failed_step", "a solver step that failed (threw) when the journal was written; it must fail again",
                      Effect::Steps,
                      {{"as", Type::Word, "newton: a step \"auto\" took as Newton's", {}, {"newton"}, true}},
                      Returns::Nothing, [](Target& t, Args& a) {
                        try {
                          if (a[0].given) t.solver.step_auto_newton();
                          else t.solver.step();
                        } catch (const std::exception&) {
                          return nothing();
                        }
                        throw ModelError("failed_step: the step succeeded here (this is not the model the journal failed a step of)");
                      }};
  failed_step.keyed = true;  // `failed_step` or `failed_step as=newton`
  failed_step.lua = "";
  out.push_back(std::move(failed_step));
  Command open{"open", "a model database (XML) to start from", Effect::Topology,
               {{"path", Type::Path, "the file"}}, Returns::Nothing, [](Target& t, Args& a) {
                 load_model_xml(a[0].word, t.model, t.solver.settings);
                 // Reactions (and residual forces) read right after the load, not
                 // 0 until a step ran. Degenerate geometry is the first step's to report.
                 try {
                   t.solver.compute_forces();
                 } catch (const std::exception&) {
                 }
                 return nothing();
               }};
  open.lua = "";  // tendril.load
  out.push_back(std::move(open));
}

}  // namespace tendril::command
