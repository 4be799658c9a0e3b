#pragma once
// CalculiX input deck of the model's current state (issue 11: the comparison
// with an independent nonlinear FE solver), and the nodal displacements ccx
// writes back. What maps to what, and what cannot, is in docs/calculix.md.
//
// Node n is particle n - 1 (ids are stable while the model does not change);
// a particle where 3-DOF beams meet pinned gets one more node per further
// beam, numbered after every particle node and tied to it by *EQUATION.
// The deck is one static step with NLGEOM from the current geometry, every
// element carrying the force it carries now as its initial stress.
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tendril {

// Thickness [m] of the exported membrane elements: tendril's membrane
// stresses and stiffnesses are per unit width, so any t gives the same
// membrane (stresses s / t, moduli d / t).
inline constexpr double kCcxMembraneThickness = 1e-3;

// Throws ModelError naming the patch for what ccx cannot take: a CST patch in
// form-finding mode (a stress that no strain changes has no material).
std::string ccx_string(const Model& m);
// Written whole or not at all (io/atomic_file.hpp).
void save_ccx(const Model& m, const std::string& path);

struct CcxDisplacement {
  int node = 0;
  double u[3] = {0, 0, 0};
};
// The last block of nodal displacements "displacements (vx,vy,vz) ..." in a
// ccx .dat file (what *NODE PRINT, NSET=NALL U writes at the step's end).
// Throws InputError naming the file and line when there is none or a line
// does not read.
std::vector<CcxDisplacement> read_ccx_displacements(const std::string& dat_path);
std::vector<CcxDisplacement> parse_ccx_displacements(const std::string& text, const std::string& name);

}  // namespace tendril
