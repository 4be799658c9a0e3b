// The static Newton solver's tangent and its solve (newton.hpp).
#include "physics/newton.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

namespace tendril {

namespace {

// An iteration that took more conjugate-gradient iterations than this
// makes the next one factor the axis blocks again at its positions (or
// build their multigrid hierarchies again, which costs less than their
// factors and so pays sooner: on the 1000 x 1000 net 8 iterations took
// 16.5 s in all, 20 took 19.5 s and every step 19.0 s).
constexpr int kRefactorAfter = 20;
constexpr int kRebuildAfter = 8;
constexpr int kMaxIterations = 1000;
// The entries of a particle's own block in the lower triangle: (a, b) and
// (b, a) are one entry, whichever row is larger.
constexpr int kPairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 0}, {2, 0}, {2, 1}};

// K_e of a bar at x; false for a slack cable (no force, no stiffness).
bool bar_tangent(const Bar& b, const Vec3* x, Mat3& Ke) {
  const Vec3 d = x[b.j] - x[b.i];
  const double l = d.norm(), k = b.EA / b.rest_length;
  const double T = b.prestress + k * (l - b.rest_length);
  if (b.tension_only && T < 0) return false;
  if (l > 0) {
    const Vec3 n = d / l;
    Ke = (k - T / l) * (n * n.transpose()) + (T / l) * Mat3::Identity();
  } else {
    Ke = k * Mat3::Identity();  // coincident ends: no direction; the axial stiffness keeps K regular
  }
  return true;
}

// K of an anchor, plane, line or length goal (goal_force in
// element_forces.hpp: w I, w d d^T / |d|^2, w (I - d d^T / |d|^2), and a
// two-way bar of stiffness w); false when it does not act (a passive
// particle).
bool goal_tangent(const Goal& g, const std::uint8_t* active, const Vec3* x, Mat3& K) {
  if (!active[g.i] || (g.j != kNone && !active[g.j])) return false;
  const double w = g.weight;
  switch (g.kind) {
    case Goal::Anchor: K = w * Mat3::Identity(); return true;
    case Goal::Plane: K = (w / g.direction.squaredNorm()) * (g.direction * g.direction.transpose()); return true;
    case Goal::Line:
      K = w * (Mat3::Identity() - g.direction * g.direction.transpose() / g.direction.squaredNorm());
      return true;
    case Goal::Length: {
      const Vec3 d = x[g.j] - x[g.i];
      const double l = d.norm(), T = w * (l - g.length);
      if (!(l > 0)) {
        K = w * Mat3::Identity();
        return true;
      }
      const Vec3 n = d / l;
      K = (w - T / l) * (n * n.transpose()) + (T / l) * Mat3::Identity();
      return true;
    }
    case Goal::Planar:
    case Goal::Rigid:
    case Goal::Bend: break;  // refused by unsupported()
  }
  return false;
}

// Every element's tangent but the bars': visit(i, j, K), K on ii and jj and
// -K on ij, j = kNone for a term on i alone.
template <class Visit>
void other_tangents(const Model& m, const Vec3* x, Visit&& visit) {
  for (const Goal& g : m.goals) {
    Mat3 K;
    if (goal_tangent(g, m.particles.active.data(), x, K)) visit(g.i, g.kind == Goal::Length ? g.j : kNone, K);
  }
}

// The frame of a particle whose own block K_pp has one clearly softest
// direction (a membrane's normal): that direction as the third axis, the
// global x (or y) projected off it as the first. False: no such direction
// (a cable's line, a node of bars in every direction); the global axes stay.
bool surface_frame(const Mat3& Kpp, Mat3& frame) {
  Eigen::SelfAdjointEigenSolver<Mat3> es;
  es.computeDirect(Kpp);
  const Vec3 lambda = es.eigenvalues();  // ascending
  if (!(lambda[1] > 0) || !(lambda[0] < 0.5 * lambda[1])) return false;
  Vec3 n = es.eigenvectors().col(0);
  const int big = n.cwiseAbs().maxCoeff() == std::abs(n.z()) ? 2 : n.cwiseAbs().maxCoeff() == std::abs(n.y()) ? 1 : 0;
  if (n[big] < 0) n = -n;  // neighbours' normals point the same way
  Vec3 e1 = Vec3::UnitX() - n.x() * n;
  if (e1.norm() < 0.5) e1 = Vec3::UnitY() - n.y() * n;
  e1.normalize();
  frame.col(0) = e1;
  frame.col(1) = n.cross(e1);
  frame.col(2) = n;
  return true;
}

}  // namespace

