// Projective dynamics: the solver's step (vie.cpp's local step and momentum,
// the prefactored global step of projective.hpp) and the sparse system.
#include "physics/projective.hpp"

#include <algorithm>
#include <string>

#include "physics/element_forces.hpp"
#include "physics/free_axes.hpp"
#include "physics/solver.hpp"

namespace tendril {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Adds w c c^T over the particles ps (coefficients c) to the rows of one
// axis, entry by entry through add(row, column, value).
template <int N, class Add>
void add_term(Add& add, const std::vector<int>& row, const ParticleId (&ps)[N], const double (&c)[N], double w) {
  for (int a = 0; a < N; ++a) {
    const int ra = row[ps[a]];
    if (ra < 0) continue;
    for (int b = 0; b < N; ++b) {
      const int rb = row[ps[b]];
      if (rb >= 0) add(ra, rb, w * c[a] * c[b]);
    }
  }
}

}  // namespace

ProjectiveSystem::Rows ProjectiveSystem::rows_of(const Model& m, int a) {
  const Particles& P = m.particles;
  Rows r;
  r.row.assign(P.capacity(), -1);
  r.left.assign(P.capacity(), -1);
  for (ParticleId p : P.integrated.raw())
    if (!(P.lock[p] & (kLockX << a))) r.row[p] = r.count++;
  return r;
}

ProjectiveSystem::Rows ProjectiveSystem::followed(const Model& m, const Axis& s, int a) {
  const Particles& P = m.particles;
  const std::size_t n = P.capacity();
  Rows r = s.rows;
  r.row.resize(n, -1);
  r.left.resize(n, -1);
  std::vector<char> here(n, 0);
  for (ParticleId p : P.integrated.raw())
    if (!(P.lock[p] & (kLockX << a))) here[p] = 1;
  // Departures first, so that a particle in a slot freed by this very change
  // finds the row to take. A row left keeps the diagonal it has in the
  // matrix the correction starts from, so that only its couplings change.
  const Eigen::Index n0 = s.A.rows();
  for (std::size_t p = 0; p < n; ++p) {
    const int q = r.row[p];
    if (q < 0 || here[p]) continue;
    r.left[p] = q;
    r.row[p] = -1;
    r.vacant.emplace_back(q, q < n0 ? s.A.coeff(q, q) : s.grown[q - n0]);
  }
  for (ParticleId p : P.integrated.raw()) {  // arrivals, in `integrated` order
    if (!here[p] || r.row[p] >= 0) continue;
    if (const int q = r.left[p]; q >= 0) {
      r.row[p] = q;
      r.left[p] = -1;
      r.vacant.erase(std::find_if(r.vacant.begin(), r.vacant.end(), [&](const auto& v) { return v.first == q; }));
    } else {
      r.row[p] = r.count++;
    }
  }
  return r;
}

