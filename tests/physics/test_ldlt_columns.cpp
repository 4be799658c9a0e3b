// Several columns through one LDL^T factor (ldlt_columns.hpp): every column
// comes out as Eigen's own solve gives it, bit for bit, whether dense, a
// unit column (the correction's), zero, or beside columns of each kind.
#include <doctest/doctest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <random>
#include <vector>

#include "physics/ldlt_columns.hpp"

using namespace tendril;

namespace {

// A grid Laplacian held at its boundary plus random couplings to far rows,
// so that the factor's fill, its ordering and its columns are irregular.
Eigen::SparseMatrix<double> system(int side, std::mt19937& random) {
  const int n = side * side;
  std::uniform_real_distribution<double> weight(0.5, 2.0);
  std::uniform_int_distribution<int> row(0, n - 1);
  std::vector<Eigen::Triplet<double>> t;
  auto link = [&](int i, int j, double w) {
    t.emplace_back(i, i, w), t.emplace_back(j, j, w), t.emplace_back(i, j, -w), t.emplace_back(j, i, -w);
  };
  for (int r = 0; r < side; ++r)
    for (int c = 0; c < side; ++c) {
      const int i = r * side + c;
      t.emplace_back(i, i, 0.1);  // held: positive definite
      if (c + 1 < side) link(i, i + 1, weight(random));
      if (r + 1 < side) link(i, i + side, weight(random));
    }
  for (int k = 0; k < n / 10; ++k) {
    const int i = row(random), j = row(random);
    if (i != j) link(i, j, weight(random));
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

}  // namespace

TEST_CASE("solve_columns gives each column of Eigen's solve, bit for bit") {
  std::mt19937 random(7);
  const Eigen::SparseMatrix<double> A = system(30, random);
  LdltFactor f(A);
  REQUIRE(f.info() == Eigen::Success);
  const Eigen::Index n = A.rows();
  std::normal_distribution<double> normal;
  Eigen::MatrixXd X(n, 5);
  for (Eigen::Index i = 0; i < n; ++i) X(i, 0) = normal(random), X(i, 1) = normal(random);
  X.col(2).setZero();
  X(17, 2) = 1;  // a unit column
  X.col(3).setZero();  // nothing
  X.col(4) = X.col(0);
  for (Eigen::Index i = 0; i < n; i += 3) X(i, 4) = 0;  // zeros among values
  RowsOfColumns scratch;
  Eigen::MatrixXd together = X;
  solve_columns(f, together, scratch);
  for (Eigen::Index c = 0; c < X.cols(); ++c) {
    const Eigen::VectorXd alone = f.solve(Eigen::VectorXd(X.col(c)));
    CAPTURE(c);
    CHECK((together.col(c).array() == alone.array()).all());
  }
  // And it solves: A x = b to rounding.
  CHECK((A * together - X).norm() <= 1e-12 * X.norm());

  SUBCASE("a block of rows, as the rows grown since a factorisation leave the factored ones") {
    Eigen::MatrixXd taller(n + 4, 2);
    taller.topRows(n) = X.leftCols(2);
    taller.bottomRows(4).setConstant(3.0);
    solve_columns(f, taller.topRows(n), scratch);
    CHECK((taller.topRows(n).array() == together.leftCols(2).array()).all());
    CHECK((taller.bottomRows(4).array() == 3.0).all());
  }
}

TEST_CASE("forward_reach bounds each unit column's forward solve, and forward_unit walks it to the same numbers") {
  // The structure's count: no unit column writes more rows, and the longest
  // chains of the elimination tree are written whole (no cancellation here).
  std::mt19937 random(11);
  const Eigen::SparseMatrix<double> A = system(20, random);
  LdltFactor f(A);
  REQUIRE(f.info() == Eigen::Success);
  const std::vector<int> reach = forward_reach(f);
  REQUIRE(reach.size() == std::size_t(A.rows()));
  const std::vector<int> parent = elimination_parents(f);
  std::vector<int> rows;
  std::vector<double> values, dense(std::size_t(A.rows()), 0.0);
  int equal = 0, longest = 0;
  for (Eigen::Index r = 0; r < A.rows(); ++r) {
    Eigen::MatrixXd unit = Eigen::MatrixXd::Zero(A.rows(), 1);
    unit(r, 0) = 1;
    RowsOfColumns y;
    forward_columns(f, unit, y);
    const int written = int((y.array() != 0.0).count());
    // forward_unit walks the path alone to the same numbers, bit for bit.
    forward_unit(f, parent, r, rows, values, dense);
    REQUIRE(rows.size() == std::size_t(written));
    for (std::size_t e = 0; e < rows.size(); ++e) CHECK(values[e] == y(rows[e], 0));
    CHECK(std::all_of(dense.begin(), dense.end(), [](double v) { return v == 0.0; }));
    CHECK(written <= reach[std::size_t(r)]);
    equal += written == reach[std::size_t(r)];
    longest = std::max(longest, reach[std::size_t(r)]);
  }
  MESSAGE("unit columns whose reach is exact: " << equal << " of " << A.rows() << "; longest " << longest);
  CHECK(equal > 0.9 * double(A.rows()));
  CHECK(longest > 20);  // a chain, not the diagonal: the count follows the tree
}
