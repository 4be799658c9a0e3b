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

// Adds w c c^T over the particles ps (coefficients c) to the rows of one axis.
template <int N>
void add_term(Triplets& t, const std::vector<int>& row, const ParticleId (&ps)[N], const double (&c)[N], double w) {
  for (int a = 0; a < N; ++a) {
    const int ra = row[ps[a]];
    if (ra < 0) continue;
    for (int b = 0; b < N; ++b) {
      const int rb = row[ps[b]];
      if (rb >= 0) t.emplace_back(ra, rb, w * c[a] * c[b]);
    }
  }
}

}  // namespace

void ProjectiveSystem::factor(const Key& key, const Model& m, const Vec3* x, const std::vector<double>& inertia,
                              const std::vector<double>& diagonal) {
  factored_ = false;
  const Particles& P = m.particles;
  const std::size_t n = P.capacity();
  std::array<int, 3> rows{};
  for (int a = 0; a < 3; ++a) {
    row_[a].assign(n, -1);
    for (ParticleId p : P.integrated.raw())
      if (!(P.lock[p] & (kLockX << a))) row_[a][p] = rows[a]++;
  }
  const double gf = key.geometric_factor;
  for (int a = 0; a < 3; ++a) {
    int same = -1;
    for (int b = 0; b < a && same < 0; ++b)
      if (row_[b] == row_[a]) same = b;
    if (same >= 0) {
      factor_[a] = factor_[same];
      continue;
    }
    const std::vector<int>& row = row_[a];
    Triplets t;
    for (ParticleId p : P.integrated.raw())
      if (row[p] >= 0) t.emplace_back(row[p], row[p], inertia[p] + diagonal[p]);
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
    Eigen::SparseMatrix<double> A(rows[a], rows[a]);
    A.setFromTriplets(t.begin(), t.end());
    auto f = std::make_shared<Factor>(A);
    if (f->info() != Eigen::Success || (f->vectorD().array() <= 0).any())
      throw NumericalError("projective: the global matrix of axis " + std::string(1, char('x' + a)) +
                           " is not positive definite (a free particle without mass or stiffness?)");
    factor_[a] = f;
  }
  for (int a = 0; a < 3; ++a) b_[a].resize(rows[a]);
  key_ = key;
  factored_ = true;
  ++factorizations_;
}

void ProjectiveSystem::solve(const Model& m, Vec3* rhs) {
  const std::vector<ParticleId>& integrated = m.particles.integrated.raw();
  for (int a = 0; a < 3; ++a) {
    const std::vector<int>& row = row_[a];
    for (ParticleId p : integrated)
      if (row[p] >= 0) b_[a][row[p]] = rhs[p][a];
    if (b_[a].size() != 0) b_[a] = factor_[a]->solve(b_[a]);
    for (ParticleId p : integrated) rhs[p][a] = row[p] >= 0 ? b_[a][row[p]] : 0.0;
  }
}

std::uint64_t Solver::factorizations() const { return projective_ ? projective_->factorizations() : 0; }

void Solver::integrate_projective() {
  const double dt = vie_dt(), inv_dt2 = 1 / (dt * dt);
  const Particles& P = model_.particles;
  const std::size_t n = P.capacity();
  const std::vector<ParticleId>& integrated = P.integrated.raw();
  if (!projective_) projective_ = std::make_shared<ProjectiveSystem>();
  const ProjectiveSystem::Key key{&model_,         model_.revision, n, settings.dt, dt, settings.mass_factor,
                                  settings.geometric_factor, int(settings.mass_mode)};
  if (!projective_->current(key)) {
    // Fictitious masses are eq. 3.4's at the factorisation and stay with it.
    projective_mass_.assign(mass_.begin(), mass_.end());
    std::vector<double> inertia(n, 0.0), diagonal(n, 0.0);
    for (ParticleId p : integrated) inertia[p] = projective_mass_[p] * inv_dt2;
    if (!model_.csts.items.empty()) {
      cst_weight_.assign(n, 0.0);
      accumulate_cst_forces(P.position.data(), vs_.data(), cst_weight_.data());
      for (std::size_t p = 0; p < n; ++p) diagonal[p] = 2 * cst_weight_[p];
    }
    projective_->factor(key, model_, P.position.data(), inertia, diagonal);
  }
  for (ParticleId p : integrated) mass_[p] = projective_mass_[p];
  start_implicit_step(dt);
  const std::uint8_t* lock = P.lock.data();
  for (int it = 0; it < settings.vie_iterations; ++it) {
    local_step(xs_.data(), qs_.data());
    for (ParticleId p : integrated) vs_[p] = mass_[p] * inv_dt2 * (x0_[p] - xs_[p]) + Fs_[p];
    projective_->solve(model_, vs_.data());  // the global step
    for (ParticleId p : integrated) xs_[p] += vs_[p].cwiseProduct(free_axes(lock[p]));
    rotation_global_step(inv_dt2);
  }
  finish_implicit_step(dt);
}

}  // namespace tendril
