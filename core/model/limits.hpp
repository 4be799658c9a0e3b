#pragma once
// How far from the origin a particle may be: checked where particles are made
// (add_particle: scenes, model files, journals) and while the solver runs
// (physics/runaway.cpp). A front end that moves a particle checks it too.
#include "model/types.hpp"

namespace tendril {

// [m]: 1e6 times the largest structure, and far enough from overflow that
// every length, area and stiffness derived from coordinates stays finite (at
// 1e154 a squared length overflows, and a rest length became infinite).
inline constexpr double kMaxCoordinate = 1e12;

// [m]: the longest rest length of a bar, cable or beam segment - beyond any
// two particles' distance (2 sqrt(3) kMaxCoordinate) - and [kg/m] the largest
// line mass: their product, a particle's lumped mass, stays finite (a line
// mass of 1e12 on a rest length of 1.8e308 made it infinite, and the model
// invalid). Checked by the commands (Lua, journals, JSON) and the model
// database reader alike.
inline constexpr double kMaxRestLength = 1e13;
inline constexpr double kMaxLineMass = 1e12;

// Throws ModelError("what: position (x, y, z) is beyond 1e+12 m from the
// origin") when a coordinate of x is beyond kMaxCoordinate or not finite.
void check_coordinates(const Vec3& x, const char* what);

}  // namespace tendril
