// Several columns through one LDL^T factor (ldlt_columns.hpp). Each loop is
// Eigen's (SimplicialCholeskyBase::_solve_impl and the sparse triangular
// solvers of SparseCore/TriangularSolver.h) with the columns innermost.
#include "physics/ldlt_columns.hpp"

namespace tendril {

namespace {

// Past the diagonal in column i of L (Eigen skips the entries above it,
// then the diagonal's, and takes the rest as stored).
int below(const Eigen::SparseMatrix<double>& L, Eigen::Index i) {
  const int* outer = L.outerIndexPtr();
  const int* inner = L.innerIndexPtr();
  int k = outer[i];
  const int end = outer[i + 1];
  while (k < end && inner[k] < i) ++k;
  if (k < end && inner[k] == i) ++k;
  return k;
}

}  // namespace

void forward_columns(const LdltFactor& f, const Eigen::Ref<const Eigen::MatrixXd>& X, RowsOfColumns& Y) {
  const Eigen::Index n = X.rows(), m = X.cols();
  if (f.permutationP().size() > 0) Y = f.permutationP() * X;
  else Y = X;
  const Eigen::SparseMatrix<double>& L = f.matrixL().nestedExpression();  // unit lower, by columns
  if (n == 0 || m == 0 || L.nonZeros() == 0) return;
  const int* outer = L.outerIndexPtr();
  const int* inner = L.innerIndexPtr();
  const double* value = L.valuePtr();
  // L y = P b, by columns: a zero entry's column is skipped, as Eigen skips it
  for (Eigen::Index i = 0; i < n; ++i) {
    const double* yi = Y.row(i).data();
    bool any = false;
    for (Eigen::Index c = 0; c < m; ++c) any |= yi[c] != 0.0;
    if (!any) continue;  // a unit column's rows before its one: L's column is not read
    for (int k = below(L, i), end = outer[i + 1]; k < end; ++k) {
      double* yr = Y.row(inner[k]).data();
      const double v = value[k];
      for (Eigen::Index c = 0; c < m; ++c)
        if (yi[c] != 0.0) yr[c] -= yi[c] * v;
    }
  }
}

Eigen::VectorXd inverse_diagonal(const LdltFactor& f) { return f.vectorD().cwiseInverse(); }

std::vector<int> forward_reach(const LdltFactor& f) {
  const Eigen::SparseMatrix<double>& L = f.matrixL().nestedExpression();
  const Eigen::Index n = L.cols();
  const int* outer = L.outerIndexPtr();
  const int* inner = L.innerIndexPtr();
  // A column's parent is its first row below the diagonal; parents come
  // after their children, so the depths fill from the root down.
  std::vector<int> depth(std::size_t(n), 1);
  for (Eigen::Index j = n - 1; j >= 0; --j)
    if (const int k = below(L, j); k < outer[j + 1]) depth[std::size_t(j)] += depth[std::size_t(inner[k])];
  std::vector<int> reach(static_cast<std::size_t>(n));
  for (Eigen::Index r = 0; r < n; ++r) {
    const Eigen::Index p = f.permutationP().size() > 0 ? f.permutationP().indices()[r] : r;
    reach[std::size_t(r)] = depth[std::size_t(p)];
  }
  return reach;
}

void backward_columns(const LdltFactor& f, const Eigen::VectorXd& inverse_d, RowsOfColumns& Y,
                      Eigen::Ref<Eigen::MatrixXd> X) {
  const Eigen::Index n = Y.rows(), m = Y.cols();
  if (inverse_d.size() > 0)
    for (Eigen::Index i = 0; i < n; ++i) {
      const double inverse = inverse_d[i];  // D^-1 y as Eigen's diagonal inverse takes it
      double* yi = Y.row(i).data();
      for (Eigen::Index c = 0; c < m; ++c) yi[c] = inverse * yi[c];
    }
  const Eigen::SparseMatrix<double>& L = f.matrixL().nestedExpression();
  if (n > 0 && m > 0 && L.nonZeros() > 0) {  // L^T z = y, by the rows of L^T (L's columns), last first
    const int* outer = L.outerIndexPtr();
    const int* inner = L.innerIndexPtr();
    const double* value = L.valuePtr();
    for (Eigen::Index i = n - 1; i >= 0; --i) {
      double* yi = Y.row(i).data();
      for (int k = below(L, i), end = outer[i + 1]; k < end; ++k) {
        const double* yr = Y.row(inner[k]).data();
        const double v = value[k];
        for (Eigen::Index c = 0; c < m; ++c) yi[c] -= v * yr[c];
      }
    }
  }
  if (f.permutationP().size() > 0) X = f.permutationPinv() * Y;
  else X = Y;
}

void solve_columns(const LdltFactor& f, Eigen::Ref<Eigen::MatrixXd> X, RowsOfColumns& scratch) {
  if (X.rows() == 0 || X.cols() == 0) return;
  forward_columns(f, X, scratch);
  backward_columns(f, inverse_diagonal(f), scratch, X);
}

}  // namespace tendril
