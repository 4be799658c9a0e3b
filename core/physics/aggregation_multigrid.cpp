// Smoothed-aggregation multigrid (aggregation_multigrid.hpp).
#include "physics/aggregation_multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace tendril {

namespace {

// A connection is strong when |a_ij| >= theta sqrt(a_ii a_jj): the usual
// choice for smoothed aggregation. On a prestressed net's x block the bars
// along x are about EA/T = 100 times stiffer than those across, so the
// aggregates follow the lines of stiff bars, as they should.
constexpr double kStrength = 0.08;  // 0.25 took 177 conjugate-gradient iterations on the 800 x 800 net, 0.02 64, 0.08 63
constexpr int kCoarsestRows = 400;     // factored below this
constexpr double kStalled = 0.85;      // a level that keeps more rows than this stops coarsening

using RowsD = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;  // the setup's matrices (the cycle's: float)

// Aggregate of every row (-1: none, a row without strong connections, left
// to the smoother); returns the number of aggregates.
int aggregate(const RowsD& A, const Eigen::VectorXd& diagonal, std::vector<int>& agg,
              std::vector<std::uint8_t>& strong) {
  const int n = int(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* value = A.valuePtr();
  strong.assign(std::size_t(A.nonZeros()), 0);
  std::vector<int> degree(n, 0);
  for (int i = 0; i < n; ++i)
    for (int k = outer[i]; k < outer[i + 1]; ++k) {
      const int j = inner[k];
      if (j != i && std::abs(value[k]) >= kStrength * std::sqrt(diagonal[i] * diagonal[j])) {
        strong[std::size_t(k)] = 1;
        ++degree[i];
      }
    }
  constexpr int kFree = -2;
  agg.assign(n, kFree);
  int count = 0;
  // 1: a row whose strong neighbours are all free starts an aggregate with them.
  for (int i = 0; i < n; ++i) {
    if (agg[i] != kFree) continue;
    if (degree[i] == 0) {
      agg[i] = -1;
      continue;
    }
    bool all_free = true;
    for (int k = outer[i]; k < outer[i + 1] && all_free; ++k)
      if (strong[std::size_t(k)] && agg[inner[k]] != kFree) all_free = false;
    if (!all_free) continue;
    agg[i] = count;
    for (int k = outer[i]; k < outer[i + 1]; ++k)
      if (strong[std::size_t(k)]) agg[inner[k]] = count;
    ++count;
  }
  // 2: a free row joins the aggregate of its strongest neighbour from step 1.
  const std::vector<int> first = agg;
  for (int i = 0; i < n; ++i) {
    if (agg[i] != kFree) continue;
    double best = 0;
    for (int k = outer[i]; k < outer[i + 1]; ++k)
      if (strong[std::size_t(k)] && first[inner[k]] >= 0 && std::abs(value[k]) > best) {
        best = std::abs(value[k]);
        agg[i] = first[inner[k]];
      }
  }
  // 3: what is left makes aggregates of itself and its free strong neighbours.
  for (int i = 0; i < n; ++i) {
    if (agg[i] != kFree) continue;
    agg[i] = count;
    for (int k = outer[i]; k < outer[i + 1]; ++k)
      if (strong[std::size_t(k)] && agg[inner[k]] == kFree) agg[inner[k]] = count;
    ++count;
  }
  return count;
}

// A matrix built row by row: each row's entries in any order, duplicates
// summed, then sorted by column (setFromTriplets sorted them all at once
// and took longer than the cycle's setup otherwise did).
class RowBuilder {
 public:
  explicit RowBuilder(int cols) : cols_(cols), at_(std::size_t(cols), -1) {}
  void add(int col, double v) {
    if (at_[std::size_t(col)] < 0) {
      at_[std::size_t(col)] = int(row_.size());
      row_.emplace_back(col, v);
    } else {
      row_[std::size_t(at_[std::size_t(col)])].second += v;
    }
  }
  void end_row() {
    std::sort(row_.begin(), row_.end());
    for (const auto& [c, v] : row_) {
      inner_.push_back(c), value_.push_back(v);
      at_[std::size_t(c)] = -1;
    }
    row_.clear();
    outer_.push_back(int(inner_.size()));
  }
  RowsD matrix() const {
    RowsD M(Eigen::Index(outer_.size() - 1), cols_);
    M.resizeNonZeros(Eigen::Index(inner_.size()));
    std::copy(outer_.begin(), outer_.end(), M.outerIndexPtr());
    std::copy(inner_.begin(), inner_.end(), M.innerIndexPtr());
    std::copy(value_.begin(), value_.end(), M.valuePtr());
    return M;
  }

 private:
  int cols_;
  std::vector<int> at_;                    // per column: its place in row_, or -1
  std::vector<std::pair<int, double>> row_;
  std::vector<int> outer_{0}, inner_;
  std::vector<double> value_;
};

// X Y, row by row (Gustavson): each entry summed in the order of X's row
// and Y's rows, so the same on every run.
RowsD product(const RowsD& X, const RowsD& Y) {
  RowBuilder out(int(Y.cols()));
  for (int i = 0; i < X.rows(); ++i) {
    for (RowsD::InnerIterator x(X, i); x; ++x)
      for (RowsD::InnerIterator y(Y, x.index()); y; ++y) out.add(int(y.index()), x.value() * y.value());
    out.end_row();
  }
  return out.matrix();
}

// P = (I - omega D_F^-1 A_F) T: T the aggregates' piecewise constants, A_F
// A with its weak connections added to the diagonal (the rows' sums stay,
// so constants stay near its null space), omega = 4/3 over a bound of the
// spectral radius of D_F^-1 A_F (Gershgorin's).
RowsD smoothed_prolongator(const RowsD& A, const Eigen::VectorXd& diagonal, const std::vector<int>& agg,
                          const std::vector<std::uint8_t>& strong, int coarse) {
  const int n = int(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const double* value = A.valuePtr();
  Eigen::VectorXd dF(n);
  double radius = 0;
  for (int i = 0; i < n; ++i) {
    double d = diagonal[i], off = 0;
    for (int k = outer[i]; k < outer[i + 1]; ++k) {
      if (inner[k] == i) continue;
      if (strong[std::size_t(k)]) off += std::abs(value[k]);
      else d += value[k];
    }
    if (!(d > 0)) d = diagonal[i];  // weak connections that would leave nothing: keep the row as it is
    dF[i] = d;
    radius = std::max(radius, 1 + off / d);
  }
  const double omega = 4.0 / 3.0 / radius;
  RowBuilder P(coarse);
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0) P.add(agg[i], 1.0 - omega);  // the diagonal of A_F over dF: 1
    for (int k = outer[i]; k < outer[i + 1]; ++k) {
      const int j = inner[k];
      if (j == i || !strong[std::size_t(k)] || agg[j] < 0) continue;
      P.add(agg[j], -omega * value[k] / dF[i]);
    }
    P.end_row();
  }
  return P.matrix();
}

// One Gauss-Seidel sweep on rows sorted by column, each row's diagonal at
// diagonal_at[i]: the entries left of it, then those right of it, in the
// row's order. From x = 0 (`from_zero`, a forward sweep) the right ones
// multiply zeros and are left out, which changes no sum. The row just
// relaxed is usually the neighbour next to the diagonal (i - 1 going
// forward, i + 1 back): its value is taken from the register that holds
// it, not loaded back from the store just made, which would put the
// store's forwarding on the sweep's chain of dependent rows (the same
// products in the same order).
template <class Matrix, class Vector>
void gauss_seidel(const Matrix& A, const std::vector<int>& diagonal_at, const Vector& inverse_diagonal,
                  const Vector& b, Vector& x, bool forward, bool from_zero = false) {
  const int n = int(A.rows());
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const auto* value = A.valuePtr();
  using Scalar = std::remove_cvref_t<decltype(b[0])>;
  if (forward) {
    Scalar last = 0;
    for (int i = 0; i < n; ++i) {
      Scalar s = b[i];
      const int d = diagonal_at[std::size_t(i)];
      int k = outer[i];
      for (; k + 1 < d; ++k) s -= value[k] * x[inner[k]];
      if (k < d) {
        if (inner[k] == i - 1) [[likely]] s -= value[k] * last;
        else s -= value[k] * x[inner[k]];
      }
      if (!from_zero)
        for (k = d + 1; k < outer[i + 1]; ++k) s -= value[k] * x[inner[k]];
      last = s * inverse_diagonal[i];
      x[i] = last;
    }
    return;
  }
  Scalar last = 0;
  for (int i = n - 1; i >= 0; --i) {
    Scalar s = b[i];
    const int d = diagonal_at[std::size_t(i)], end = outer[i + 1];
    for (int k = outer[i]; k < d; ++k) s -= value[k] * x[inner[k]];
    int k = from_zero ? end : d + 1;
    if (k < end) {
      if (inner[k] == i + 1) [[likely]] s -= value[k] * last;
      else s -= value[k] * x[inner[k]];
      ++k;
    }
    for (; k < end; ++k) s -= value[k] * x[inner[k]];
    last = s * inverse_diagonal[i];
    x[i] = last;
  }
}

// The whole symmetric matrix, by rows, from its lower triangle by columns:
// row i is row i of the lower triangle (columns j < i, found in column j)
// followed by column i (rows >= i).
RowsD whole(const Eigen::SparseMatrix<double>& lower) {
  const int n = int(lower.rows());
  const int* lo = lower.outerIndexPtr();
  const int* li = lower.innerIndexPtr();
  const double* lv = lower.valuePtr();
  std::vector<int> left(n, 0);
  for (int j = 0; j < n; ++j)
    for (int k = lo[j]; k < lo[j + 1]; ++k)
      if (li[k] > j) ++left[li[k]];
  RowsD A(n, n);
  int* outer = A.outerIndexPtr();
  outer[0] = 0;
  for (int i = 0; i < n; ++i) outer[i + 1] = outer[i] + left[i] + (lo[i + 1] - lo[i]);
  A.resizeNonZeros(outer[n]);
  int* inner = A.innerIndexPtr();
  double* value = A.valuePtr();
  std::vector<int> fill(outer, outer + n);
  for (int j = 0; j < n; ++j)
    for (int k = lo[j]; k < lo[j + 1]; ++k) {
      const int i = li[k];
      if (i > j) inner[fill[i]] = j, value[fill[i]++] = lv[k];  // (i, j) below the diagonal, columns ascending
    }
  for (int i = 0; i < n; ++i)
    for (int k = lo[i]; k < lo[i + 1]; ++k) inner[fill[i]] = li[k], value[fill[i]++] = lv[k];
  return A;
}

}  // namespace

