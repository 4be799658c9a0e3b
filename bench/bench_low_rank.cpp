// Why projective dynamics follows a change with a Woodbury correction
// (core/physics/low_rank_solve.hpp): on the global matrix of the issue-18
// net (s x s, the boundary fixed: (s-2)^2 rows per axis, EA/L = 1e5 N/m
// plus the prestress' geometric 1e3 N/m on every grid edge, the momentum
// weight of fictitious masses at vie_dt = 100 dt), one cable added across
// a cell, solved four ways: the old factor alone (the steady solve), a
// fresh factorisation (the reference), the old factor with the Woodbury
// correction, and conjugate gradients preconditioned by the old factor
// (to 1e-12). Each solve repeated --reps times; thread CPU time.
//
//   bench_low_rank [--sides 128,316] [--reps 20]
#include <Eigen/Dense>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/huge_pages.hpp"
#include "bench_util.hpp"

using namespace tendril::bench;

namespace {

using Sparse = Eigen::SparseMatrix<double>;
using LDLT = Eigen::SimplicialLDLT<Sparse>;

// The old factor as a preconditioner for Eigen's conjugate gradients.
struct OldFactor {
  const LDLT* factor = nullptr;
  template <class M> OldFactor& analyzePattern(const M&) { return *this; }
  template <class M> OldFactor& factorize(const M&) { return *this; }
  template <class M> OldFactor& compute(const M&) { return *this; }
  template <class R> Eigen::VectorXd solve(const Eigen::MatrixBase<R>& b) const { return factor->solve(b); }
  Eigen::ComputationInfo info() { return Eigen::Success; }
};

void measure(int side, int reps, Table& table) {
  const int s = side - 2, n = s * s;
  auto id = [&](int r, int c) { return r * s + c; };
  const double k = 1e5 + 1e3, inertia = 4 * k * 1e-4;
  std::vector<Eigen::Triplet<double>> t;
  auto edge = [&](int a, int b) {  // -1: a fixed boundary particle
    if (a >= 0) t.emplace_back(a, a, k);
    if (b >= 0) t.emplace_back(b, b, k);
    if (a >= 0 && b >= 0) {
      t.emplace_back(a, b, -k);
      t.emplace_back(b, a, -k);
    }
  };
  for (int r = -1; r < s; ++r)
    for (int c = -1; c < s; ++c) {
      const int p = r >= 0 && c >= 0 ? id(r, c) : -1;
      if (p >= 0) t.emplace_back(p, p, inertia);
      if (r >= 0) edge(c >= 0 ? p : -1, c + 1 < s ? id(r, c + 1) : -1);
      if (c >= 0) edge(r >= 0 ? p : -1, r + 1 < s ? id(r + 1, c) : -1);
    }
  Sparse A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  const int i = id(s / 3, s / 2), j = id(s / 3 + 1, s / 2 + 1);
  const double w = 1e5 / std::sqrt(2.0);
  Sparse D(n, n);
  std::vector<Eigen::Triplet<double>> d{{i, i, w}, {j, j, w}, {i, j, -w}, {j, i, -w}};
  D.setFromTriplets(d.begin(), d.end());
  const Sparse changed = A + D;
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 1);

  double t0 = thread_seconds();
  const LDLT old(A);
  const double factor_s = (thread_seconds() - t0);
  Eigen::VectorXd x;
  t0 = thread_seconds();
  for (int q = 0; q < reps; ++q) x = old.solve(b);
  const double solve_s = (thread_seconds() - t0) / reps;
  const Eigen::VectorXd exact = LDLT(changed).solve(b);

  t0 = thread_seconds();
  Eigen::MatrixXd Z(n, 2);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
  e[i] = 1;
  Z.col(0) = old.solve(e);
  e[i] = 0;
  e[j] = 1;
  Z.col(1) = old.solve(e);
  Eigen::Matrix2d C, S;
  C << w, -w, -w, w;
  S << Z(i, 0), Z(i, 1), Z(j, 0), Z(j, 1);
  const Eigen::PartialPivLU<Eigen::MatrixXd> K(Eigen::MatrixXd(Eigen::Matrix2d::Identity() + S * C));
  const double setup_s = (thread_seconds() - t0);
  t0 = thread_seconds();
  for (int q = 0; q < reps; ++q) {
    x = old.solve(b);
    const Eigen::Vector2d yT(x[i], x[j]);
    x -= Z * (C * K.solve(yT));
  }
  const double woodbury_s = (thread_seconds() - t0) / reps;
  const double woodbury_error = (x - exact).norm() / exact.norm();

  Eigen::ConjugateGradient<Sparse, Eigen::Lower | Eigen::Upper, OldFactor> cg;
  cg.compute(changed);
  cg.preconditioner().factor = &old;
  cg.setTolerance(1e-12);
  t0 = thread_seconds();
  for (int q = 0; q < reps; ++q) x = cg.solve(b);
  const double cg_s = (thread_seconds() - t0) / reps;
  const double cg_error = (x - exact).norm() / exact.norm();

  table.add({fmt("%d x %d", side, side), fmt("%d", n), fmt("%.1f ms", 1e3 * factor_s), fmt("%.2f ms", 1e3 * solve_s),
             fmt("%.2f ms", 1e3 * setup_s), fmt("%.2f ms (%.2f)", 1e3 * woodbury_s, woodbury_s / solve_s),
             fmt("%.0e", woodbury_error), fmt("%.2f ms (%.2f)", 1e3 * cg_s, cg_s / solve_s),
             fmt("%ld", long(cg.iterations())), fmt("%.0e", cg_error)});
}

}  // namespace

int main(int argc, char** argv) {
  tendril::restart_with_huge_pages(argv);  // as tendril itself runs (io/huge_pages.hpp)
  std::vector<int> sides{128, 316};
  int reps = 20;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--sides" && a + 1 < argc) {
      sides.clear();
      for (std::size_t v : parse_sizes(argv[++a])) sides.push_back(int(v));
    } else if (arg == "--reps" && a + 1 < argc) reps = std::max(1, std::stoi(argv[++a]));
    else {
      std::fprintf(arg == "-h" || arg == "--help" ? stdout : stderr, "usage: %s [--sides 128,316] [--reps 20]\n",
                   argv[0]);
      return arg == "-h" || arg == "--help" ? 0 : 2;
    }
  }
  std::puts("bench_low_rank: one cable added to the issue-18 net's projective matrix, solved with the old factor");
  std::puts("  (ratios to the steady solve; errors against a fresh factorisation of the changed matrix)\n");
  Table table({"net", "rows", "factorisation", "solve", "Woodbury setup", "Woodbury solve", "error",
               "CG (old factor)", "iterations", "error"});
  for (int side : sides) measure(side, reps, table);
  table.print();
  std::printf("load average %.2f\n", load_average());
  return 0;
}
