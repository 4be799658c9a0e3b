#pragma once
// The linear algebra of the static Newton solver (integrator "newton",
// newton_step.cpp): the exact tangent stiffness K = -dF/dx over the free
// coordinates (particles integrated, axes not locked) and the solve of
// K dx = F. Per bar or cable, with d = x_j - x_i, l = |d|, n = d / l and T
// its force (eq. 3.32; a slack cable none):
//   K_e = (EA / L) n n^T + (T / l) (I - n n^T)
// on the blocks ii and jj, -K_e on ij and ji. Goals (elements.hpp): an
// anchor w I, a plane w d d^T / |d|^2, a line w (I - d d^T / |d|^2), a
// length a two-way bar of stiffness w. Loads and gravity do not depend on
// positions and add nothing. Nothing else has a tangent here:
// unsupported() names the first element kind a model has beyond them.
//
// K dx = F is solved by conjugate gradients preconditioned with the exact
// sparse LDL^T factors of three scalar blocks of K: its x, y and z blocks,
// or, at a particle whose own block has one clearly softest direction (a
// membrane's normal), the blocks of its local axes (x and y projected on
// its tangent plane, and the normal): the couplings between axes left out.
// Why not LDL^T of K itself: a 3n system fills in 27 times the work of a
// scalar one (measured on the 200 x 200 net: 0.75 s per factorisation, 4
// times what the axis blocks and the iterations cost together). A flat net
// is exactly block diagonal, so the iterations only pay for the slopes;
// the local axes keep a curved membrane's stiff in-plane directions apart
// from its soft normal (after a refactorisation of the 800 x 800 net, 27
// iterations where the global axes took 46). The factors are kept while a
// solve converges in few iterations and computed again (with new frames)
// when it took many, the shift changed or the pattern did: refactoring
// after 8 iterations instead of 20 took as long on the 800 x 800 and
// 1000 x 1000 nets (fewer iterations, one more factorisation).
// Large blocks (multigrid_rows) get a smoothed-aggregation multigrid
// cycle instead of their factors: a 2-D net's factors cost n^1.5 to
// compute and n log n to apply, the cycle n (on the 1000 x 1000 net the
// solve went from 62 s to 13 s); its hierarchy is built again when a solve
// took more than 8 iterations.
// Rows are ordered axis by axis (every free x, then y, then z), each in
// the fill-reducing order (AMD) of its block, so an axis block is a
// diagonal block of K and its factor needs no permutation (a multigrid
// block keeps the particles' order, which keeps neighbours near). The pattern
// depends on the awake bars and the free coordinates only, so the symbolic
// analysis (ordering, elimination tree) is kept: when the model's revision
// moves the pattern is built again and compared, and a new analysis comes
// only when it differs (a rest length or a load changes values, not the
// pattern). Slack cables stay in the pattern with zeros.
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <vector>

#include "model/model.hpp"
#include "physics/aggregation_multigrid.hpp"

namespace tendril {

class NewtonSystem {
 public:
  // An axis block with at least this many rows is preconditioned by a
  // multigrid cycle instead of its factors (aggregation_multigrid.hpp).
  // Measured on the prestressed net, three alternating runs (bench_scaling
  // --multigrid-rows), cycle against factors: 4 900 particles 0.018-0.021
  // s against 0.021-0.027 s, 10K 0.047-0.060 against 0.060-0.077, 25.6K
  // 0.11-0.15 against 0.21-0.24; at 1M 14 s against 62 s. Below it the
  // factors are as cheap and exact. Tests and benchmarks may change it.
  static inline int multigrid_rows = 4'000;
  // The first element kind of the model the tangent does not cover
  // ("hinges (3-DOF spline beams)", "goals", ...), or nullptr.
  static const char* unsupported(const Model& m);
  // Assembles K + shift diag(K) at x.
  void assemble(const Model& m, const Vec3* x, double shift);
  // dx with |K dx - F| <= tolerance |F| over the free coordinates (zero on
  // every other), F per particle. False when K showed it is not positive
  // definite (a bar in compression, a mechanism): a larger shift may help.
  bool solve(const Model& m, const Vec3* F, Vec3* dx, double tolerance);
  std::uint64_t analyses() const { return analyses_; }            // symbolic analyses so far
  std::uint64_t factorizations() const { return factorizations_; }  // numeric ones (three axes: one)
  std::uint64_t iterations() const { return iterations_; }          // conjugate-gradient iterations so far
  int rows() const { return rows_; }
  // The last assemble()'s K (lower triangle) and p's row on an axis (-1: not free).
  const Eigen::SparseMatrix<double>& tangent() const { return K_; }
  int row(ParticleId p, int axis) const { return row_[3 * std::size_t(p) + axis]; }

 private:
  void build_pattern(const Model& m);  // rows and patterns, when the revision moved
  // The frames and the axis blocks of R^T K R at x, factored; false: one is
  // not positive definite.
  bool factor_axes(const Model& m, const Vec3* x, double shift);
  using Sparse = Eigen::SparseMatrix<double>;
  std::uint64_t revision_ = ~std::uint64_t(0);
  std::size_t capacity_ = 0;
  std::vector<int> row_;           // 3 p + axis -> row, or -1 (locked axis, particle not integrated)
  std::array<int, 4> offset_{};    // axis a's rows: [offset_[a], offset_[a + 1])
  int rows_ = 0;
  Sparse K_;                       // lower triangle
  std::vector<int> own_slot_;      // per particle: its block's 6 entries in K_'s values, or -1
  std::vector<int> bar_slot_;      // per awake bar: the 9 entries of its (i, j) block, or -1
  std::vector<int> axis_slot_;     // per awake bar and axis: its ii, jj and ij entries in that axis block, or -1
  struct Axis {
    Sparse A;                      // K_'s diagonal block, lower triangle
    Eigen::SimplicialLDLT<Sparse, Eigen::Lower, Eigen::NaturalOrdering<int>> ldlt;  // rows already in AMD order
    bool multigrid = false;        // a large block: a multigrid cycle instead of the factors
    AggregationMultigrid cycle;
  };
  std::array<Axis, 3> axis_;
  std::vector<ParticleId> framed_;  // particles with a frame of their own
  std::vector<Mat3> frames_;        // their frames (columns: the local axes)
  std::vector<Mat3> own_;           // each particle's own block of K, for its frame
  bool analysed_ = false, factored_ = false, factor_ok_ = false;
  double factored_shift_ = -1;
  int last_iterations_ = 0;
  std::uint64_t analyses_ = 0, factorizations_ = 0, iterations_ = 0;
  Eigen::VectorXd b_, x_, r_, z_, p_, q_, t_;
};

}  // namespace tendril
