// Lee's frame (benchmark_models.hpp): two members of L = 120 in at a right
// angle, pinned at both supports, a load at 24 in from the corner on the
// horizontal member; its limit load PL^2/EI = 18.56 (Lee, Manuel & Rossow
// 1968), found under displacement control (find_limit). 3 DOF: the corner
// a rigid joint (Model::set_joint); 6 DOF: the corner's shared frame.
#include "limit_case.hpp"

namespace tendril::validate {

Case lee_frame_case() {
  Case c;
  c.name = "lee_frame";
  c.reference = "Lee's frame (Lee, Manuel & Rossow 1968): limit load PL^2/EI = 18.56 under displacement control";
  c.resolution = "segments per member";
  c.formulations = {"beam-3dof", "beam-6dof"};
  c.segments = {10, 20, 40};
  c.quick_segments = {10, 20};
  c.defaults.formulation = "beam-3dof";
  c.defaults.segments = 20;
  c.tolerance = 0.01;
  std::erase(c.integrators, Integrator::Midpoint);  // 10x the steps of the others
  c.run = run_limit_case<LeeFrame>;
  return c;
}

}  // namespace tendril::validate