template <class Add>
void ProjectiveSystem::terms(const Model& m, const Rows& rows, const Vec3* x, double inv_dt2,
                             const std::vector<double>& diagonal, Add&& t) const {
  const Particles& P = m.particles;
  const std::vector<int>& row = rows.row;
  const double gf = key_.geometric_factor;
  for (ParticleId p : P.integrated.raw())
    if (row[p] >= 0) t(row[p], row[p], mass_[p] * inv_dt2 + diagonal[p]);
  for (const auto& [r, d] : rows.vacant) t(r, r, d);
  for (const Bar* bp = m.bars.awake_begin(); bp != m.bars.awake_end(); ++bp) {  // dormant ones never act
    const Bar& b = *bp;
    const double l = (x[b.j] - x[b.i]).norm(), k = b.EA / b.rest_length;
    const double T = b.prestress + k * (l - b.rest_length);
    add_term<2>(t, row, {b.i, b.j}, {-1, 1}, k + (l > 0 && T > 0 ? gf * T / l : 0.0));
  }
  for (const Hinge* hp = m.hinges.awake_begin(); hp != m.hinges.awake_end(); ++hp) {
    const Hinge& h = *hp;
    const double l = 0.5 * ((x[h.j] - x[h.i]).norm() + (x[h.k] - x[h.j]).norm());
    add_term<3>(t, row, {h.i, h.j, h.k}, {1, -2, 1}, h.EI / (l * l * l));
  }
  for (const Beam6* bp = m.beam6s.awake_begin(); bp != m.beam6s.awake_end(); ++bp) {
    const Beam6& b = *bp;
    const double L = b.rest_length;
    const double w = std::max(b.EA / L, 12 * std::max(b.EIy, b.EIz) / (L * L * L));
    add_term<2>(t, row, {b.i, b.j}, {-1, 1}, w);
  }
  for (const Goal& g : m.goals) {
    if (g.kind == Goal::Length) {
      add_term<2>(t, row, {g.i, g.j}, {-1, 1}, g.weight);
    } else if (g.kind == Goal::Rigid) {  // w (I - 1 1^T / n): the members about their centroid
      const double n = double(g.members.size());
      for (ParticleId a : g.members) {
        if (row[a] < 0) continue;
        for (ParticleId b : g.members)
          if (row[b] >= 0) t(row[a], row[b], g.weight * ((a == b ? 1.0 : 0.0) - 1 / n));
      }
    } else if (g.kind == Goal::Bend) {  // w K K^T: the hinge's energy, quadratic
      add_term<4>(t, row, {g.i, g.j, g.k, g.l}, {g.hinge[0], g.hinge[1], g.hinge[2], g.hinge[3]},
                  g.weight / g.hinge_area);
    } else if (g.kind == Goal::Planar) {  // w (I - 1 1^T / 4): the corners about their centroid
      const ParticleId c[4] = {g.i, g.j, g.k, g.l};
      for (int a = 0; a < 4; ++a) {
        double coef[4] = {-0.25, -0.25, -0.25, -0.25};
        coef[a] += 1;
        add_term<4>(t, row, {c[0], c[1], c[2], c[3]}, coef, g.weight);
      }
    } else {
      add_term<1>(t, row, {g.i}, {1}, g.weight);
    }
  }
  for (const RotationalJoint& jt : m.joints.items) {
    ParticleId nb[4];
    if (!m.joint_neighbours(jt.particle, nb)) continue;
    for (ParticleId q : nb) add_term<2>(t, row, {jt.particle, q}, {-1, 1}, jt.stiffness);
  }
}

Eigen::SparseMatrix<double> ProjectiveSystem::assemble(const Model& m, const Rows& rows, const Vec3* x,
                                                       double inv_dt2, const std::vector<double>& diagonal) const {
  Triplets t;
  t.reserve(m.particles.integrated.size() + 4 * m.bars.size() + 9 * m.hinges.size() + 4 * m.beam6s.size());
  terms(m, rows, x, inv_dt2, diagonal, [&](int r, int c, double v) { t.emplace_back(r, c, v); });
  Eigen::SparseMatrix<double> A(rows.count, rows.count);
  A.setFromTriplets(t.begin(), t.end());  // duplicates summed in the order of terms()
  return A;
}

void ProjectiveSystem::factor_axis(Axis& s, int a) {
  s.factor.compute(s.A);
  if (s.factor.info() != Eigen::Success || (s.factor.vectorD().array() <= 0).any())
    throw NumericalError("projective: the global matrix of axis " + std::string(1, char('x' + a)) +
                         " is not positive definite (a free particle without mass or stiffness?)");
  s.change.clear(s.factor);
  s.changed.clear();
  s.grown.resize(0);
  s.reach = forward_reach(s.factor);
  s.entries = std::size_t(s.factor.matrixL().nestedExpression().nonZeros() + s.A.rows());  // L's unit diagonal apart
  s.b.resize(s.A.rows(), s.b.cols());
}

void ProjectiveSystem::factor(const Key& key, std::uint64_t revision, const Model& m, const Vec3* x,
                              const std::vector<double>& mass, double inv_dt2, const std::vector<double>& diagonal) {
  factored_ = false;
  key_ = key;
  const std::size_t n = m.particles.capacity();
  reference_.assign(x, x + n);
  mass_.assign(mass.begin(), mass.end());
  known_.assign(n, 0);
  for (ParticleId p : m.particles.integrated.raw()) known_[p] = 1;
  for (int a = 0; a < 3; ++a) {
    Rows rows = rows_of(m, a);
    int same = -1;
    for (int b = 0; b < a && same < 0; ++b)
      if (axis_[b]->rows == rows) same = b;
    if (same >= 0) {
      axis_[a] = axis_[same];
      continue;
    }
    auto s = std::make_shared<Axis>();
    s->rows = std::move(rows);
    s->A = assemble(m, s->rows, x, inv_dt2, diagonal);
    factor_axis(*s, a);
    axis_[a] = s;
  }
  revision_ = revision;
  factored_ = true;
  ++factorizations_;
}