const char* NewtonSystem::unsupported(const Model& m) {
  if (m.hinges.awake > 0) return "hinges (3-DOF spline beams)";
  if (m.beam6s.awake > 0) return "6-DOF beams";
  if (m.csts.awake > 0) return "CST membranes";
  if (!m.joints.items.empty()) return "rotational joints";
  for (const Goal& g : m.goals) {
    if (g.kind == Goal::Planar) return "planarity goals";
    if (g.kind == Goal::Rigid) return "rigid-body goals";
    if (g.kind == Goal::Bend) return "bending hinges";
  }
  for (Dart d : m.clamp_darts.raw())
    if (m.clamp_acts(d)) return "clamps";
  for (const RigidJoint& j : m.rigid_joints.raw())
    if (m.rigid_acts(j)) return "rigid joints";
  return nullptr;
}

void NewtonSystem::build_pattern(const Model& m) {
  const Particles& P = m.particles;
  const std::array<bool, 3> multigrid{axis_[0].multigrid, axis_[1].multigrid, axis_[2].multigrid};
  capacity_ = P.capacity();
  row_.assign(3 * capacity_, -1);
  rows_ = 0;
  // Axis by axis, by particle id: the order (and so the numbers) does not
  // depend on the order particles joined `integrated`.
  for (int a = 0; a < 3; ++a) {
    offset_[a] = rows_;
    for (ParticleId p = 0; p < capacity_; ++p)
      if (P.active[p] && !(P.lock[p] & (kLockX << a))) row_[3 * p + a] = rows_++;
  }
  offset_[3] = rows_;
  // Then each axis' rows in the fill-reducing order of its block (AMD), so
  // that the factors need no permutation: Eigen's permuted solve spent a
  // quarter of the time at 640K particles permuting vectors.
  for (int a = 0; a < 3; ++a) {
    const int o = offset_[a], n = offset_[a + 1] - o;
    axis_[a].multigrid = n >= multigrid_rows;
    if (n == 0 || axis_[a].multigrid) continue;  // multigrid keeps the particles' order, which keeps neighbours near
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(std::size_t(n) + 2 * m.bars.awake);
    for (int r = 0; r < n; ++r) t.emplace_back(r, r, 1.0);
    for (const Bar* b = m.bars.awake_begin(); b != m.bars.awake_end(); ++b) {
      const int ri = row_[3 * b->i + a], rj = row_[3 * b->j + a];
      if (ri < 0 || rj < 0) continue;
      t.emplace_back(ri - o, rj - o, 1.0);
      t.emplace_back(rj - o, ri - o, 1.0);
    }
    for (const Goal& g : m.goals) {
      if (g.kind != Goal::Length) continue;
      const int ri = row_[3 * g.i + a], rj = row_[3 * g.j + a];
      if (ri < 0 || rj < 0) continue;
      t.emplace_back(ri - o, rj - o, 1.0);
      t.emplace_back(rj - o, ri - o, 1.0);
    }
    Sparse A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
    Eigen::AMDOrdering<int>()(A, inverse);  // position -> old row, as SimplicialLDLT reads it
    std::vector<int> renumber(n);
    for (int k = 0; k < n; ++k) renumber[inverse.indices()[k]] = k;
    for (ParticleId p = 0; p < capacity_; ++p)
      if (int& r = row_[3 * p + a]; r >= 0) r = o + renumber[r - o];
  }
  // K's pattern column by column, from each particle's neighbours (bars
  // and length goals): a column (p, a) holds the rows (q, b) >= its own of
  // p and its neighbours. Built directly: from triplets it took 2.8 s of a
  // 1M-particle solve. The rows of p and its neighbours are sorted once per
  // particle; each of p's columns is the part of them at or below its
  // diagonal. While a column is written, the entries it holds of p's own
  // block and of p's bars are noted, so that assembling is a scatter
  // (binary searches per entry took 11 % of the time on the 128 x 128 net,
  // and finding the slots by search after the pattern a quarter of building
  // it).
  std::vector<int> degree(capacity_ + 1, 0);
  auto each_pair = [&](auto&& visit) {  // bars first, in order (their index), then length goals (-1)
    int e = 0;
    for (const Bar* b = m.bars.awake_begin(); b != m.bars.awake_end(); ++b) visit(b->i, b->j, e++);
    for (const Goal& g : m.goals)
      if (g.kind == Goal::Length) visit(g.i, g.j, -1);
  };
  each_pair([&](ParticleId i, ParticleId j, int) { ++degree[i + 1], ++degree[j + 1]; });
  for (std::size_t p = 0; p < capacity_; ++p) degree[p + 1] += degree[p];
  std::vector<ParticleId> neighbour(static_cast<std::size_t>(degree[capacity_]));
  std::vector<int> via_bar(neighbour.size());  // the bar to that neighbour, or -1 (a length goal)
  {
    std::vector<int> fill(degree.begin(), degree.end() - 1);
    each_pair([&](ParticleId i, ParticleId j, int e) {
      neighbour[fill[i]] = j, via_bar[fill[i]++] = e;
      neighbour[fill[j]] = i, via_bar[fill[j]++] = e;
    });
  }
  std::vector<int> near_begin(capacity_ + 1, 0), near;
  near.reserve(3 * (capacity_ + neighbour.size()));
  for (ParticleId p = 0; p < capacity_; ++p) {
    const std::size_t first = near.size();
    auto rows_of = [&](ParticleId q) {
      for (int b = 0; b < 3; ++b)
        if (const int r = row_[3 * q + b]; r >= 0) near.push_back(r);
    };
    rows_of(p);
    for (int k = degree[p]; k < degree[p + 1]; ++k)
      if (P.active[neighbour[k]]) rows_of(neighbour[k]);
    std::sort(near.begin() + std::ptrdiff_t(first), near.end());
    near.erase(std::unique(near.begin() + std::ptrdiff_t(first), near.end()), near.end());
    near_begin[p + 1] = int(near.size());
  }
  std::vector<int> particle_of(rows_), axis_of(rows_);
  for (ParticleId p = 0; p < capacity_; ++p)
    for (int a = 0; a < 3; ++a)
      if (const int r = row_[3 * p + a]; r >= 0) particle_of[r] = int(p), axis_of[r] = a;
  // The index in kPairs of the unordered axis pair {a, b}.
  constexpr int kPairOf[3][3] = {{0, 3, 4}, {3, 1, 5}, {4, 5, 2}};
  const Bar* bars = m.bars.awake_begin();
  own_slot_.assign(6 * capacity_, -1);
  bar_slot_.assign(9 * m.bars.awake, -1);
  std::vector<int> where(rows_);  // row -> its entry in the column being written
  // Written in place, its size counted first: a fresh buffer costs its
  // first touch of every page, which on the 128 x 128 net took longer than
  // the arithmetic (copying K into K_ 9.7 ms of a 100 ms solve).
  auto column_rows = [&](int c) {
    const ParticleId p = ParticleId(particle_of[c]);
    const int* rows_begin = near.data() + near_begin[p];
    const int* rows_end = near.data() + near_begin[p + 1];
    return std::pair{std::lower_bound(rows_begin, rows_end, c), rows_end};
  };
  Sparse K(rows_, rows_);
  int* outer = K.outerIndexPtr();
  outer[0] = 0;
  for (int c = 0; c < rows_; ++c) {
    const auto [first, last] = column_rows(c);
    outer[c + 1] = outer[c] + int(last - first);
  }
  K.resizeNonZeros(outer[rows_]);
  int* inner = K.innerIndexPtr();
  for (int c = 0; c < rows_; ++c) {
    const ParticleId p = ParticleId(particle_of[c]);
    const int a = axis_of[c];
    const auto [first, last] = column_rows(c);
    for (const int* r = first; r != last; ++r) where[*r] = outer[c] + int(r - first);
    std::copy(first, last, inner + outer[c]);
    for (int b = 0; b < 3; ++b)
      if (const int r = row_[3 * p + b]; r >= c) own_slot_[6 * p + kPairOf[a][b]] = where[r];
    for (int k = degree[p]; k < degree[p + 1]; ++k) {
      const int e = via_bar[k];
      if (e < 0) continue;
      const ParticleId q = neighbour[k];
      const bool p_first = bars[e].i == p;
      for (int b = 0; b < 3; ++b)
        if (const int r = row_[3 * q + b]; r >= c) bar_slot_[9 * std::size_t(e) + (p_first ? 3 * a + b : 3 * b + a)] = where[r];
    }
  }
  // The values are written by assemble().
  const bool same = analysed_ && K.rows() == K_.rows() && K.nonZeros() == K_.nonZeros() &&
                    multigrid == std::array<bool, 3>{axis_[0].multigrid, axis_[1].multigrid, axis_[2].multigrid} &&
                    std::equal(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1, K_.outerIndexPtr()) &&
                    std::equal(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros(), K_.innerIndexPtr());
  K_.swap(K);
  revision_ = m.revision;
  for (Eigen::VectorXd* v : {&b_, &x_, &r_, &z_, &p_, &q_, &t_}) v->resize(rows_);
  if (!same) {
    // Each axis block: in every column of K_ the rows of its own axis come
    // first (rows sorted, axes in order).
    for (int a = 0; a < 3; ++a) {
      Axis& s = axis_[a];
      const int o = offset_[a], n = offset_[a + 1] - o;
      // In place, sizes first (see K_ above); the values are factor_axes'.
      const int* K_outer = K_.outerIndexPtr();
      const int* K_inner = K_.innerIndexPtr();
      auto own_axis_end = [&](int c) {  // the end of column c's rows of axis a
        return int(std::lower_bound(K_inner + K_outer[c], K_inner + K_outer[c + 1], offset_[a + 1]) - K_inner);
      };
      s.A.resize(n, n);
      int* outer = s.A.outerIndexPtr();
      outer[0] = 0;
      for (int c = o; c < offset_[a + 1]; ++c) outer[c - o + 1] = outer[c - o] + own_axis_end(c) - K_outer[c];
      s.A.resizeNonZeros(outer[n]);
      int* inner = s.A.innerIndexPtr();
      for (int c = o; c < offset_[a + 1]; ++c)
        for (int k = K_outer[c], end = own_axis_end(c); k < end; ++k) inner[outer[c - o] + k - K_outer[c]] = K_inner[k] - o;
      if (!s.multigrid) s.ldlt.analyzePattern(s.A);
    }
  }
  // a column of an axis block is the start of K_'s same column, so an
  // entry's place is K_'s less where each column starts.
  axis_slot_.assign(9 * m.bars.awake, -1);
  for (std::size_t e = 0; e < m.bars.awake; ++e) {
    const Bar& b = bars[e];
    for (int a = 0; a < 3; ++a) {
      const int ri = row_[3 * b.i + a], rj = row_[3 * b.j + a];
      auto in_block = [&](int slot, int column) {
        return slot < 0 ? -1
                        : slot - K_.outerIndexPtr()[column] + axis_[a].A.outerIndexPtr()[column - offset_[a]];
      };
      if (ri >= 0) axis_slot_[9 * e + 3 * a] = in_block(own_slot_[6 * std::size_t(b.i) + a], ri);
      if (rj >= 0) axis_slot_[9 * e + 3 * a + 1] = in_block(own_slot_[6 * std::size_t(b.j) + a], rj);
      if (ri >= 0 && rj >= 0) axis_slot_[9 * e + 3 * a + 2] = in_block(bar_slot_[9 * e + 4 * a], std::min(ri, rj));
    }
  }
  if (same) return;
  analysed_ = true;
  factored_ = false;
  ++analyses_;
}

