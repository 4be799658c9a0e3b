#pragma once
// Solves (B + D) x = b with a solver of B alone, when D is nonzero only on
// a few rows and columns T (a bar added or removed, a rest length or weight
// changed, a particle's mass, a new particle's row): D = U C U^T, U the
// columns of the identity at T, C = D[T, T] (dense, k x k, any sign), and
//   (B + U C U^T)^-1 b = y - Z C (I + S C)^-1 y_T,   y = B^-1 b,
//   Z = B^-1 U (a solve per new row, once; the new rows' together), S = Z[T, :]
// (Sherman-Morrison-Woodbury without C^-1, so a singular C - one bar's
// w (e_i - e_j)(e_i - e_j)^T - is fine). Exact up to rounding: the same
// solution as a fresh factorisation of B + D, at the price of one solve per
// new row once and 2 n k flops per solve after (projective.hpp decides when
// a refactorisation pays off instead). Preferred, measured
// (bench/bench_low_rank.cpp), to conjugate gradients preconditioned by the
// old factor, which solve to 1e-12 in about 2x a plain solve on every step
// until the next factorisation, where this costs 1.0-1.1x; and to
// CHOLMOD's up/down-dates, a dependency for the same result. B may grow by rows that it solves
// apart from the others (a block diagonal extension: B^-1 e_r is zero on
// rows added later, so the columns of Z kept stay right).
#include <Eigen/Dense>
#include <functional>
#include <vector>

namespace tendril {

class LowRankSolve {
 public:
  using Solve = std::function<void(Eigen::MatrixXd&)>;  // every column b -> B^-1 b, in place
  // Forgets every change: solves with B alone.
  void clear();
  // The change D is now `delta` (dense over `rows`, in their order) on the
  // rows `rows`, which extend rows() (rows already there keep their place),
  // and B has n rows. False when I + S C is singular or its determinant,
  // det(B + D) / det(B), not positive: B + D is not positive definite (or
  // nearly not), so the caller refactors, which says why.
  bool set(const Solve& B, Eigen::Index n, const std::vector<int>& rows, const Eigen::MatrixXd& delta);
  // Every column b -> (B + D)^-1 b, in place.
  void solve(const Solve& B, Eigen::MatrixXd& b) const;
  const std::vector<int>& rows() const { return rows_; }

 private:
  std::vector<int> rows_;
  Eigen::MatrixXd Z_, C_;
  Eigen::PartialPivLU<Eigen::MatrixXd> K_;  // I + S C
  mutable Eigen::VectorXd yT_;
};

}  // namespace tendril
