#pragma once
// The global step of projective dynamics (Bouaziz et al. 2014), an
// alternative to the per-particle average of eq. 3.63:
//   (M/dt^2 + sum_k w_k A_k^T A_k) x = M/dt^2 x0 + sum_k w_k A_k^T p_k.
// The local step's projections balance to the element forces
// (projections.hpp), so with L = sum w_k A_k^T A_k the right-hand side is
// M/dt^2 x0 + L x + F(x), and the step solves for the increment
//   (M/dt^2 + L) dx = M/dt^2 (x0 - x) + F(x)
// over the free coordinates (locked axes and inactive particles stay). The
// weights are taken at the positions of a full factorisation (sparse LDL^T)
// and stay with it:
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
// A topology or parameter change (the model's revision moves) is followed
// locally while every particle's row stays: the matrix is assembled again
// at the same reference positions, so only the changed elements' rows
// differ, and the old factor solves the new matrix exactly through a
// low-rank correction (low_rank_solve.hpp) - a new cable costs two solves,
// not a factorisation. New particles' rows come after the others and join
// the correction. A particle that leaves an axis (made passive, deleted,
// locked) keeps its row there, decoupled: its diagonal alone, its right
// side zero; it takes the row again if it comes back, and a new particle in
// its slot takes it too. Fictitious masses stay those of the factorisation
// (a new or returning particle's its first); physical ones are followed. A
// full factorisation at the current positions comes when dt or the mass
// mode changes, a lock splits axes that shared a system, or the changed
// rows since the last one (more than 16) would cost more per solve than
// the triangular solves themselves (projective.cpp, factor_axis).
// A fixed point is an equilibrium whatever the weights: they only decide how
// fast the iterations get there.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "model/model.hpp"
#include "physics/ldlt_columns.hpp"
#include "physics/low_rank_solve.hpp"

namespace tendril {

class ProjectiveSystem {
 public:
  // What a factorisation depends on besides the elements: a change here
  // refactors.
  struct Key {
    const Model* model = nullptr;
    double dt = 0, step_dt = 0, mass_factor = 0, geometric_factor = 0;
    int mass_mode = 0;
    bool operator==(const Key&) const = default;
  };
  bool current(const Key& k, std::uint64_t revision, std::size_t capacity) const {
    return factored_ && key_ == k && revision_ == revision && reference_.size() == capacity;
  }
  // Assembles M/dt^2 + L at positions x, with `mass` (frozen with the factor,
  // mass()) and `diagonal` extra per-particle weights (CST), and factors it.
  // Throws NumericalError when the matrix is not positive definite.
  void factor(const Key& key, std::uint64_t revision, const Model& m, const Vec3* x, const std::vector<double>& mass,
              double inv_dt2, const std::vector<double>& diagonal);
  // Follows a change of the model (same key) locally: assembles at
  // reference() with mass() - where `follow_mass` (physical masses) the
  // particles whose `mass` changed take it - and `diagonal` (CST at
  // reference()). New particles (after the old ones in every axis' rows)
  // take their position x and `mass` into reference() and mass(). False
  // when it needs factor(): another key, axes that shared a system no
  // longer sharing it, too many changed rows, or a matrix the correction
  // would not keep positive definite.
  bool update(const Key& key, std::uint64_t revision, const Model& m, const Vec3* x, const std::vector<double>& mass,
              bool follow_mass, double inv_dt2, const std::vector<double>& diagonal);
  // dx for the free coordinates of every particle: rhs -> increments, in place.
  void solve(const Model& m, Vec3* rhs);
  const std::vector<Vec3>& reference() const { return reference_; }  // x of the last factor()
  const std::vector<double>& mass() const { return mass_; }
  // Whether p was integrated at factor() or an update: reference() and
  // mass() hold its place and mass.
  bool known(ParticleId p) const { return p < known_.size() && known_[p]; }
  int rows(int axis) const { return axis_[axis]->rows.count; }  // left ones included
  std::uint64_t factorizations() const { return factorizations_; }  // factor(), and updates with low_rank off
  std::uint64_t updates() const { return updates_; }
  // Off: update() factors the updated matrix afresh instead of correcting
  // the old factor (the same matrix: what the tests check the correction
  // against).
  bool low_rank = true;

 private:
  using Factor = LdltFactor;
  struct Rows {  // the rows of one axis
    std::vector<int> row;   // particle -> row, or -1 (fixed, passive, gone)
    std::vector<int> left;  // particle -> the row it left since factor(), or -1
    std::vector<std::pair<int, double>> vacant;  // rows left, decoupled, and the diagonal each keeps
    int count = 0;
    bool operator==(const Rows&) const = default;
  };
  struct Axis {  // the system of one axis; axes with equal rows share one
    Rows rows;
    Eigen::SparseMatrix<double> A;  // what `factor` factors
    Factor factor;
    Eigen::VectorXd grown;         // rows added since factor(): their diagonal
    LowRankSolve change;           // diag(A, grown) + change: the current matrix
    std::vector<int> changed;      // rows changed since factor(), in order
    std::vector<int> reach;        // row -> the nonzeros of its column of L^-1 P (forward_reach)
    std::size_t entries = 0;       // of L and D
    Eigen::MatrixXd b;                 // a column per axis that shares it
    RowsOfColumns scratch;             // the forward half of a solve (low_rank_solve.hpp)
  };
  template <class Add>  // every matrix entry's terms, in a fixed order, through add(row, column, value)
  void terms(const Model& m, const Rows& rows, const Vec3* x, double inv_dt2, const std::vector<double>& diagonal,
             Add&& add) const;
  Eigen::SparseMatrix<double> assemble(const Model& m, const Rows& rows, const Vec3* x, double inv_dt2,
                                       const std::vector<double>& diagonal) const;
  void factor_axis(Axis& s, int a);
  bool shared_before(int a) const;  // axis a's system is an earlier axis's too
  static bool outgrown(const Axis& s);  // its changed rows cost more than a factorisation saves
  static Rows rows_of(const Model& m, int a);                      // numbered afresh, in `integrated` order
  static Rows followed(const Model& m, const Axis& s, int a);      // s's rows kept, arrivals after them
  Key key_;
  std::uint64_t revision_ = 0;
  bool factored_ = false;
  std::uint64_t factorizations_ = 0, updates_ = 0;
  std::array<std::shared_ptr<Axis>, 3> axis_;
  std::vector<Vec3> reference_;
  std::vector<double> mass_;
  std::vector<std::uint8_t> known_;  // integrated at factor() or an update: mass_ holds its mass
};

}  // namespace tendril
