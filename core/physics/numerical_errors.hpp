#pragma once
// What the solver says when a number stops being finite: the particle, the
// elements on it and why, so a user can find the spot in the scene. These
// run on the failure path only; the step's loops pay one branch at most.
#include <cstdint>
#include <string>

#include "physics/solver.hpp"

namespace tendril {

// "particle 5 (on beam 0, cable 3)".
std::string describe_particle(const Model& m, ParticleId p);

// A spline-beam hinge (eq. 3.41-3.43) needs both links longer than zero:
// its bending stiffness 4 EI / L^3 (eq. 3.43) is infinite on a zero-length
// (or, overflowing, a 1e-100 m) link and its plane undefined. Names the hinge, its beam and the particles
// that coincide (or the one whose position is not finite).
[[noreturn]] void throw_degenerate_hinge(const Model& m, const Hinge& h, const Vec3* x,
                                         const char* done = "no particle was moved");

// The state an integrator was about to write (positions x, velocities v,
// angular velocities w; null when not computed) is not finite at some
// particle: the time step is beyond the integrator's stability limit (or
// a mass is zero). Names the first such particle; `done` says what the
// solver did about it. Returned, so the caller can tidy up before throwing.
NumericalError non_finite_motion(const Model& m, const Vec3* x, const Vec3* v, const Vec3* w,
                                          const SolverSettings& s, std::uint64_t step, const char* done);

}  // namespace tendril
