#pragma once
// Solves (A + D) x = b with the sparse LDL^T factor of A alone, when D is
// nonzero only on a few rows and columns T (a bar added or removed, a rest
// length or weight changed, a particle's mass): D = U C U^T, U the columns
// of the identity at T, C = D[T, T] (dense, k x k, any sign), and
//   (A + U C U^T)^-1 b = y - Z C (I + S C)^-1 y_T,   y = A^-1 b,
//   Z = A^-1 U (k solves, once per new row), S = U^T Z = Z[T, :]
// (Sherman-Morrison-Woodbury without C^-1, so a singular C - one bar's
// w (e_i - e_j)(e_i - e_j)^T - is fine). Exact up to rounding: the same
// solution as a fresh factorisation of A + D, at the price of one solve per
// new row once and 2 n k flops per solve after (projective.hpp decides when
// a refactorisation pays off instead).
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

namespace tendril {

class LowRankSolve {
 public:
  using Factor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
  // Forgets every change: solves with A's factor alone.
  void clear();
  // The change D is now `delta` (dense over rows(), in their order) on the
  // rows `rows`, which extend rows() (rows already there keep their place).
  // False when I + S C is singular or its determinant, det(A + D) / det(A),
  // not positive: A + D is not positive definite (or nearly not), so the
  // caller refactors, which says why.
  bool set(const Factor& A, const std::vector<int>& rows, const Eigen::MatrixXd& delta);
  // b -> (A + D)^-1 b, in place.
  void solve(const Factor& A, Eigen::VectorXd& b) const;
  const std::vector<int>& rows() const { return rows_; }

 private:
  std::vector<int> rows_;
  Eigen::MatrixXd Z_, C_;
  Eigen::PartialPivLU<Eigen::MatrixXd> K_;  // I + S C
  mutable Eigen::VectorXd yT_;
};

}  // namespace tendril
