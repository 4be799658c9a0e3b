// Sherman-Morrison-Woodbury on the old factor (low_rank_solve.hpp).
#include "physics/low_rank_solve.hpp"

#include <cmath>

namespace tendril {

void LowRankSolve::clear() {
  rows_.clear();
  Z_.resize(0, 0);
  C_.resize(0, 0);
}

bool LowRankSolve::set(const Solve& B, Eigen::Index n, const std::vector<int>& rows, const Eigen::MatrixXd& delta) {
  const Eigen::Index k = Eigen::Index(rows.size()), had = Eigen::Index(rows_.size());
  // Columns of Z for the rows seen before stay (B did not change on its old
  // rows); on rows B gained since they are zero.
  Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(n, k);
  Z.topLeftCorner(Z_.rows(), had) = Z_.leftCols(had);
  Eigen::MatrixXd e = Eigen::MatrixXd::Zero(n, k - had);  // the new rows' unit columns, solved at once
  for (Eigen::Index c = had; c < k; ++c) e(rows[std::size_t(c)], c - had) = 1;
  B(e);
  Z.rightCols(k - had) = e;
  Z_ = std::move(Z);
  rows_ = rows;
  C_ = delta;
  Eigen::MatrixXd S(k, k);
  for (Eigen::Index r = 0; r < k; ++r) S.row(r) = Z_.row(rows_[std::size_t(r)]);
  K_.compute(Eigen::MatrixXd::Identity(k, k) + S * C_);
  // A positive determinant is necessary for B + D to stay positive definite;
  // a small rcond means the correction would lose the digits a fresh
  // factorisation keeps.
  const double det = K_.determinant();
  return std::isfinite(det) && det > 0 && K_.rcond() > 1e-10;
}

void LowRankSolve::solve(const Solve& B, Eigen::MatrixXd& b) const {
  B(b);
  if (rows_.empty()) return;
  yT_.resize(Eigen::Index(rows_.size()));
  for (Eigen::Index c = 0; c < b.cols(); ++c) {
    for (std::size_t r = 0; r < rows_.size(); ++r) yT_[Eigen::Index(r)] = b(rows_[r], c);
    const Eigen::VectorXd w = C_ * K_.solve(yT_);
    b.col(c).noalias() -= Z_ * w;
  }
}

}  // namespace tendril
