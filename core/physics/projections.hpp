#pragma once
// The local step of the constraint-based solvers (thesis 3.3.5, eq. 3.59):
// every element projects each of its particles to a position p_k where its
// constraint holds, with a weight K_k. The projections are consistent with
// forces.cpp: K_k (p_k - x) is the element's force on the particle (eq. 3.55
// for the energy of eq. 3.59), so every integrator shares one discrete
// equilibrium and the local-global iteration has exactly the explicit
// solvers' fixed points.
//
// Weights bound each element's stiffness by its row sums (Gershgorin), so the
// per-particle average of eq. 3.63 never overshoots, whatever the time step:
//   bars and cables  2 (EA/L + g T/l) on both ends (eq. 3.35): the length
//                    projection, halfway for each end; a slack cable projects
//                    onto itself (its constraint, l <= L, holds);
//   3-DOF hinges     4EI/La^3, 4EI/La^3 + 4EI/Lb^3, 4EI/Lb^3 (eq. 3.43): the
//                    ends and the middle move along the eq. 3.42 shear
//                    directions, towards the rest curvature, by the distance
//                    whose weight times it is the eq. 3.41 moment's shear;
//   6-DOF beams      twice the eq. 3.47 and 3.49 stiffnesses: translation and
//                    rotation, each end turned about the rotation vector
//                    torque / weight (the matrix form of the rotational
//                    average, linearised about the current frame);
//   rotational joints  each neighbour to its target (thesis 6.5.2) with twice
//                    the joint's stiffness, the shared particle with 8 times;
//   CST membranes    (Solver::local_step) each corner by its force over twice
//                    its eq. 3.40 stiffness;
//   goals            anchors, planes and lines project their particle exactly
//                    (weight: the goal's), a length goal is a bar.
// Sums are kept relative to x: pull = sum K_k (p_k - x), so eq. 3.63 reads
// x + pull / weight and carries no round-off from large coordinates.
#include "model/model.hpp"

namespace tendril {

struct ProjectionSums {
  Vec3* pull;         // per particle: sum K_k (p_k - x)
  double* weight;     // per particle: sum K_k
  Vec3* turn;         // rotating particles: sum K_k r_k, r_k the rotation vector to the projected frame
  double* rot_weight;  // rotating particles: sum K_k
};

// Zeroes the sums of every particle (turn, rot_weight: rotating ones only)
// and adds every element's projections at positions x and frames q.
void accumulate_projections(const Model& m, const Vec3* x, const Quat* q, double geometric_factor,
                            const ProjectionSums& out);

}  // namespace tendril
