#pragma once
// Eq. 3.41: a spline-beam hinge's curvature 2 sin(alpha) / Lc, with
// sin(alpha) = |a x b| / (La Lb), from the reciprocals of its links'
// lengths (the step needs them for the stiffnesses and shears too, and
// multiplying by them spares the divider). Every place that measures a
// hinge's curvature calls this: its force (physics/element_forces.hpp and
// the step's blocks, physics/forces.cpp), the shapes a beam is built in
// (model/rest_shape.cpp, model/extend.cpp) and the reports (query/), so a
// beam at rest in the shape it was built in has exactly no moment.
namespace tendril {

inline double hinge_curvature(double cross_norm, double inv_La, double inv_Lb, double Lc) {
  return 2 * (cross_norm * (inv_La * inv_Lb)) / Lc;
}

}  // namespace tendril
