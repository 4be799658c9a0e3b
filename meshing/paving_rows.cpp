// Paving: one row along the front, row ends, seams and the intersection checks.
#include "paving_paver.hpp"

namespace tendril::meshing::detail {

// One row of quads along the whole front; false (and nothing changed) when
// the row would overlap itself or the old front.
bool Paver::advance(std::vector<Index>& front, int row, double scale, const Fronts& others) {
  const std::size_t m = front.size();
  const double pi = std::numbers::pi;
  std::vector<double> theta(m);
  std::vector<Kind> kind(m);
  for (std::size_t j = 0; j < m; ++j) {
    theta[j] = angle(front, j);
    kind[j] = theta[j] < 0.75 * pi ? Kind::End : theta[j] < 1.25 * pi ? Kind::Side : Kind::Corner;
  }
  // Two adjacent row ends would need a quad of front nodes only.
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t k = (j + 1) % m;
      if (kind[j] == Kind::End && kind[k] == Kind::End) {
        kind[theta[j] > theta[k] ? j : k] = Kind::Side;
        changed = true;
      }
    }
  }
  if (row > 0) add_row_ends(front, theta, kind);

  const Mark before = mark();
  std::vector<Index> left(m, kNoNode), right(m, kNoNode), middle(m, kNoNode);
  for (std::size_t j = 0; j < m; ++j) {
    if (kind[j] == Kind::End) continue;
    const Vec2 x = pts_[front[j]], next = pts_[front[(j + 1) % m]], prev = pts_[front[(j + m - 1) % m]];
    // The first row follows the boundary's local spacing; later rows step
    // by the target size h: a local step would let convex parts of the
    // front (whose edges shrink) lag behind and sharpen into lobes.
    const double local = 0.5 * ((next - x).norm() + (prev - x).norm());
    const double base = scale * (row == 0 ? 0.5 * (local + h_) : h_);
    const Vec2 dn = (next - x).normalized();
    auto ray = [&](double a) { return Vec2(dn.x() * std::cos(a) - dn.y() * std::sin(a), dn.x() * std::sin(a) + dn.y() * std::cos(a)); };
    const double half = theta[j] / 2;
    if (kind[j] == Kind::Side) {
      left[j] = right[j] = add(x + base / std::max(std::sin(half), 0.5) * ray(half));
    } else {
      // Three quads share the angle at x: the two side quads get a right
      // angle where there is room (theta >= 270 deg), a third of it on the
      // flatter wedges of a growing front; the corner quad the rest.
      const double side = std::min(pi / 2, theta[j] / 3);
      left[j] = add(x + base * ray(theta[j] - side));
      middle[j] = add(x + 2 * base * std::cos(half - side) * ray(half));
      right[j] = add(x + base * ray(side));
    }
  }
  for (std::size_t j = 0; j < m; ++j)
    if (kind[j] == Kind::End) unite(right[(j + m - 1) % m], left[(j + 1) % m]);
  for (std::size_t j = 0; j < m; ++j) {
    const std::size_t k = (j + 1) % m, p = (j + m - 1) % m;
    if (kind[j] != Kind::End && kind[k] != Kind::End)
      quads_.push_back({front[j], front[k], find(left[k]), find(right[j])});
    if (kind[j] == Kind::End) quads_.push_back({front[p], front[j], front[k], find(right[p])});
    if (kind[j] == Kind::Corner) quads_.push_back({front[j], right[j], middle[j], left[j]});
  }
  std::vector<Index> next;
  auto push = [&](Index v) {
    v = find(v);
    if (next.empty() || next.back() != v) next.push_back(v);
  };
  for (std::size_t j = 0; j < m; ++j) {
    if (kind[j] == Kind::Side) push(left[j]);
    if (kind[j] == Kind::Corner) push(left[j]), push(middle[j]), push(right[j]);
  }
  while (next.size() > 1 && next.front() == next.back()) next.pop_back();
  seam(next);

  if (!row_valid(front, next, before, others)) {
    rollback(before);
    return false;
  }
  front = next;
  return true;
}

// Row adjustment: a shrinking front keeps about perimeter / h nodes by
// turning its sharpest side nodes into row ends, spread along the front.
void Paver::add_row_ends(const std::vector<Index>& front, const std::vector<double>& theta, std::vector<Kind>& kind) const {
  const std::size_t m = front.size();
  double perimeter = 0;
  long natural = 0;
  std::vector<std::size_t> ends;
  for (std::size_t j = 0; j < m; ++j) {
    perimeter += (pts_[front[(j + 1) % m]] - pts_[front[j]]).norm();
    natural += kind[j] == Kind::Side ? 1 : kind[j] == Kind::Corner ? 3 : -1;
    if (kind[j] == Kind::End) ends.push_back(j);
  }
  // The next front is shorter than this one by h times the turning of the
  // front (2 pi for an outer loop) and longer by as much for a hole's.
  double turning = 0;
  for (double t : theta) turning += std::numbers::pi - t;
  const long target = std::max(4L, 2 * std::lround((perimeter - turning * h_) / (2 * h_)));
  long extra = (natural - target) / 2;
  if (extra < 0 && turning < 0) add_wedges(front, theta, kind, -extra);
  if (extra <= 0) return;
  const std::size_t spacing = std::max<std::size_t>(3, m / (ends.size() + std::size_t(extra)) - 1);
  std::vector<std::size_t> candidates;
  for (std::size_t j = 0; j < m; ++j)
    if (kind[j] == Kind::Side && theta[j] < 0.995 * std::numbers::pi) candidates.push_back(j);
  std::stable_sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) { return theta[a] < theta[b]; });
  for (std::size_t c : candidates) {
    if (extra == 0) break;
    bool far = true;
    for (std::size_t e : ends) {
      const std::size_t d = c > e ? c - e : e - c;
      far = far && std::min(d, m - d) >= spacing;
    }
    if (!far) continue;
    kind[c] = Kind::End;
    ends.push_back(c);
    --extra;
  }
}