bool ProjectiveSystem::update(const Key& key, std::uint64_t revision, const Model& m, const Vec3* x,
                              const std::vector<double>& mass, bool follow_mass, double inv_dt2,
                              const std::vector<double>& diagonal) {
  const std::size_t n = m.particles.capacity(), had = reference_.size();
  if (!factored_ || !(key_ == key) || n < had) return false;
  // Every row stays where it was (projective.hpp); axes that shared a
  // system must still share it, the factor being one (axes apart may stay
  // apart with equal rows).
  std::array<Rows, 3> row;
  for (int a = 0; a < 3; ++a) {
    row[a] = followed(m, *axis_[a], a);
    for (int b = 0; b < a; ++b)
      if (axis_[b] == axis_[a] && !(row[b] == row[a])) return false;
  }
  factored_ = false;  // until every axis follows
  // New particles: their reference is where they are, their mass this step's;
  // one that left is new when it comes back (or another takes its slot).
  reference_.insert(reference_.end(), x + had, x + n);
  mass_.resize(n, 0.0);
  known_.resize(n, 0);
  for (std::size_t p = 0; p < had; ++p)
    if (!m.particles.active[p]) known_[p] = 0;
  for (ParticleId p : m.particles.integrated.raw())
    if (follow_mass || !known_[p]) {
      mass_[p] = mass[p];
      if (!known_[p]) reference_[p] = x[p];  // a slot reused since: not its old particle's place
      known_[p] = 1;
    }
  for (int a = 0; a < 3; ++a) {
    if (shared_before(a)) continue;  // done with that axis
    Axis& s = *axis_[a];
    s.rows = std::move(row[a]);
    // The new matrix minus the base (the old one, and the diagonal of rows
    // added since), D: the terms again at the same positions, summed into
    // the old pattern in the order assemble() sums them, so that an
    // unchanged entry repeats bit for bit; entries outside it (a new cable,
    // a new row) apart. Cheaper than assembling and subtracting (no sort).
    const Eigen::SparseMatrix<double>& A0 = s.A;
    const int n0 = int(A0.rows()), rows = s.rows.count, grown = int(s.grown.size());
    const int* outer = A0.outerIndexPtr();
    const int* inner = A0.innerIndexPtr();
    std::vector<double> d(std::size_t(A0.nonZeros()), 0.0), new_diagonal(std::size_t(rows - n0), 0.0);
    Triplets extra;
    terms(m, s.rows, reference_.data(), inv_dt2, diagonal, [&](int r, int c, double v) {
      if (r >= n0 || c >= n0) {
        if (r == c) new_diagonal[std::size_t(r - n0)] += v;
        else extra.emplace_back(r, c, v);
        return;
      }
      const int *begin = inner + outer[c], *end = inner + outer[c + 1], *at = std::lower_bound(begin, end, r);
      if (at != end && *at == r) d[std::size_t(at - inner)] += v;
      else extra.emplace_back(r, c, v);
    });
    const double* old = A0.valuePtr();
    for (std::size_t i = 0; i < d.size(); ++i) d[i] -= old[i];
    // Rows new in this update enter the base with their diagonal (so that
    // it stays positive definite); every row added since is a changed one.
    s.grown.conservativeResize(rows - n0);
    for (int r = grown; r < rows - n0; ++r) s.grown[r] = new_diagonal[std::size_t(r)];
    for (int r = 0; r < rows - n0; ++r) new_diagonal[std::size_t(r)] -= s.grown[r];
    // Changed rows: the threshold only forgives a sum taken in another order
    // (elements moved in their arrays).
    Eigen::VectorXd scale(rows);
    scale << A0.diagonal().cwiseAbs(), s.grown.cwiseAbs();
    auto significant = [&](int r, int c, double v) { return std::abs(v) > 1e-13 * std::sqrt(scale[r] * scale[c]); };
    std::vector<char> in(std::size_t(rows), 0), fresh(std::size_t(rows), 0);
    for (int r : s.changed) in[std::size_t(r)] = 1;
    for (int c = 0; c < n0; ++c)
      for (int i = outer[c]; i < outer[c + 1]; ++i)
        if (significant(inner[i], c, d[std::size_t(i)])) fresh[std::size_t(inner[i])] = fresh[std::size_t(c)] = 1;
    for (const auto& e : extra)
      if (significant(e.row(), e.col(), e.value())) fresh[std::size_t(e.row())] = fresh[std::size_t(e.col())] = 1;
    for (int r = n0; r < rows; ++r) fresh[std::size_t(r)] = 1;
    for (std::size_t r = 0; r < fresh.size(); ++r)
      if (fresh[r] && !in[r]) s.changed.push_back(int(r));
    if (outgrown(s)) return false;
    s.b.conservativeResize(rows, s.b.cols());
    if (low_rank) {
      const Eigen::Index k = Eigen::Index(s.changed.size());
      Eigen::MatrixXd C = Eigen::MatrixXd::Zero(k, k);
      std::vector<int> place(std::size_t(rows), -1);
      for (Eigen::Index i = 0; i < k; ++i) place[std::size_t(s.changed[std::size_t(i)])] = int(i);
      for (int r : s.changed) {
        if (r >= n0) {
          C(place[std::size_t(r)], place[std::size_t(r)]) = new_diagonal[std::size_t(r - n0)];
          continue;
        }
        for (int i = outer[r]; i < outer[r + 1]; ++i)  // symmetric: column r is row r
          if (place[std::size_t(inner[i])] >= 0) C(place[std::size_t(inner[i])], place[std::size_t(r)]) = d[std::size_t(i)];
      }
      for (const auto& e : extra)
        if (place[std::size_t(e.row())] >= 0 && place[std::size_t(e.col())] >= 0)
          C(place[std::size_t(e.row())], place[std::size_t(e.col())]) += e.value();
      if (!s.change.set(s.factor, s.grown, s.changed, C)) return false;
    } else {
      std::vector<int> changed = std::move(s.changed), reach = std::move(s.reach);
      const std::size_t entries = s.entries;
      s.A = assemble(m, s.rows, reference_.data(), inv_dt2, diagonal);
      factor_axis(s, a);
      // outgrown() counts from the last factor() in both ways
      s.changed = std::move(changed), s.reach = std::move(reach), s.entries = entries;
    }
  }
  revision_ = revision;
  factored_ = true;
  ++updates_;
  factorizations_ += !low_rank;  // every update factored afresh: counted as what it is
  return true;
}

