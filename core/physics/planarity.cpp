// Planarity goals (planarity.hpp).
#include "physics/planarity.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace tendril {

namespace {

// The best-fit plane of four points: centroid and unit normal.
void best_fit(const Vec3 (&c)[4], Vec3& centre, Vec3& normal) {
  centre = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  Mat3 scatter = Mat3::Zero();
  for (const Vec3& p : c) scatter += (p - centre) * (p - centre).transpose();
  Eigen::SelfAdjointEigenSolver<Mat3> eig(scatter);  // eigenvalues ascending
  normal = eig.eigenvectors().col(0);
}

}  // namespace

PlanarityPulls planarity_pulls(const Goal& g, const Vec3* x) {
  PlanarityPulls out{{g.i, g.j, g.k, g.l}, {}};
  const Vec3 c[4] = {x[g.i], x[g.j], x[g.k], x[g.l]};
  Vec3 centre, n;
  best_fit(c, centre, n);
  for (int a = 0; a < 4; ++a) out.f[a] = -g.weight * (c[a] - centre).dot(n) * n;
  return out;
}

double planarity_gap(const Vec3 (&c)[4]) {
  Vec3 centre, n;
  best_fit(c, centre, n);
  double gap = 0;
  for (const Vec3& p : c) gap = std::max(gap, std::abs((p - centre).dot(n)));
  return gap;
}

}  // namespace tendril
