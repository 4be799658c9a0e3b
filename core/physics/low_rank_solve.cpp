// Sherman-Morrison-Woodbury between the halves of the factor's solve
// (low_rank_solve.hpp).
#include "physics/low_rank_solve.hpp"

#include <cmath>

namespace tendril {

void LowRankSolve::clear(const LdltFactor& f) {
  rows_.clear();
  G_.clear();
  S_.resize(0, 0);
  C_.resize(0, 0);
  inverse_d_ = inverse_diagonal(f);
  parent_ = elimination_parents(f);
}

bool LowRankSolve::set(const LdltFactor& f, const Eigen::VectorXd& grown, const std::vector<int>& rows,
                       const Eigen::MatrixXd& delta) {
  const Eigen::Index k = Eigen::Index(rows.size()), had = Eigen::Index(rows_.size());
  const Eigen::Index n0 = f.rows(), n = n0 + grown.size();
  // D^-1: the factor's on its rows (kept since clear), the grown
  // diagonal's after them.
  inverse_d_.conservativeResize(n);
  inverse_d_.tail(grown.size()) = grown.cwiseInverse();
  // The new rows' columns of G: a factored row's unit column forward-solved
  // along its path in the elimination tree (the rows it can reach), a grown
  // row's its own unit column. Those of the rows seen before stay: the
  // factor did not change, and grown rows are apart from it.
  G_.resize(std::size_t(k));
  dense_.resize(std::size_t(n), 0.0);  // zero between uses
  for (Eigen::Index c = had; c < k; ++c) {
    Column& g = G_[std::size_t(c)];
    if (const int r = rows[std::size_t(c)]; r < n0) forward_unit(f, parent_, r, g.row, g.value, dense_);
    else g = {{r}, {1.0}};
  }
  // S = G^T D^-1 G: the block of the old rows stays, the new rows' entries
  // from each new column scattered and dotted with every column.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(k, k);
  S.topLeftCorner(had, had) = S_.topLeftCorner(had, had);
  for (Eigen::Index j = had; j < k; ++j) {
    const Column& gj = G_[std::size_t(j)];
    for (std::size_t e = 0; e < gj.row.size(); ++e)
      dense_[std::size_t(gj.row[e])] = gj.value[e] * inverse_d_[gj.row[e]];
    for (Eigen::Index i = 0; i < k; ++i) {
      const Column& gi = G_[std::size_t(i)];
      double sum = 0;
      for (std::size_t e = 0; e < gi.row.size(); ++e) sum += gi.value[e] * dense_[std::size_t(gi.row[e])];
      S(i, j) = sum;
      S(j, i) = sum;
    }
    for (int r : gj.row) dense_[std::size_t(r)] = 0.0;
  }
  S_ = std::move(S);
  rows_ = rows;
  C_ = delta;
  K_.compute(Eigen::MatrixXd::Identity(k, k) + S_ * C_);
  // A positive determinant is necessary for B + D to stay positive definite;
  // a small rcond means the correction would lose the digits a fresh
  // factorisation keeps.
  const double det = K_.determinant();
  return std::isfinite(det) && det > 0 && K_.rcond() > 1e-10;
}

void LowRankSolve::solve(const LdltFactor& f, const Eigen::VectorXd& grown, Eigen::MatrixXd& b,
                         RowsOfColumns& scratch) const {
  const Eigen::Index n0 = f.rows(), m = b.cols();
  if (b.rows() == 0 || m == 0) return;
  forward_columns(f, b.topRows(n0), scratch);  // f = F b on the factored rows; the grown ones stay in b
  if (!rows_.empty()) {
    auto at = [&](int i, Eigen::Index c) -> double& { return i < n0 ? scratch(i, c) : b(i, c); };
    yT_.resize(Eigen::Index(rows_.size()));
    for (Eigen::Index c = 0; c < m; ++c) {
      for (std::size_t t = 0; t < G_.size(); ++t) {
        const Column& g = G_[t];
        double sum = 0;
        for (std::size_t e = 0; e < g.row.size(); ++e) sum += g.value[e] * (inverse_d_[g.row[e]] * at(g.row[e], c));
        yT_[Eigen::Index(t)] = sum;
      }
      kw_ = K_.solve(yT_);  // sized once: no allocation in a step
      w_.noalias() = C_ * kw_;
      for (std::size_t t = 0; t < G_.size(); ++t) {
        const Column& g = G_[t];
        for (std::size_t e = 0; e < g.row.size(); ++e) at(g.row[e], c) -= g.value[e] * w_[Eigen::Index(t)];
      }
    }
  }
  backward_columns(f, inverse_d_, scratch, b.topRows(n0));
  if (grown.size() > 0) b.bottomRows(grown.size()).array().colwise() /= grown.array();
}

}  // namespace tendril
