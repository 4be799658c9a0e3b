#include "physics/rigid_body.hpp"

#include <Eigen/SVD>

namespace tendril {

void rigid_pulls(const Goal& g, const Vec3* x, std::vector<Vec3>& pull) {
  const std::size_t n = g.members.size();
  Vec3 c = Vec3::Zero();
  for (ParticleId p : g.members) c += x[p];
  c /= double(n);
  Mat3 H = Mat3::Zero();
  for (std::size_t k = 0; k < n; ++k) H += (x[g.members[k]] - c) * g.rest[k].transpose();
  const Eigen::JacobiSVD<Mat3> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 D = Mat3::Identity();
  // A reflection fits a mirrored body better than any rotation when the
  // body is flat or turned inside out: the smallest singular direction flips.
  if ((svd.matrixU() * svd.matrixV().transpose()).determinant() < 0) D(2, 2) = -1;
  const Mat3 R = svd.matrixU() * D * svd.matrixV().transpose();
  pull.resize(n);
  for (std::size_t k = 0; k < n; ++k) pull[k] = g.weight * (c + R * g.rest[k] - x[g.members[k]]);
}

}  // namespace tendril
