#pragma once
// A smoothed-aggregation multigrid V-cycle (Vanek, Mandel and Brezina 1996)
// for a sparse symmetric positive definite matrix whose near-null space is
// the constant vector: an axis block of the Newton tangent, a weighted graph
// Laplacian held at its supports. It replaces the block's sparse LDL^T as
// the conjugate gradients' preconditioner on large models: its setup and
// one cycle cost O(n), where the factors of a 2-D net's Laplacian cost
// n^1.5 to compute and n log n to apply.
//
// Setup: per level, aggregates of strongly connected rows (|a_ij| >=
// theta sqrt(a_ii a_jj)), in row order, so the hierarchy depends on the
// matrix alone; the piecewise-constant prolongator smoothed by one damped
// Jacobi step on the matrix with its weak connections moved onto the
// diagonal; the coarse matrix P^T A P; down to a few hundred rows, which
// are factored. Cycle: one forward Gauss-Seidel sweep before the coarse
// correction and one backward sweep after it, so the cycle is a symmetric
// positive definite operator, as conjugate gradients need.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <vector>

namespace tendril {

class AggregationMultigrid {
 public:
  using Lower = Eigen::SparseMatrix<double>;  // column-major, lower triangle
  // Builds the hierarchy for the symmetric matrix whose lower triangle is
  // given; false when a diagonal entry is not positive or the coarsest
  // matrix is not positive definite.
  bool setup(const Lower& lower);
  // out = one V-cycle applied to in (from zero).
  void apply(const Eigen::Ref<const Eigen::VectorXd>& in, Eigen::Ref<Eigen::VectorXd> out) const;
  int levels() const { return int(levels_.size()); }
  // Nonzeros of every level's matrix over the finest one's.
  double operator_complexity() const;

 private:
  // The cycle runs in single precision: it only preconditions, and half
  // the bytes make it cheaper where it streams its matrices.
  using Rows = Eigen::SparseMatrix<float, Eigen::RowMajor, int>;
  struct Level {
    Rows A;                    // the whole symmetric matrix
    Eigen::VectorXf inverse_diagonal;
    std::vector<int> diagonal_at;  // where each row's diagonal entry sits in A's values
    Rows P, R;                 // to this level from the next coarser one, and back (R = P^T)
    mutable Eigen::VectorXf b, x, r;
  };
  void cycle(std::size_t l) const;  // levels_[l].x from levels_[l].b
  std::vector<Level> levels_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> coarsest_;
};

}  // namespace tendril