bool AggregationMultigrid::setup(const Lower& lower) {
  levels_.clear();
  RowsD A = whole(lower);
  std::vector<int> agg;
  std::vector<std::uint8_t> strong;
  for (;;) {
    const Eigen::VectorXd diagonal = A.diagonal();
    if (!(diagonal.array() > 0).all()) return false;
    Level L;
    const int n = int(A.rows());
    L.inverse_diagonal = diagonal.cwiseInverse().cast<float>();
    L.b.resize(n), L.x.resize(n), L.r.resize(n);
    int coarse = 0;
    if (n > kCoarsestRows) coarse = aggregate(A, diagonal, agg, strong);
    if (coarse == 0 || coarse > kStalled * n) {
      L.A = A.cast<float>();
      levels_.push_back(std::move(L));
      break;
    }
    const RowsD P = smoothed_prolongator(A, diagonal, agg, strong, coarse);
    const RowsD R = P.transpose();
    const RowsD AP = product(A, P);
    L.A = A.cast<float>(), L.P = P.cast<float>(), L.R = R.cast<float>();
    L.diagonal_at.resize(std::size_t(n));
    for (int i = 0; i < n; ++i) {  // rows sorted by column, the diagonal in each (positive, above)
      const int* first = L.A.innerIndexPtr() + L.A.outerIndexPtr()[i];
      const int* last = L.A.innerIndexPtr() + L.A.outerIndexPtr()[i + 1];
      L.diagonal_at[std::size_t(i)] = int(std::lower_bound(first, last, i) - L.A.innerIndexPtr());
    }
    A = product(R, AP);
    levels_.push_back(std::move(L));
  }
  coarsest_.compute(Eigen::SparseMatrix<double>(A));
  return coarsest_.info() == Eigen::Success && (coarsest_.vectorD().array() > 0).all();
}

void AggregationMultigrid::cycle(std::size_t l) const {
  const Level& L = levels_[l];
  if (l + 1 == levels_.size()) {
    L.x = coarsest_.solve(L.b.cast<double>()).cast<float>();
    return;
  }
  L.x.setZero();
  gauss_seidel(L.A, L.diagonal_at, L.inverse_diagonal, L.b, L.x, true, true);
  L.r.noalias() = L.b - L.A * L.x;
  const Level& C = levels_[l + 1];
  C.b.noalias() = L.R * L.r;
  cycle(l + 1);
  L.x.noalias() += L.P * C.x;
  gauss_seidel(L.A, L.diagonal_at, L.inverse_diagonal, L.b, L.x, false);
}

void AggregationMultigrid::apply(const Eigen::Ref<const Eigen::VectorXd>& in, Eigen::Ref<Eigen::VectorXd> out) const {
  levels_.front().b = in.cast<float>();
  cycle(0);
  out = levels_.front().x.cast<double>();
}

double AggregationMultigrid::operator_complexity() const {
  if (levels_.empty()) return 0;
  double sum = 0;
  for (const Level& L : levels_) sum += double(L.A.nonZeros());
  return sum / double(levels_.front().A.nonZeros());
}

}  // namespace tendril
