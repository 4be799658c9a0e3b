#include "model/cross_section.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "model/types.hpp"

namespace tendril {

namespace {

constexpr double kPi = std::numbers::pi;

void require_positive(const char* shape, const char* name, double v) {
  if (!(std::isfinite(v) && v > 0))
    throw ModelError(std::string("section.") + shape + ": '" + name + "' must be a finite length > 0 [m]");
}

}  // namespace

CrossSection rod_section(double d) {
  require_positive("rod", "d", d);
  CrossSection s;
  s.A = kPi * d * d / 4;
  s.Iy = s.Iz = kPi * std::pow(d, 4) / 64;
  s.J = 2 * s.Iy;  // polar moment: exact for a circle
  s.Wy = s.Wz = s.Iy / (d / 2);
  return s;
}

CrossSection tube_section(double d, double t) {
  require_positive("tube", "d", d);
  require_positive("tube", "t", t);
  if (t > d / 2) throw ModelError("section.tube: 't' must be at most half of 'd' (a wall, not more than a rod)");
  const double di = d - 2 * t;
  CrossSection s;
  s.A = kPi * (d * d - di * di) / 4;
  s.Iy = s.Iz = kPi * (std::pow(d, 4) - std::pow(di, 4)) / 64;
  s.J = 2 * s.Iy;  // exact for a circular tube
  s.Wy = s.Wz = s.Iy / (d / 2);
  return s;
}

CrossSection rect_section(double b, double h) {
  require_positive("rect", "b", b);
  require_positive("rect", "h", h);
  CrossSection s;
  s.A = b * h;
  s.Iy = b * h * h * h / 12;
  s.Iz = h * b * b * b / 12;
  // Saint-Venant torsion of a rectangle, long side a, short side c, by
  // Roark's approximation (Roark's Formulas for Stress and Strain, torsion
  // of a solid rectangle; 0.1408 a^4 for a square against 0.1406 exact):
  // J = a c^3 (1/3 - 0.21 (c/a) (1 - (c/a)^4 / 12)).
  const double a = std::max(b, h), c = std::min(b, h), r = c / a;
  s.J = a * c * c * c * (1.0 / 3 - 0.21 * r * (1 - std::pow(r, 4) / 12));
  s.Wy = s.Iy / (h / 2);
  s.Wz = s.Iz / (b / 2);
  return s;
}

}  // namespace tendril