void NewtonSystem::assemble(const Model& m, const Vec3* x, double shift) {
  if (revision_ != m.revision || capacity_ != m.particles.capacity()) build_pattern(m);
  double* v = K_.valuePtr();
  std::fill(v, v + K_.nonZeros(), 0.0);
  auto own = [&](ParticleId p, const Mat3& k) {
    const int* at = &own_slot_[6 * std::size_t(p)];
    for (int n = 0; n < 6; ++n)
      if (at[n] >= 0) v[at[n]] += k(kPairs[n][0], kPairs[n][1]);
  };
  const Bar* bars = m.bars.awake_begin();
  for (std::size_t e = 0; e < m.bars.awake; ++e) {
    const Bar& b = bars[e];
    Mat3 Ke;
    if (!bar_tangent(b, x, Ke)) continue;
    own(b.i, Ke);
    own(b.j, Ke);
    const int* at = &bar_slot_[9 * e];  // -Ke on the pair's block, wherever it falls in the lower triangle
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c)
        if (at[3 * a + c] >= 0) v[at[3 * a + c]] -= Ke(a, c);
  }
  // Goals are few: entry by entry (a binary search each).
  auto add = [&](ParticleId p, ParticleId q, const Mat3& k) {  // k into the lower part of block (p, q)
    for (int a = 0; a < 3; ++a) {
      const int r = row_[3 * p + a];
      if (r < 0) continue;
      for (int b = 0; b < 3; ++b) {
        const int c = row_[3 * q + b];
        if (c >= 0 && c <= r) K_.coeffRef(r, c) += k(a, b);
      }
    }
  };
  other_tangents(m, x, [&](ParticleId i, ParticleId j, const Mat3& k) {
    add(i, i, k);
    if (j == kNone) return;
    add(j, j, k);
    add(j, i, -k);
    add(i, j, -k);
  });
  if (shift > 0)
    for (int c = 0; c < rows_; ++c) K_.coeffRef(c, c) *= 1 + shift;
  if (shift != factored_shift_) factored_ = false;
  factored_shift_ = shift;
  if (!factored_ || last_iterations_ > (axis_[0].multigrid ? kRebuildAfter : kRefactorAfter)) {
    factor_ok_ = factor_axes(m, x, shift);
    last_iterations_ = 0;
  }
}

