#pragma once
// Cross-sections of members from their dimensions [m]: area, second moments
// about the section's axes (b along y, h along z for a rectangle: Iy =
// b h^3 / 12 bends about y, across the depth h), the torsion constant and
// the elastic section moduli W = I / (distance to the extreme fibre), from
// which a member's stress is N / A + My / Wy + Mz / Wz (exact at a corner
// of a rectangle, conservative for a round section under both moments).
namespace tendril {

struct CrossSection {
  double A = 0, Iy = 0, Iz = 0, J = 0, Wy = 0, Wz = 0;
};

// Each throws ModelError naming the dimension at fault (not finite, <= 0,
// or a tube wall thicker than half its diameter).
CrossSection rod_section(double d);
CrossSection tube_section(double d, double t);
CrossSection rect_section(double b, double h);

}  // namespace tendril
