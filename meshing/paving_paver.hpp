#pragma once
// Internal to paving, not part of the API: the advancing-front state shared
// by paving_2d.cpp (driver, finish), paving_rows.cpp (rows, row ends, seams,
// intersection checks), paving_closure.cpp and paving_smoothing.cpp. The
// algorithm is described in paving_2d.hpp.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "paving_2d.hpp"

namespace tendril::meshing::detail {

inline constexpr Index kNoNode = 0xffffffffu;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
inline K::Point_2 cg(const Vec2& p) { return {p.x(), p.y()}; }

inline bool segments_meet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  return CGAL::do_intersect(K::Segment_2(cg(a), cg(b)), K::Segment_2(cg(c), cg(d)));
}

inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Scaled Jacobian of a counter-clockwise planar quad (min over corners).
inline double jacobian(const std::array<Vec2, 4>& p) {
  double j = 1;
  for (int i = 0; i < 4; ++i) {
    const Vec2 a = p[(i + 1) % 4] - p[i], b = p[(i + 3) % 4] - p[i];
    const double la = a.norm(), lb = b.norm();
    j = std::min(j, la > 0 && lb > 0 ? cross(a, b) / (la * lb) : -1.0);
  }
  return j;
}

inline bool strictly_convex(const std::array<Vec2, 4>& p) {
  for (int i = 0; i < 4; ++i)
    if (CGAL::orientation(cg(p[(i + 3) % 4]), cg(p[i]), cg(p[(i + 1) % 4])) != CGAL::LEFT_TURN) return false;
  return true;
}

inline double signed_area(const std::vector<Vec2>& poly) {
  double a = 0;
  for (std::size_t i = 0; i < poly.size(); ++i) a += cross(poly[i], poly[(i + 1) % poly.size()]);
  return a / 2;
}

enum class Kind { End, Side, Corner };

// Nodes are indices into pts_; the loop is 0..n_-1 and never moves or merges.
// Merged nodes are a union-find (parent_); quads keep the ids they were made
// with and are read through find().
class Paver {
 public:
  // `points` are the given boundary nodes; each of `fronts` is a cycle of
  // indices into them with the region on its left (the outer loop
  // counter-clockwise, holes clockwise).
  // `thin_rows`: a front that can neither advance nor close may also try a
  // row of 0.35 h before a forced closure (see pave_best in paving_2d.cpp).
  Paver(const std::vector<Vec2>& points, std::vector<std::vector<Index>> fronts, const PavingOptions& o,
        bool thin_rows = false);
  Mesh2 run();

 private:
  std::vector<Vec2> pts_;
  std::vector<Index> parent_;
  std::vector<QuadIndices> quads_;
  std::vector<std::vector<Index>> fronts0_;
  std::vector<std::vector<std::vector<Index>>> pending_;  // regions not yet paved
  std::size_t n_;
  double h_ = 0;
  PavingOptions opt_;
  bool thin_rows_ = false;

  Index add(const Vec2& p) {
    pts_.push_back(p);
    parent_.push_back(Index(parent_.size()));
    return Index(pts_.size() - 1);
  }
  Index find(Index v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void unite(Index a, Index b) {
    a = find(a), b = find(b);
    if (a == b) return;
    if (b < a) std::swap(a, b);
    pts_[a] = (pts_[a] + pts_[b]) / 2;
    parent_[b] = a;
  }
  std::array<Vec2, 4> corners(const QuadIndices& q) { return {pts_[find(q[0])], pts_[find(q[1])], pts_[find(q[2])], pts_[find(q[3])]}; }

  // Interior angle at front[j] (region on the left of a counter-clockwise front).
  double angle(const std::vector<Index>& f, std::size_t j) const {
    const std::size_t m = f.size();
    const Vec2 x = pts_[f[j]];
    const Vec2 dn = pts_[f[(j + 1) % m]] - x, dp = pts_[f[(j + m - 1) % m]] - x;
    double a = std::atan2(cross(dn, dp), dn.dot(dp));
    return a < 0 ? a + 2 * std::numbers::pi : a;
  }

  struct Mark {
    std::size_t points, quads;
  };
  Mark mark() const { return {pts_.size(), quads_.size()}; }
  void rollback(const Mark& k) {
    pts_.resize(k.points);
    parent_.resize(k.points);
    quads_.resize(k.quads);
  }

  using Fronts = std::vector<std::vector<Index>>;

  // paving_rows.cpp
  bool advance(std::vector<Index>& front, int row, double scale, const Fronts& others = {});
  void add_row_ends(const std::vector<Index>& front, const std::vector<double>& theta, std::vector<Kind>& kind) const;
  void add_wedges(const std::vector<Index>& front, const std::vector<double>& theta, std::vector<Kind>& kind,
                  long count) const;
  void seam(std::vector<Index>& front);
  bool share_quad(Index a, Index b);
  bool row_valid(const std::vector<Index>& old_front, const std::vector<Index>& next, const Mark& before,
                 const Fronts& others);

  void pave_front(std::vector<Index> front, int& row);
  Fronts with_pending(Fronts fronts) const;

  // paving_fronts.cpp (domains with holes: several fronts until they join;
  // narrow necks: a front split in two)
  void pave_fronts(Fronts& fronts, int& row);
  double gap(const Fronts& fronts, std::size_t k) const;
  bool bridge_clear(const Fronts& fronts, const std::array<Index, 4>& q, bool both_rungs) const;
  void join(Fronts& fronts);
  bool split(std::vector<Index>& front);
  void zip(Fronts& fronts, std::size_t which, Index u, Index v);

  // paving_closure.cpp
  struct Closure {
    double score = -std::numeric_limits<double>::infinity();
    std::vector<QuadIndices> quads;
  };
  Closure strip_closure(const std::vector<Index>& f);
  bool close(std::vector<Index>& front, bool any_valid);

  // paving_smoothing.cpp
  void smooth(const std::vector<bool>& movable, const Fronts& fronts, int iterations);
  void optimise(const std::vector<bool>& movable, int iterations);
  // The smallest scaled Jacobian of the given quads (1 when there are none).
  double worst_jacobian(const std::vector<std::size_t>& quads);

  Mesh2 finish();
};

}  // namespace tendril::meshing::detail