bool NewtonSystem::factor_axes(const Model& m, const Vec3* x, double shift) {
  ++factorizations_;
  factored_ = false;
  // Frames: from each fully free particle's own block.
  std::vector<Mat3>& own = own_;  // kept: at 1M particles a fresh one cost its page faults
  own.assign(capacity_, Mat3::Zero());
  for (const Bar* bp = m.bars.awake_begin(); bp != m.bars.awake_end(); ++bp) {
    Mat3 Ke;
    if (!bar_tangent(*bp, x, Ke)) continue;
    own[bp->i] += Ke;
    own[bp->j] += Ke;
  }
  other_tangents(m, x, [&](ParticleId i, ParticleId j, const Mat3& k) {
    own[i] += k;
    if (j != kNone) own[j] += k;
  });
  framed_.clear();
  frames_.clear();
  std::vector<int> frame_of(capacity_, -1);
  for (ParticleId p = 0; p < capacity_; ++p) {
    if (row_[3 * p] < 0 || row_[3 * p + 1] < 0 || row_[3 * p + 2] < 0) continue;  // locked axes stay global
    Mat3 f;
    if (!surface_frame(own[p], f)) continue;
    frame_of[p] = int(framed_.size());
    framed_.push_back(p);
    frames_.push_back(f);
  }
  auto axis_dir = [&](ParticleId p, int a) -> Vec3 {
    return frame_of[p] >= 0 ? Vec3(frames_[frame_of[p]].col(a)) : Vec3(Vec3::Unit(a));
  };
  // The axis blocks of R^T K R, R the frames.
  for (Axis& s : axis_)
    std::fill(s.A.valuePtr(), s.A.valuePtr() + s.A.nonZeros(), 0.0);
  auto add = [&](int a, ParticleId p, ParticleId q, double v) {
    int r = row_[3 * p + a], c = row_[3 * q + a];
    if (r < 0 || c < 0) return;
    if (c > r) std::swap(r, c);
    axis_[a].A.coeffRef(r - offset_[a], c - offset_[a]) += v;
  };
  const Bar* bars = m.bars.awake_begin();
  for (std::size_t e = 0; e < m.bars.awake; ++e) {
    const Bar& b = bars[e];
    Mat3 Ke;
    if (!bar_tangent(b, x, Ke)) continue;
    for (int a = 0; a < 3; ++a) {
      const Vec3 ei = axis_dir(b.i, a), ej = axis_dir(b.j, a);
      double* v = axis_[a].A.valuePtr();
      const int* at = &axis_slot_[9 * e + 3 * a];
      if (at[0] >= 0) v[at[0]] += ei.dot(Ke * ei);
      if (at[1] >= 0) v[at[1]] += ej.dot(Ke * ej);
      if (at[2] >= 0) v[at[2]] -= ei.dot(Ke * ej);
    }
  }
  other_tangents(m, x, [&](ParticleId i, ParticleId j, const Mat3& k) {
    for (int a = 0; a < 3; ++a) {
      const Vec3 ei = axis_dir(i, a);
      add(a, i, i, ei.dot(k * ei));
      if (j == kNone) continue;
      const Vec3 ej = axis_dir(j, a);
      add(a, j, j, ej.dot(k * ej));
      add(a, i, j, -ei.dot(k * ej));
    }
  });
  for (int a = 0; a < 3; ++a) {
    Axis& s = axis_[a];
    if (s.A.rows() == 0) continue;
    if (shift > 0)
      for (int c = 0; c < s.A.rows(); ++c) s.A.coeffRef(c, c) *= 1 + shift;
    if (s.multigrid) {
      if (!s.cycle.setup(s.A)) return false;
      continue;
    }
    s.ldlt.factorize(s.A);
    if (s.ldlt.info() != Eigen::Success || !(s.ldlt.vectorD().array() > 0).all()) return false;
  }
  factored_ = true;
  return true;
}

