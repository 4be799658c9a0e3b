#pragma once
// The global step of projective dynamics (Bouaziz et al. 2014), an
// alternative to the per-particle average of eq. 3.63:
//   (M/dt^2 + sum_k w_k A_k^T A_k) x = M/dt^2 x0 + sum_k w_k A_k^T p_k.
// The local step's projections balance to the element forces
// (projections.hpp), so with L = sum w_k A_k^T A_k the right-hand side is
// M/dt^2 x0 + L x + F(x), and the step solves for the increment
//   (M/dt^2 + L) dx = M/dt^2 (x0 - x) + F(x)
// over the free coordinates (locked axes and inactive particles stay). L is
// constant between topology changes and is factored once (sparse LDL^T):
//   bars, cables    w = EA/L + g T/l on the edge (A: x_j - x_i), T the
//                   tension at factorisation;
//   3-DOF hinges    w = EI / l^3 on the second difference x_i - 2 x_j + x_k,
//                   the bending stiffness of eq. 3.41 for small angles;
//   6-DOF beams     w = max(EA/L, 12 EI/L^3) on the edge; rotation keeps the
//                   per-particle average of eq. 3.63 (vie.cpp);
//   joints          w = the joint stiffness on each neighbour's edge;
//   CST membranes   twice each corner's eq. 3.40 stiffness on its diagonal;
//   goals           the weight on the particle's diagonal (anchor, plane,
//                   line) or on the edge (length).
// A fixed point is an equilibrium whatever the weights: they only decide how
// fast the iterations get there.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <vector>

#include "model/model.hpp"

namespace tendril {

class ProjectiveSystem {
 public:
  // What the factorisation depends on besides the model's revision.
  struct Key {
    const Model* model = nullptr;
    std::uint64_t revision = 0;
    std::size_t capacity = 0;
    double dt = 0, step_dt = 0, mass_factor = 0, geometric_factor = 0;
    int mass_mode = 0;
    bool operator==(const Key&) const = default;
  };
  bool current(const Key& k) const { return factored_ && key_ == k; }
  // Assembles and factors M/dt^2 + L at positions x. `inertia` is M/dt^2
  // per particle, `diagonal` extra per-particle weights (CST). Throws
  // NumericalError when the matrix is not positive definite.
  void factor(const Key& key, const Model& m, const Vec3* x, const std::vector<double>& inertia,
              const std::vector<double>& diagonal);
  // dx for the free coordinates of every particle: rhs -> increments, in place.
  void solve(const Model& m, Vec3* rhs);
  std::uint64_t factorizations() const { return factorizations_; }

 private:
  using Factor = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>;
  Key key_;
  bool factored_ = false;
  std::uint64_t factorizations_ = 0;
  std::array<std::vector<int>, 3> row_;            // per axis: particle -> row, or -1 (fixed)
  std::array<std::shared_ptr<Factor>, 3> factor_;  // axes with equal rows share one
  std::array<Eigen::VectorXd, 3> b_;
};

}  // namespace tendril