// A solve reads L twice (forward, backward) and the correction each changed
// row's column of G twice (y_T, then f - G w) and C and (I + S C)^-1 once:
// once the correction outweighs L a factorisation pays, and beyond 256 rows
// setting it (k^3) does too. The first 16 rows are always followed, so that
// small models refactor rarely too. A membrane, whose matrix is almost
// diagonal, follows far more rows than a net, whose columns of G are long.
bool ProjectiveSystem::outgrown(const Axis& s) {
  const std::size_t k = s.changed.size();
  if (k <= 16) return false;
  if (k > 256) return true;
  std::size_t read = k * k;
  for (int r : s.changed) read += r < int(s.reach.size()) ? std::size_t(s.reach[std::size_t(r)]) : 1;
  return read > s.entries;
}

bool ProjectiveSystem::shared_before(int a) const {
  for (int b = 0; b < a; ++b)
    if (axis_[b] == axis_[a]) return true;
  return false;
}

// The axes that share a system (equal rows) are solved together, a column
// each: one pass over the factor for x, y and z of a net without locks.
void ProjectiveSystem::solve(const Model& m, Vec3* rhs) {
  const std::vector<ParticleId>& integrated = m.particles.integrated.raw();
  for (int a = 0; a < 3; ++a) {
    if (shared_before(a)) continue;  // solved with that axis
    Axis& s = *axis_[a];
    int axes[3], count = 0;
    for (int b = a; b < 3; ++b)
      if (axis_[b] == axis_[a]) axes[count++] = b;
    if (s.b.cols() != count) s.b = Eigen::MatrixXd::Zero(s.b.rows(), count);
    const std::vector<int>& row = s.rows.row;
    for (ParticleId p : integrated)
      if (row[p] >= 0)
        for (int c = 0; c < count; ++c) s.b(row[p], c) = rhs[p][axes[c]];
    for (const auto& v : s.rows.vacant) s.b.row(v.first).setZero();  // decoupled: stays zero
    s.change.solve(s.factor, s.grown, s.b, s.scratch);
    for (ParticleId p : integrated)
      for (int c = 0; c < count; ++c) rhs[p][axes[c]] = row[p] >= 0 ? s.b(row[p], c) : 0.0;
  }
}

