#include "paving_2d.hpp"

#include <CGAL/Polygon_2_algorithms.h>

#include <limits>
#include <optional>
#include <string>

#include "paving_paver.hpp"

namespace tendril::meshing {
namespace detail {

Paver::Paver(const std::vector<Vec2>& points, std::vector<std::vector<Index>> fronts, const PavingOptions& o,
             bool thin_rows)
    : pts_(points), fronts0_(std::move(fronts)), n_(points.size()), opt_(o), thin_rows_(thin_rows) {
  for (Index i = 0; i < n_; ++i) parent_.push_back(i);
  double perimeter = 0;
  for (const std::vector<Index>& f : fronts0_)
    for (std::size_t i = 0; i < f.size(); ++i) perimeter += (pts_[f[(i + 1) % f.size()]] - pts_[f[i]]).norm();
  h_ = perimeter / double(n_);
}

Mesh2 Paver::run() {
  // Regions still to pave, each bounded by its fronts (an outer one first).
  // The domain is one region; a front split across a narrow neck becomes two.
  pending_ = {fronts0_};
  int row = 0;
  while (!pending_.empty()) {
    Fronts fronts = std::move(pending_.back());
    pending_.pop_back();
    pave_fronts(fronts, row);  // until the holes' fronts have joined the outer one
    pave_front(fronts.front(), row);
  }
  return finish();
}

Paver::Fronts Paver::with_pending(Fronts fronts) const {
  for (const Fronts& region : pending_) fronts.insert(fronts.end(), region.begin(), region.end());
  return fronts;
}

void Paver::pave_front(std::vector<Index> front, int& row) {
  for (; front.size() > 2; ++row) {  // 2 or fewer: zipped shut
    if (row >= opt_.max_rows) throw ModelError("paving: no closure after " + std::to_string(row) + " rows");
    const std::size_t m = front.size();
    bool ok = false;
    if (m <= 8) ok = close(front, false) || close(front, true);
    else
      ok = advance(front, row, 1.0) || advance(front, row, 0.6) || close(front, false) || split(front) ||
           (thin_rows_ && advance(front, row, 0.35)) || close(front, true);
    if (!ok)
      throw ModelError("paving: the front of " + std::to_string(m) + " nodes after " + std::to_string(row) +
                       " rows could not advance without self-intersection (narrow or strongly concave "
                       "regions are not supported yet)");
    std::vector<bool> movable(pts_.size(), false);
    for (Index v = Index(n_); v < pts_.size(); ++v) movable[v] = parent_[v] == v;
    smooth(movable, with_pending({front}), opt_.row_smoothing);
  }
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

namespace {

double worst_jacobian(const Mesh2& mesh) {
  double j = 1;
  for (const QuadIndices& q : mesh.quads)
    j = std::min(j, jacobian({mesh.points[q[0]], mesh.points[q[1]], mesh.points[q[2]], mesh.points[q[3]]}));
  return j;
}

// The paver's plain strategy first; where it fails or leaves a quad below a
// scaled Jacobian of 0.5, a second run that may also advance by thin rows
// (0.35 h) before forcing a closure, which gets some small, strongly concave
// fronts (the middle of a star) through. The better result is kept, so the
// second run never makes a mesh worse.
Mesh2 pave_best(const std::vector<Vec2>& points, const std::vector<std::vector<Index>>& fronts,
                const PavingOptions& options) {
  std::optional<Mesh2> first;
  std::string error;
  double score = -std::numeric_limits<double>::infinity();
  try {
    first = Paver(points, fronts, options).run();
    score = worst_jacobian(*first);
  } catch (const ModelError& e) {
    error = e.what();
  }
  if (score >= 0.5) return *first;
  try {
    Mesh2 second = Paver(points, fronts, options, true).run();
    if (worst_jacobian(second) > score) return second;
  } catch (const ModelError&) {
  }
  if (first) return *first;
  throw ModelError(error);
}

}  // namespace


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
  std::vector<Index> front(loop.size());
  for (Index i = 0; i < front.size(); ++i) front[i] = i;
  return pave_best(loop, {front}, options);
}

namespace {

bool loops_touch(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j)
      if (segments_meet(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return true;
  return false;
}

// Loops that do not touch are nested or apart; one corner tells which.
bool inside(const Vec2& p, const std::vector<Vec2>& loop) {
  std::vector<K::Point_2> poly;
  for (const Vec2& v : loop) poly.push_back(cg(v));
  return CGAL::bounded_side_2(poly.begin(), poly.end(), cg(p), K()) == CGAL::ON_BOUNDED_SIDE;
}

}  // namespace

Mesh2 pave_2d(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
              const PavingOptions& options) {
  if (holes.empty()) return pave_2d(outer, options);
  std::size_t total = outer.size();
  if (outer.size() < 4) throw ModelError("paving: the outer loop needs at least 4 points, got " + std::to_string(outer.size()));
  if (!simple_polygon(outer)) throw ModelError("paving: the outer loop intersects itself");
  if (signed_area(outer) <= 0) throw ModelError("paving: the outer loop must run counter-clockwise");
  for (std::size_t h = 0; h < holes.size(); ++h) {
    const std::string name = "hole " + std::to_string(h + 1);
    if (holes[h].size() < 3) throw ModelError("paving: " + name + " needs at least 3 points, got " + std::to_string(holes[h].size()));
    if (!simple_polygon(holes[h])) throw ModelError("paving: " + name + " intersects itself");
    if (loops_touch(outer, holes[h])) throw ModelError("paving: " + name + " touches or crosses the outer loop");
    if (!inside(holes[h][0], outer)) throw ModelError("paving: " + name + " is not inside the outer loop");
    for (std::size_t g = 0; g < h; ++g) {
      const std::string other = "hole " + std::to_string(g + 1);
      if (loops_touch(holes[g], holes[h])) throw ModelError("paving: " + name + " touches or crosses " + other);
      if (inside(holes[h][0], holes[g]) || inside(holes[g][0], holes[h]))
        throw ModelError("paving: " + name + " and " + other + " are nested");
    }
    total += holes[h].size();
  }
  if (total % 2)
    throw ModelError("paving: needs an even number of boundary points in all loops together (an all-quad patch has an even boundary), got " +
                     std::to_string(total));
  std::vector<Vec2> points = outer;
  std::vector<std::vector<Index>> fronts(1);
  for (Index i = 0; i < outer.size(); ++i) fronts[0].push_back(i);
  for (const std::vector<Vec2>& hole : holes) {
    std::vector<Index> front;
    for (const Vec2& p : hole) front.push_back(Index(points.size())), points.push_back(p);
    if (signed_area(hole) > 0) std::reverse(front.begin(), front.end());  // the region on its left
    fronts.push_back(front);
  }
  return pave_best(points, fronts, options);
}

}  // namespace tendril::meshing
