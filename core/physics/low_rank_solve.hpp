#pragma once
// Solves (B + D) x = b with the factor of B alone, when D is nonzero only on
// a few rows and columns T (a bar added or removed, a rest length or weight
// changed, a particle's mass, a new particle's row): D = U C U^T, U the
// columns of the identity at T, C = D[T, T] (dense, k x k, any sign).
// B = diag(A, grown): A factored as P^T L D L^T P (ldlt_columns.hpp), and
// the rows added since, each its own diagonal entry. With F = L^-1 P (the
// identity on the grown rows), B^-1 = F^T D^-1 F, so
//   (B + U C U^T)^-1 b = F^T D^-1 (f - G w),   f = F b,  G = F U,
//   w = C (I + S C)^-1 y_T,  y_T = G^T D^-1 f,  S = G^T D^-1 G
// (Sherman-Morrison-Woodbury without C^-1, so a singular C - one bar's
// w (e_i - e_j)(e_i - e_j)^T - is fine). A column of G is the forward solve
// of a unit column: sparse (the row's ancestors in the elimination tree,
// walked alone), found once per new row, and S needs no backward solve. The correction
// goes between the forward and the backward half of the solve it corrects,
// so a step makes one pass over the factor, changes or not. Exact up to
// rounding: the solution of a fresh factorisation of B + D. Preferred,
// measured (bench/bench_low_rank.cpp), to conjugate gradients preconditioned
// by the old factor, which solve to 1e-12 in about 2x a plain solve on every
// step until the next factorisation, and to CHOLMOD's up/down-dates, a
// dependency for the same result (projective.hpp decides when a
// refactorisation pays off instead).
#include <Eigen/Dense>
#include <vector>

#include "physics/ldlt_columns.hpp"

namespace tendril {

class LowRankSolve {
 public:
  // Forgets every change: solves with B alone, f newly factored.
  void clear(const LdltFactor& f);
  // The change D is now `delta` (dense over `rows`, in their order) on the
  // rows `rows`, which extend rows() (rows already there keep their place);
  // B is diag(f's matrix, grown). False when I + S C is singular or its
  // determinant, det(B + D) / det(B), not positive: B + D is not positive
  // definite (or nearly not), so the caller refactors, which says why.
  bool set(const LdltFactor& f, const Eigen::VectorXd& grown, const std::vector<int>& rows,
           const Eigen::MatrixXd& delta);
  // Every column b -> (B + D)^-1 b, in place (`scratch`: the forward half).
  void solve(const LdltFactor& f, const Eigen::VectorXd& grown, Eigen::MatrixXd& b, RowsOfColumns& scratch) const;
  const std::vector<int>& rows() const { return rows_; }

 private:
  struct Column {  // a column of G: its nonzero rows (forward-solved order; grown rows as they are)
    std::vector<int> row;
    std::vector<double> value;
  };
  std::vector<int> rows_;
  std::vector<Column> G_;
  Eigen::MatrixXd S_, C_;
  Eigen::VectorXd inverse_d_;  // D^-1 of every row, the factor's (from clear) and the grown ones
  std::vector<int> parent_;    // the factor's elimination tree (from clear)
  Eigen::PartialPivLU<Eigen::MatrixXd> K_;  // I + S C
  mutable Eigen::VectorXd yT_, kw_, w_;  // y_T, (I + S C)^-1 y_T, w
  mutable std::vector<double> dense_;  // a column of G scattered, for S
};

}  // namespace tendril
