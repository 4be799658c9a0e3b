// Discrete-shell bending hinges (shell_bending.hpp).
#include "physics/shell_bending.hpp"

#include <cmath>

namespace tendril {

namespace {

// cot of the angle between u and v; inf for parallel vectors.
double cotangent(const Vec3& u, const Vec3& v) {
  const double s = u.cross(v).norm();
  return s > 0 ? u.dot(v) / s : INFINITY;
}

}  // namespace

bool bend_hinge(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, BendHinge& out) {
  const Vec3 e = b - a;
  // The angles at a and at b in each triangle.
  const double ca_c = cotangent(e, c - a), ca_d = cotangent(e, d - a);
  const double cb_c = cotangent(-e, c - b), cb_d = cotangent(-e, d - b);
  out.K = {cb_c + cb_d, ca_c + ca_d, -ca_c - cb_c, -ca_d - cb_d};
  out.area = 0.5 * (e.cross(c - a).norm() + e.cross(d - a).norm());
  for (double k : out.K)
    if (!std::isfinite(k)) return false;
  return out.area > 0 && std::isfinite(out.area);
}

BendPulls bend_pulls(const Goal& g, const Vec3* x) {
  BendPulls out{{g.i, g.j, g.k, g.l}, {}, {}};
  Vec3 v = Vec3::Zero();  // the hinge's mean-curvature vector
  double sum = 0;
  for (int a = 0; a < 4; ++a) {
    v += g.hinge[a] * x[out.p[a]];
    sum += std::abs(g.hinge[a]);
  }
  const double w = g.weight / g.hinge_area;
  for (int a = 0; a < 4; ++a) {
    out.f[a] = -w * g.hinge[a] * v;
    out.k[a] = w * std::abs(g.hinge[a]) * sum;
  }
  return out;
}

}  // namespace tendril