bool NewtonSystem::solve(const Model& m, const Vec3* F, Vec3* dx, double tolerance) {
  const std::size_t n = m.particles.capacity();
  for (std::size_t p = 0; p < n; ++p)
    for (int a = 0; a < 3; ++a)
      if (const int r = row_[3 * p + a]; r >= 0) b_[r] = F[p][a];
  if (!factor_ok_) return false;
  // R (blocks of R^T K R)^-1 R^T in.
  auto precondition = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
    t_ = in;
    auto turn = [&](Eigen::VectorXd& v, bool back) {
      for (std::size_t k = 0; k < framed_.size(); ++k) {
        const ParticleId p = framed_[k];
        const int r0 = row_[3 * p], r1 = row_[3 * p + 1], r2 = row_[3 * p + 2];
        const Vec3 u(v[r0], v[r1], v[r2]);
        const Vec3 w = back ? Vec3(frames_[k] * u) : Vec3(frames_[k].transpose() * u);
        v[r0] = w.x(), v[r1] = w.y(), v[r2] = w.z();
      }
    };
    turn(t_, false);
    for (int a = 0; a < 3; ++a) {
      const int o = offset_[a], len = offset_[a + 1] - o;
      if (len == 0) continue;
      if (axis_[a].multigrid)
        axis_[a].cycle.apply(t_.segment(o, len), out.segment(o, len));
      else
        out.segment(o, len) = axis_[a].ldlt.solve(t_.segment(o, len));
    }
    turn(out, true);
  };
  // Conjugate gradients from dx = 0.
  x_.setZero();
  r_ = b_;
  const double goal = tolerance * b_.norm();
  precondition(r_, z_);
  p_ = z_;
  double rz = r_.dot(z_);
  int it = 0;
  bool positive = true;
  while (r_.norm() > goal && it < kMaxIterations) {
    q_.noalias() = K_.selfadjointView<Eigen::Lower>() * p_;
    const double pq = p_.dot(q_);
    if (!(pq > 0)) {  // a direction of non-positive curvature: K is not positive definite
      positive = false;
      break;
    }
    const double alpha = rz / pq;
    x_ += alpha * p_;
    r_ -= alpha * q_;
    precondition(r_, z_);
    const double rz_next = r_.dot(z_);
    p_ = z_ + (rz_next / rz) * p_;
    rz = rz_next;
    ++it;
  }
  last_iterations_ = it;
  iterations_ += std::uint64_t(it);
  if (!positive && it == 0) return false;
  for (std::size_t p = 0; p < n; ++p)
    for (int a = 0; a < 3; ++a) {
      const int r = row_[3 * p + a];
      dx[p][a] = r >= 0 ? x_[r] : 0.0;
    }
  return true;
}

}  // namespace tendril