// Row adjustment on a growing front (around a hole): its flattest reflex
// side nodes become corners (wedges), each adding two nodes to the front,
// spread along it.
void Paver::add_wedges(const std::vector<Index>& front, const std::vector<double>& theta, std::vector<Kind>& kind,
                       long count) const {
  const std::size_t m = front.size();
  std::vector<std::size_t> corners, candidates;
  for (std::size_t j = 0; j < m; ++j) {
    if (kind[j] == Kind::Corner) corners.push_back(j);
    if (kind[j] == Kind::Side && theta[j] > 1.02 * std::numbers::pi) candidates.push_back(j);
  }
  const std::size_t spacing = std::max<std::size_t>(3, m / (corners.size() + std::size_t(count)) - 1);
  std::stable_sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) { return theta[a] > theta[b]; });
  for (std::size_t c : candidates) {
    if (count == 0) break;
    bool far = true;
    for (std::size_t e : corners) {
      const std::size_t d = c > e ? c - e : e - c;
      far = far && std::min(d, m - d) >= spacing;
    }
    if (!far) continue;
    kind[c] = Kind::Corner;
    corners.push_back(c);
    --count;
  }
}

// Seams: where rows from opposite sides meet, the new front folds back on
// itself at a node with a near-zero angle; its two neighbours are merged
// (zipping the front shut) unless they share a quad or one is on the loop.
void Paver::seam(std::vector<Index>& front) {
  for (bool again = true; again && front.size() > 2;) {
    again = false;
    const std::size_t m = front.size();
    for (std::size_t j = 0; j < m && !again; ++j) {
      const Index a = front[(j + m - 1) % m], b = front[(j + 1) % m];
      if (a < n_ || b < n_ || a == b || angle(front, j) >= std::numbers::pi / 6 || share_quad(a, b)) continue;
      unite(a, b);
      std::vector<Index> zipped;
      for (std::size_t k = 0; k < m; ++k) {
        if (k == j) continue;
        const Index v = find(front[k]);
        if (zipped.empty() || zipped.back() != v) zipped.push_back(v);
      }
      while (zipped.size() > 1 && zipped.front() == zipped.back()) zipped.pop_back();
      front = zipped;
      again = true;
    }
  }
}

bool Paver::share_quad(Index a, Index b) {
  a = find(a), b = find(b);
  for (const QuadIndices& q : quads_) {
    bool has_a = false, has_b = false;
    for (Index v : q) has_a = has_a || find(v) == a, has_b = has_b || find(v) == b;
    if (has_a && has_b) return true;
  }
  return false;
}

bool Paver::row_valid(const std::vector<Index>& old_front, const std::vector<Index>& next, const Mark& before,
                      const Fronts& others) {
  for (std::size_t q = before.quads; q < quads_.size(); ++q) {
    QuadIndices c = quads_[q];
    for (Index& v : c) v = find(v);
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (c[a] == c[b]) return false;
    const auto p = corners(c);
    if (!strictly_convex(p)) return false;
    // The other fronts (of a domain with holes) stay outside the new quads.
    for (const std::vector<Index>& o : others)
      for (std::size_t i = 0; i < o.size(); ++i) {
        const Vec2 a = pts_[o[i]], b = pts_[o[(i + 1) % o.size()]];
        bool inside = true;
        for (int k = 0; k < 4; ++k) {
          if (segments_meet(p[k], p[(k + 1) % 4], a, b)) return false;
          inside = inside && CGAL::orientation(cg(p[k]), cg(p[(k + 1) % 4]), cg(a)) == CGAL::LEFT_TURN;
        }
        if (inside) return false;
      }
  }
  if (next.size() <= 2) return true;  // zipped shut by seams
  if (next.size() % 2) return false;
  std::vector<Vec2> poly;
  for (Index v : next) poly.push_back(pts_[v]);
  std::vector<Vec2> old_poly;
  for (Index v : old_front) old_poly.push_back(pts_[v]);
  // Same orientation as the front it replaces: counter-clockwise for an
  // outer front, clockwise around a hole.
  if (!simple_polygon(poly) || signed_area(poly) * signed_area(old_poly) <= 0) return false;
  const std::size_t m = old_front.size();
  for (std::size_t i = 0; i < poly.size(); ++i)
    for (std::size_t j = 0; j < m; ++j)
      if (segments_meet(poly[i], poly[(i + 1) % poly.size()], pts_[old_front[j]], pts_[old_front[(j + 1) % m]]))
        return false;
  return true;
}

}  // namespace tendril::meshing::detail