std::uint64_t Solver::factorizations() const { return projective_ ? projective_->factorizations() : 0; }
std::uint64_t Solver::projective_updates() const { return projective_ ? projective_->updates() : 0; }

void Solver::integrate_projective() {
  const double dt = vie_dt(), inv_dt2 = 1 / (dt * dt);
  const Particles& P = model_.particles;
  const std::size_t n = P.capacity();
  const std::vector<ParticleId>& integrated = P.integrated.raw();
  if (!projective_) projective_ = std::make_shared<ProjectiveSystem>();
  projective_->low_rank = projective_low_rank_;
  const ProjectiveSystem::Key key{&model_, settings.dt, dt, settings.mass_factor, settings.geometric_factor,
                                  int(settings.mass_mode)};
  if (!projective_->current(key, model_.revision, n)) {
    std::vector<double> diagonal(n, 0.0);
    auto cst_diagonal = [&](const Vec3* x) {
      if (model_.csts.items.empty()) return;
      cst_weight_.assign(n, 0.0);
      accumulate_cst_forces(x, vs_.data(), cst_weight_.data());
      for (std::size_t p = 0; p < n; ++p) diagonal[p] = 2 * cst_weight_[p];
    };
    // Fictitious masses are eq. 3.4's at the factorisation and stay with it;
    // physical ones are the model's and followed.
    const bool physical = settings.mass_mode == MassMode::Physical;
    bool followed = false;
    if (projective_->reference().size() <= n) {
      // CST at the reference positions (new particles' are their own: the
      // reference grows first, so that the update sees what it assembles).
      std::vector<Vec3> reference(P.position.begin(), P.position.end());
      const std::vector<Vec3>& old = projective_->reference();
      for (std::size_t p = 0; p < old.size(); ++p)
        if (projective_->known(ParticleId(p))) reference[p] = old[p];
      cst_diagonal(reference.data());
      followed = projective_->update(key, model_.revision, model_, P.position.data(), mass_, physical, inv_dt2,
                                     diagonal);
    }
    if (!followed) {
      std::fill(diagonal.begin(), diagonal.end(), 0.0);
      cst_diagonal(P.position.data());
      projective_->factor(key, model_.revision, model_, P.position.data(), mass_, inv_dt2, diagonal);
    }
  }
  const std::vector<double>& frozen = projective_->mass();
  for (ParticleId p : integrated) mass_[p] = frozen[p];
  start_implicit_step(dt);
  const std::uint8_t* lock = P.lock.data();
  // vie_iterations = 0: one iteration in form-finding; in dynamics until the
  // last correction is below kAdaptiveTolerance of how far the step moved
  // (translations; the largest component of each), at most
  // kAdaptiveIterations (solver.hpp says why).
  const bool adaptive = settings.vie_iterations == 0, dynamics = settings.mass_mode == MassMode::Physical;
  const int iterations = !adaptive ? settings.vie_iterations : dynamics ? kAdaptiveIterations : 1;
  for (int it = 0; it < iterations; ++it) {
    local_step(xs_.data(), qs_.data());
    for (ParticleId p : integrated) vs_[p] = mass_[p] * inv_dt2 * (x0_[p] - xs_[p]) + Fs_[p];
    projective_->solve(model_, vs_.data());  // the global step
    for (ParticleId p : integrated) xs_[p] += vs_[p].cwiseProduct(free_axes(lock[p]));
    rotation_global_step(inv_dt2);
    if (!adaptive || !dynamics) continue;  // the two passes below only where the count adapts
    double correction = 0, moved = 0;
    for (ParticleId p : integrated) {
      correction = std::max(correction, vs_[p].cwiseProduct(free_axes(lock[p])).cwiseAbs().maxCoeff());
      moved = std::max(moved, (xs_[p] - P.position[p]).cwiseAbs().maxCoeff());
    }
    if (correction <= kAdaptiveTolerance * moved) break;
  }
  finish_implicit_step(dt);
}

}  // namespace tendril
