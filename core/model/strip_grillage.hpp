#pragma once
// A bending strip (thesis 6.1) as a grillage: a plate of thickness t and
// modulus E on a structured grid of rows (along the strip) and columns
// (across it), modelled by the members tendril already solves with every
// integrator (the grillage analogy of bridge-deck analysis, Hambly 1991):
//
// - a 3-DOF beam along every row and every column, with the plate's
//   bending stiffness D = E t^3 / 12 (1 - nu^2) and membrane stiffness E t
//   over its tributary width (EI = D w, EA = E t w): cylindrical bending of
//   the strip is then exactly the wide beam's bending, the rows bending as
//   one;
// - the plate's twisting stiffness as a planarity goal on every quad: the
//   twist energy D (1 - nu) kxy^2 a b of a quad a x b with twist kxy warps
//   its corners +-kxy a b / 4 off their best-fit plane, which the goal's
//   energy w/2 sum h^2 matches with w = 8 D (1 - nu) / (a b); bending
//   without twist leaves a quad planar, so the goal does not stiffen it;
// - the in-plane shear stiffness G t as two crossed diagonal bars per
//   quad, EA = G t d^3 / (2 a b) each (their energy under a shear strain g
//   is G t g^2 a b / 2).
//
// The Poisson coupling of the two curvatures (nu kx ky) is left out: exact
// for cylindrical bending (the wide-beam cases) and for nu = 0, an
// approximation of the anticlastic response otherwise.
#include <vector>

#include "model/types.hpp"

namespace tendril {

struct StripMaterial {
  double E = 0;        // [Pa]
  double t = 0;        // thickness [m]
  double nu = 0;       // Poisson's ratio
  double density = 0;  // [kg/m^3]

  double D() const { return E * t * t * t / (12 * (1 - nu * nu)); }  // [N m]
  double G() const { return E / (2 * (1 + nu)); }
};

struct StripMember {  // a row or a column beam
  double EA = 0, EI = 0, line_mass = 0;
};

struct StripQuad {
  int row = 0, column = 0;  // its corner of least indices
  double diagonal_EA[2] = {0, 0};  // (r, c)-(r+1, c+1) and (r, c+1)-(r+1, c)
  double twist_weight = 0;         // [N/m]
};

struct StripGrillage {
  std::vector<StripMember> rows, columns;
  std::vector<StripQuad> quads;  // row by row
};

// grid[r][c]: rows >= 2 of columns >= 2 points each. Tributary widths and
// lengths are read off the grid as given (a member's mean over its
// particles); the rows carry the strip's weight.
StripGrillage strip_grillage(const std::vector<std::vector<Vec3>>& grid, const StripMaterial& m);

// What makes a strip's members (the Lua binding: journaled commands; the
// validation cases: the model directly).
struct StripMaker {
  virtual ~StripMaker() = default;
  virtual BlockId beam(const StripMember& section, const std::vector<ParticleId>& particles) = 0;
  virtual BlockId bar(ParticleId a, ParticleId b, double EA) = 0;
  virtual std::size_t planarity(double weight, const std::vector<ParticleId>& corners) = 0;
};

struct StripMembers {
  std::vector<BlockId> rows, columns, bars;
  std::vector<std::size_t> twist;  // the planarity goals
};

// The members of the grillage g on the particle grid ids[r][c] (the grid g
// was derived from), in a fixed order: the row beams, the column beams,
// then quad by quad its two diagonal bars and its twist goal.
StripMembers make_strip(const std::vector<std::vector<ParticleId>>& ids, const StripGrillage& g, StripMaker& make);

}  // namespace tendril
