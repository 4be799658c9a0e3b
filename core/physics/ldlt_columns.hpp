#pragma once
// Solves with a sparse LDL^T factor for several right-hand sides in one pass
// over the factor: what Eigen's SimplicialLDLT::solve does column by column,
// the same operations in the same order (so the same numbers bit for bit),
// but each entry of L read once for all the columns, not once a column. The
// triangular solves stream L and stall on its scattered rows; three columns
// cost little more than one. The projective global step solves its x, y and
// z with one factor, and a change's correction its new unit columns
// (projective.hpp, low_rank_solve.hpp).
#include <Eigen/SparseCholesky>
#include <vector>

namespace tendril {

using LdltFactor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
using RowsOfColumns = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// X <- A^-1 X, A the matrix f factored (successfully); `scratch` holds X's
// rows permuted (kept by the caller, so that a solve allocates nothing once
// it has been sized).
void solve_columns(const LdltFactor& f, Eigen::Ref<Eigen::MatrixXd> X, RowsOfColumns& scratch);

// Its two halves, A^-1 = (L^-1 P)^T D^-1 (L^-1 P): Y <- L^-1 P X, then
// X <- P^-1 L^-T D^-1 Y (low_rank_solve.hpp corrects between them).
// `inverse_d` is inverse_diagonal(f), taken once per factorisation: Eigen's
// vectorD() returns a copy, which a solve would allocate every time.
void forward_columns(const LdltFactor& f, const Eigen::Ref<const Eigen::MatrixXd>& X, RowsOfColumns& Y);
void backward_columns(const LdltFactor& f, const Eigen::VectorXd& inverse_d, RowsOfColumns& Y,
                      Eigen::Ref<Eigen::MatrixXd> X);
Eigen::VectorXd inverse_diagonal(const LdltFactor& f);  // D^-1, as Eigen's solve takes it

// Per row r of the factored matrix: how many rows L^-1 P e_r can have
// nonzero (r's ancestors in the elimination tree, itself included), what a
// forward solve of its unit column writes.
std::vector<int> forward_reach(const LdltFactor& f);

// The elimination tree of f's L: each column's parent, or -1 at a root.
std::vector<int> elimination_parents(const LdltFactor& f);
// L^-1 P e_r, walking only r's ancestors (`parent`: elimination_parents),
// the same numbers as forward_columns gives it: its nonzero rows ascending
// into `rows`, their values into `values`. `dense`: n zeros, left zero.
void forward_unit(const LdltFactor& f, const std::vector<int>& parent, Eigen::Index r, std::vector<int>& rows,
                  std::vector<double>& values, std::vector<double>& dense);

}  // namespace tendril
