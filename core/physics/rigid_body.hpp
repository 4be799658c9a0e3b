#pragma once
// The rigid-body goal (Goal::Rigid, thesis 6.1: a module taken into the
// particle model as one body): shape matching. The current positions x_i
// of the members are fitted by the rest shape r_i (offsets from the rest
// centroid) moved as a rigid body: the centroid c of the x_i and the
// rotation R that best maps the r_i onto the x_i - c (least squares, the
// polar factor of sum (x_i - c) r_i^T by SVD, a reflection excluded). Each
// member is pulled towards its target c + R r_i with the goal's weight
// [N/m]. The pulls sum to zero and so do their moments about c: the goal
// holds the shape and leaves the body's six rigid motions free.
#include <vector>

#include "model/elements.hpp"

namespace tendril {

// Whether every member takes part in the step (a passive one freezes the body's goal).
inline bool members_active(const Goal& g, const std::uint8_t* active) {
  for (ParticleId p : g.members)
    if (!active[p]) return false;
  return true;
}

// w (c + R r_i - x_i) for every member, in member order, into `pull`
// (reused: the step allocates nothing once it has grown).
void rigid_pulls(const Goal& g, const Vec3* x, std::vector<Vec3>& pull);

}  // namespace tendril
