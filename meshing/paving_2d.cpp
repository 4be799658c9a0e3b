#include "paving_2d.hpp"

#include "paving_paver.hpp"

namespace tendril::meshing {
namespace detail {

Paver::Paver(const std::vector<Vec2>& loop, const PavingOptions& o) : pts_(loop), n_(loop.size()), opt_(o) {
  for (Index i = 0; i < n_; ++i) parent_.push_back(i);
  double perimeter = 0;
  for (std::size_t i = 0; i < n_; ++i) perimeter += (loop[(i + 1) % n_] - loop[i]).norm();
  h_ = perimeter / double(n_);
}

Mesh2 Paver::run() {
  std::vector<Index> front(n_);
  for (Index i = 0; i < n_; ++i) front[i] = i;
  for (int row = 0; front.size() > 2; ++row) {  // 2 or fewer: zipped shut
    if (row >= opt_.max_rows) throw ModelError("paving: no closure after " + std::to_string(row) + " rows");
    const std::size_t m = front.size();
    bool ok = false;
    if (m <= 8) ok = close(front, false) || close(front, true);
    else ok = advance(front, row, 1.0) || advance(front, row, 0.6) || close(front, false) || close(front, true);
    if (!ok)
      throw ModelError("paving: the front of " + std::to_string(m) + " nodes after " + std::to_string(row) +
                       " rows could not advance without self-intersection (narrow or strongly concave "
                       "regions are not supported yet)");
    std::vector<bool> movable(pts_.size(), false);
    for (Index v = Index(n_); v < pts_.size(); ++v) movable[v] = parent_[v] == v;
    smooth(movable, front, opt_.row_smoothing);
  }
  return finish();
}

Mesh2 Paver::finish() {
  std::vector<Index> id(pts_.size(), kNoNode);
  Mesh2 out;
  for (Index v = 0; v < pts_.size(); ++v)
    if (find(v) == v) {
      id[v] = Index(out.points.size());
      out.points.push_back(pts_[v]);
    }
  for (QuadIndices q : quads_) {
    for (Index& v : q) v = id[find(v)];
    out.quads.push_back(q);
  }
  // Final smoothing on the compact mesh: every new node is now enclosed.
  pts_ = out.points;
  parent_.resize(pts_.size());
  for (Index v = 0; v < pts_.size(); ++v) parent_[v] = v;
  quads_ = out.quads;
  std::vector<bool> movable(pts_.size(), true);
  for (std::size_t v = 0; v < n_; ++v) movable[v] = false;
  smooth(movable, {}, opt_.final_smoothing);
  optimise(movable, opt_.final_smoothing);
  out.points = pts_;
  for (std::size_t q = 0; q < out.quads.size(); ++q) {
    std::vector<Vec2> poly;
    for (Index v : out.quads[q]) poly.push_back(out.points[v]);
    if (signed_area(poly) <= 0) throw ModelError("paving: quad " + std::to_string(q) + " came out inverted");
  }
  return out;
}

}  // namespace detail

using namespace detail;


bool simple_polygon(const std::vector<Vec2>& loop) {
  const std::size_t n = loop.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (loop[i] == loop[(i + 1) % n]) return false;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool next = j == i + 1, wrap = i == 0 && j == n - 1;
      if (next || wrap) {
        // Adjacent edges share one corner; they must not fold back onto each other.
        const Vec2 s = next ? loop[j] : loop[0];
        const Vec2 a = next ? loop[i] : loop[1];
        const Vec2 b = next ? loop[(j + 1) % n] : loop[n - 1];
        if (CGAL::collinear(cg(a), cg(s), cg(b)) && (a - s).dot(b - s) > 0) return false;
        continue;
      }
      if (segments_meet(loop[i], loop[(i + 1) % n], loop[j], loop[(j + 1) % n])) return false;
    }
  return true;
}

Mesh2 pave_2d(const std::vector<Vec2>& loop, const PavingOptions& options) {
  if (loop.size() < 4 || loop.size() % 2)
    throw ModelError("paving: needs an even number (>= 4) of boundary points, got " + std::to_string(loop.size()));
  if (!simple_polygon(loop)) throw ModelError("paving: the boundary intersects itself");
  if (signed_area(loop) <= 0) throw ModelError("paving: the boundary must run counter-clockwise");
  return Paver(loop, options).run();
}

}  // namespace tendril::meshing
