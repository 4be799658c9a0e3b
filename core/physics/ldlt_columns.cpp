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

std::vector<int> elimination_parents(const LdltFactor& f) {
  // A column's parent is its first row below the diagonal.
  const Eigen::SparseMatrix<double>& L = f.matrixL().nestedExpression();
  std::vector<int> parent(std::size_t(L.cols()), -1);
  for (Eigen::Index j = 0; j < L.cols(); ++j)
    if (const int k = below(L, j); k < L.outerIndexPtr()[j + 1]) parent[std::size_t(j)] = L.innerIndexPtr()[k];
  return parent;
}

std::vector<int> forward_reach(const LdltFactor& f) {
  const std::vector<int> parent = elimination_parents(f);
  const std::size_t n = parent.size();
  // Parents come after their children: the depths fill from the roots down.
  std::vector<int> depth(n, 1);
  for (std::size_t j = n; j-- > 0;)
    if (parent[j] >= 0) depth[j] += depth[std::size_t(parent[j])];
  std::vector<int> reach(n);
  for (std::size_t r = 0; r < n; ++r)
    reach[r] = depth[std::size_t(f.permutationP().size() > 0 ? f.permutationP().indices()[Eigen::Index(r)] : int(r))];
  return reach;
}

// forward_columns' loop for one unit column: a column whose entry is zero
// is skipped, the others subtract in ascending order; every row it can
// write lies on the path to the root (L's column j holds ancestors of j).
void forward_unit(const LdltFactor& f, const std::vector<int>& parent, Eigen::Index r, std::vector<int>& rows,
                  std::vector<double>& values, std::vector<double>& dense) {
  const Eigen::SparseMatrix<double>& L = f.matrixL().nestedExpression();
  const int* outer = L.outerIndexPtr();
  const int* inner = L.innerIndexPtr();
  const double* value = L.valuePtr();
  rows.clear(), values.clear();
  int i = f.permutationP().size() > 0 ? f.permutationP().indices()[r] : int(r);
  dense[std::size_t(i)] = 1;
  for (; i >= 0; i = parent[std::size_t(i)]) {
    const double yi = dense[std::size_t(i)];
    dense[std::size_t(i)] = 0;
    if (yi == 0.0) continue;
    rows.push_back(i), values.push_back(yi);
    for (int k = below(L, i), end = outer[i + 1]; k < end; ++k) dense[std::size_t(inner[k])] -= yi * value[k];
  }
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
