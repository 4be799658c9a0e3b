#pragma once
// The formulation of a tensile patch (thesis 3.2.8.2, 5.5.2.2): elastic bars
// on its edges, or constant strain triangles (CST) for stress-controlled
// form-finding (eq. 3.36) or orthotropic analysis (eq. 3.37-3.39).
#include <array>
#include <cstdint>
#include <string>

namespace tendril {

// Membrane stresses and stiffnesses are per unit width [N/m]: sigma = t * s
// for a fabric of thickness t and stress s, d = t * E' for its stiffnesses.
struct Membrane {
  enum Mode : std::uint8_t { Bars = 0, FormFinding = 1, Analysis = 2 };
  Mode mode = Bars;
  // Form-finding: the prescribed warp and weft stresses. Analysis: the
  // prestress the reference geometry carries (often the form-found stresses).
  double sigma_warp = 0, sigma_weft = 0;
  // Analysis (eq. 3.38): sigma_x = dxx eps_x + dxy eps_y,
  // sigma_y = dyx eps_x + dyy eps_y, tau = G gamma. Zero in form-finding.
  double dxx = 0, dxy = 0, dyx = 0, dyy = 0, G = 0;
  bool cst() const { return mode != Bars; }
  bool operator==(const Membrane&) const = default;
};
const char* membrane_mode_name(Membrane::Mode m);  // "bars", "form", "analysis"

// The reference geometry of a CST in analysis (eq. 3.37), taken when the
// patch switches: side 1 (i -> j) of length l1 along x, k at (c, h).
struct CstReference {
  double l1 = 0, h = 0, c = 0;
  bool operator==(const CstReference&) const = default;
};

}  // namespace tendril
