// Williams' toggle (benchmark_models.hpp): two shallow members (half span
// 12.943 in, rise 0.386 in) clamped at their supports and rigidly joined at
// the apex, loaded there; its limit load 33.86 lb (Williams 1964), found
// under displacement control (find_limit). 3 DOF: the apex a rigid joint
// (Model::set_joint), the supports clamp hinges (Model::set_clamp); 6 DOF:
// the apex's shared frame, the supports fully locked.
#include "limit_case.hpp"

namespace tendril::validate {

Case williams_toggle_case() {
  Case c;
  c.name = "williams_toggle";
  c.reference = "Williams' toggle (Williams 1964): limit load 33.86 lb under displacement control";
  c.resolution = "segments per member";
  c.formulations = {"beam-3dof", "beam-6dof"};
  c.segments = {10, 20, 40};
  c.quick_segments = {10, 20};
  c.defaults.formulation = "beam-3dof";
  c.defaults.segments = 20;
  c.tolerance = 0.01;
  std::erase(c.integrators, Integrator::Midpoint);  // 10x the steps of the others
  c.run = run_limit_case<WilliamsToggle>;
  return c;
}

}  // namespace tendril::validate
