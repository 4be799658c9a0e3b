// The static Newton solver's tangent and its solve (newton.hpp).
#include "physics/newton.hpp"

#include <algorithm>
#include <cmath>

namespace tendril {

namespace {

// An iteration that took more conjugate-gradient iterations than this
// makes the next one factor the axis blocks again at its positions.
constexpr int kRefactorAfter = 20;
constexpr int kMaxIterations = 1000;

}  // namespace

const char* NewtonSystem::unsupported(const Model& m) {
  if (m.hinges.awake > 0) return "hinges (3-DOF spline beams)";
  if (m.beam6s.awake > 0) return "6-DOF beams";
  if (m.csts.awake > 0) return "CST membranes";
  if (!m.joints.items.empty()) return "rotational joints";
  if (!m.goals.empty()) return "goals";
  for (Dart d : m.clamp_darts.raw())
    if (m.clamp_acts(d)) return "clamps";
  for (const RigidJoint& j : m.rigid_joints.raw())
    if (m.rigid_acts(j)) return "rigid joints";
  return nullptr;
}

void NewtonSystem::build_pattern(const Model& m) {
  const Particles& P = m.particles;
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
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(std::size_t(rows_) * 2 + 9 * m.bars.awake);
  auto block = [&](ParticleId p, ParticleId q) {  // the lower part of block (p, q)
    for (int a = 0; a < 3; ++a) {
      const int r = row_[3 * p + a];
      if (r < 0) continue;
      for (int b = 0; b < 3; ++b) {
        const int c = row_[3 * q + b];
        if (c >= 0 && c <= r) t.emplace_back(r, c, 0.0);
      }
    }
  };
  for (ParticleId p = 0; p < capacity_; ++p)
    if (P.active[p]) block(p, p);
  for (const Bar* b = m.bars.awake_begin(); b != m.bars.awake_end(); ++b) {
    block(b->i, b->j);
    block(b->j, b->i);
  }
  Sparse K(rows_, rows_);
  K.setFromTriplets(t.begin(), t.end());
  K.makeCompressed();
  const bool same = analysed_ && K.rows() == K_.rows() && K.nonZeros() == K_.nonZeros() &&
                    std::equal(K.outerIndexPtr(), K.outerIndexPtr() + K.outerSize() + 1, K_.outerIndexPtr()) &&
                    std::equal(K.innerIndexPtr(), K.innerIndexPtr() + K.nonZeros(), K_.innerIndexPtr());
  K_ = std::move(K);
  revision_ = m.revision;
  for (Eigen::VectorXd* v : {&b_, &x_, &r_, &z_, &p_, &q_}) v->resize(rows_);
  if (same) return;
  // Each axis block: in every column of K_ the rows of its own axis come
  // first (rows sorted, axes in order), so its entries are a prefix.
  for (int a = 0; a < 3; ++a) {
    Axis& s = axis_[a];
    const int n = offset_[a + 1] - offset_[a];
    s.prefix.assign(n, 0);
    std::vector<Eigen::Triplet<double>> ta;
    for (int c = offset_[a]; c < offset_[a + 1]; ++c)
      for (Sparse::InnerIterator it(K_, c); it && it.row() < offset_[a + 1]; ++it) {
        ta.emplace_back(int(it.row()) - offset_[a], c - offset_[a], 0.0);
        ++s.prefix[c - offset_[a]];
      }
    s.A.resize(n, n);
    s.A.setFromTriplets(ta.begin(), ta.end());
    s.A.makeCompressed();
    s.ldlt.analyzePattern(s.A);
  }
  analysed_ = true;
  factored_ = false;
  ++analyses_;
}

void NewtonSystem::assemble(const Model& m, const Vec3* x, double shift) {
  if (revision_ != m.revision || capacity_ != m.particles.capacity()) build_pattern(m);
  std::fill(K_.valuePtr(), K_.valuePtr() + K_.nonZeros(), 0.0);
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
  for (const Bar* bp = m.bars.awake_begin(); bp != m.bars.awake_end(); ++bp) {
    const Bar& b = *bp;
    const Vec3 d = x[b.j] - x[b.i];
    const double l = d.norm(), k = b.EA / b.rest_length;
    const double T = b.prestress + k * (l - b.rest_length);
    if (b.tension_only && T < 0) continue;  // slack: no force, no stiffness
    Mat3 Ke;
    if (l > 0) {
      const Vec3 n = d / l;
      Ke = (k - T / l) * (n * n.transpose()) + (T / l) * Mat3::Identity();
    } else {
      Ke = k * Mat3::Identity();  // coincident ends: no direction; the axial stiffness keeps K regular
    }
    add(b.i, b.i, Ke);
    add(b.j, b.j, Ke);
    add(b.j, b.i, -Ke);  // ij and ji: the lower triangle holds whichever has the larger row
    add(b.i, b.j, -Ke);
  }
  if (shift > 0)
    for (int c = 0; c < rows_; ++c) K_.coeffRef(c, c) *= 1 + shift;
  if (shift != factored_shift_) factored_ = false;
  factored_shift_ = shift;
}

bool NewtonSystem::factor_axes() {
  ++factorizations_;
  factored_ = true;
  for (int a = 0; a < 3; ++a) {
    Axis& s = axis_[a];
    if (s.A.rows() == 0) continue;
    double* v = s.A.valuePtr();
    for (int c = offset_[a]; c < offset_[a + 1]; ++c) {
      const double* from = K_.valuePtr() + K_.outerIndexPtr()[c];
      v = std::copy(from, from + s.prefix[c - offset_[a]], v);
    }
    s.ldlt.factorize(s.A);
    if (s.ldlt.info() != Eigen::Success || !(s.ldlt.vectorD().array() > 0).all()) {
      factored_ = false;
      return false;
    }
  }
  return true;
}

bool NewtonSystem::solve(const Model& m, const Vec3* F, Vec3* dx, double tolerance) {
  const std::size_t n = m.particles.capacity();
  for (std::size_t p = 0; p < n; ++p)
    for (int a = 0; a < 3; ++a)
      if (const int r = row_[3 * p + a]; r >= 0) b_[r] = F[p][a];
  if (!factored_ || last_iterations_ > kRefactorAfter) {
    if (!factor_axes()) return false;
  }
  auto precondition = [&](const Eigen::VectorXd& in, Eigen::VectorXd& out) {
    for (int a = 0; a < 3; ++a) {
      const int o = offset_[a], len = offset_[a + 1] - o;
      if (len > 0) out.segment(o, len) = axis_[a].ldlt.solve(in.segment(o, len));
    }
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
