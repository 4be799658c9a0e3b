// Paving a domain with holes (Blacker & Stephenson): every loop is a front
// of its own, the outer one counter-clockwise, each hole's clockwise, so the
// region is always on a front's left and one row generator serves them all.
// The fronts advance row by row, the outer one shrinking (row ends), the
// holes' growing (wedges), until two of them come within a row of each
// other; then a bridging quad joins them into one front, which the
// single-front paver closes (usually as a ladder across the strip left).
#include "paving_paver.hpp"

namespace tendril::meshing::detail {

namespace {

// Fronts closer than this many target sizes join instead of advancing: the
// strip between them is then one row of quads of about h.
constexpr double kJoinGap = 1.6;
// The worst scaled Jacobian a zipping quad may have (smoothing improves it).
constexpr double kZipQuality = 0.3;

double point_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d - p).norm();
}

}  // namespace

// Shortest distance between front k and any other front (nodes to edges,
// both ways).
double Paver::gap(const Fronts& fronts, std::size_t k) const {
  double best = std::numeric_limits<double>::infinity();
  auto one_way = [&](const std::vector<Index>& nodes, const std::vector<Index>& edges) {
    for (Index v : nodes)
      for (std::size_t i = 0; i < edges.size(); ++i)
        best = std::min(best, point_segment(pts_[v], pts_[edges[i]], pts_[edges[(i + 1) % edges.size()]]));
  };
  for (std::size_t o = 0; o < fronts.size(); ++o)
    if (o != k) one_way(fronts[k], fronts[o]), one_way(fronts[o], fronts[k]);
  return best;
}

void Paver::pave_fronts(Fronts& fronts, int& row) {
  while (fronts.size() > 1) {
    if (row >= opt_.max_rows) throw ModelError("paving: the fronts did not meet after " + std::to_string(row) + " rows");
    bool joined = false;
    for (std::size_t k = 0; k < fronts.size() && !joined; ++k) {
      if (gap(fronts, k) < kJoinGap * h_) {
        join(fronts);
        joined = true;
        break;
      }
      Fronts others;
      for (std::size_t o = 0; o < fronts.size(); ++o)
        if (o != k) others.push_back(fronts[o]);
      if (!advance(fronts[k], row, 1.0, others) && !advance(fronts[k], row, 0.6, others)) {
        join(fronts);  // a row would run into another front: join where they are closest
        joined = true;
      }
    }
    std::vector<bool> movable(pts_.size(), false);
    for (Index v = Index(n_); v < pts_.size(); ++v) movable[v] = parent_[v] == v;
    smooth(movable, with_pending(fronts), opt_.row_smoothing);
    if (!joined) ++row;
  }
}

// A quad q laid across fronts, whose edges q[3] -> q[0] (and, with
// `both_rungs`, q[1] -> q[2]) are new: the new edges cross no front edge
// and no front node lies inside it (exact predicates). With its other edges
// on fronts and the region on their left, the quad then lies in the region.
bool Paver::bridge_clear(const Fronts& fronts, const std::array<Index, 4>& q, bool both_rungs) const {
  const std::array<Vec2, 4> p{pts_[q[0]], pts_[q[1]], pts_[q[2]], pts_[q[3]]};
  for (const std::vector<Index>& o : fronts)
    for (std::size_t i = 0; i < o.size(); ++i) {
      const Index a = o[i], b = o[(i + 1) % o.size()];
      for (int r = 0; r < (both_rungs ? 2 : 1); ++r) {
        const Index s = r ? q[1] : q[3], t = r ? q[2] : q[0];
        if (a != s && a != t && b != s && b != t && segments_meet(pts_[s], pts_[t], pts_[a], pts_[b])) return false;
      }
      if (std::find(q.begin(), q.end(), a) != q.end()) continue;
      bool inside = true;
      for (int c = 0; c < 4; ++c)
        inside = inside && CGAL::orientation(cg(p[c]), cg(p[(c + 1) % 4]), cg(pts_[a])) == CGAL::LEFT_TURN;
      if (inside) return false;
    }
  return true;
}

// Joins the two fronts that face each other best with one quad
// {a0, a1, b0, b1} on an edge a0 -> a1 of one and b0 -> b1 of the other:
// the new front runs a1 .. a0 along the first, then b1 .. b0 along the
// second. The quad must be strictly convex, its two new edges may cross no
// front and no front node may lie inside it (exact predicates); among those
// it maximises the scaled Jacobian times how square it is.
void Paver::join(Fronts& fronts) {
  struct Candidate {
    double score;
    std::size_t f, i, g, j;
  };
  std::vector<Candidate> candidates;
  for (std::size_t f = 0; f < fronts.size(); ++f)
    for (std::size_t g = f + 1; g < fronts.size(); ++g) {
      const std::vector<Index>&A = fronts[f], &B = fronts[g];
      for (std::size_t i = 0; i < A.size(); ++i)
        for (std::size_t j = 0; j < B.size(); ++j) {
          const std::array<Vec2, 4> p{pts_[A[i]], pts_[A[(i + 1) % A.size()]], pts_[B[j]], pts_[B[(j + 1) % B.size()]]};
          const double jac = jacobian(p);
          if (jac <= 0) continue;
          const double side = std::max((p[1] - p[0]).norm(), (p[3] - p[2]).norm());
          const double rung = std::max((p[2] - p[1]).norm(), (p[0] - p[3]).norm());
          // Bridges longer than a row only when no short one fits.
          const double score = jac * std::min(side / rung, rung / side);
          candidates.push_back({rung < kJoinGap * h_ ? 1 + score : score, f, i, g, j});
        }
    }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.score > y.score; });
  for (const Candidate& c : candidates) {
    const std::vector<Index>&A = fronts[c.f], &B = fronts[c.g];
    const Index a0 = A[c.i], a1 = A[(c.i + 1) % A.size()], b0 = B[c.j], b1 = B[(c.j + 1) % B.size()];
    const std::array<Vec2, 4> p{pts_[a0], pts_[a1], pts_[b0], pts_[b1]};
    if (!strictly_convex(p) || !bridge_clear(fronts, {a0, a1, b0, b1}, true)) continue;
    quads_.push_back({a0, a1, b0, b1});
    std::vector<Index> merged;
    for (std::size_t k = 0; k < A.size(); ++k) merged.push_back(A[(c.i + 1 + k) % A.size()]);
    for (std::size_t k = 0; k < B.size(); ++k) merged.push_back(B[(c.j + 1 + k) % B.size()]);
    fronts[c.f] = std::move(merged);
    fronts.erase(fronts.begin() + std::ptrdiff_t(c.g));
    // Where the two fronts run close beside the bridge, zip the strip shut.
    zip(fronts, c.f, a0, b1);
    zip(fronts, c.f, b0, a1);
    return;
  }
  throw ModelError("paving: found no quad to join the fronts of the outer loop and a hole");
}

// A front that cannot advance because two of its parts face each other
// across a neck narrower than a row is split there: one quad
// {a0, a1, b0, b1} on two facing edges cuts the region in two, each with a
// front of an even number (>= 4) of nodes, a1 .. b0 and b1 .. a0; the neck
// on either side of the cut is zipped. The first piece stays `front`, the
// second waits in pending_.
bool Paver::split(std::vector<Index>& front) {
  const std::size_t m = front.size();
  struct Candidate {
    double score;
    std::size_t i, j;
  };
  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t first = (j + m - i) % m, second = m - first;  // sizes of the pieces
      if (first < 4 || second < 4 || first % 2 || second % 2) continue;
      const std::array<Vec2, 4> p{pts_[front[i]], pts_[front[(i + 1) % m]], pts_[front[j]], pts_[front[(j + 1) % m]]};
      const double jac = jacobian(p);
      const double side = std::max((p[1] - p[0]).norm(), (p[3] - p[2]).norm());
      const double rung = std::max((p[2] - p[1]).norm(), (p[0] - p[3]).norm());
      if (jac <= kZipQuality || rung >= kJoinGap * h_) continue;
      candidates.push_back({jac * std::min(side / rung, rung / side), i, j});
    }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& x, const Candidate& y) { return x.score > y.score; });
  for (const Candidate& c : candidates) {
    const Index a0 = front[c.i], a1 = front[(c.i + 1) % m], b0 = front[c.j], b1 = front[(c.j + 1) % m];
    const std::array<Vec2, 4> p{pts_[a0], pts_[a1], pts_[b0], pts_[b1]};
    if (!strictly_convex(p) || !bridge_clear(with_pending({front}), {a0, a1, b0, b1}, true)) continue;
    quads_.push_back({a0, a1, b0, b1});
    Fronts pieces(2);
    for (std::size_t k = (c.i + 1) % m;; k = (k + 1) % m) {
      pieces[0].push_back(front[k]);
      if (k == c.j) break;
    }
    for (std::size_t k = (c.j + 1) % m;; k = (k + 1) % m) {
      pieces[1].push_back(front[k]);
      if (k == c.i) break;
    }
    zip(pieces, 0, b0, a1);
    zip(pieces, 1, a0, b1);
    front = pieces[0];
    pending_.push_back({pieces[1]});
    return true;
  }
  return false;
}

// Zips a narrow strip shut from its rung u -> v (a front edge across the
// strip): each step closes three consecutive front edges that include the
// rung with one quad (a rung quad, or a turn when the strip's sides have
// different node counts), whose fourth edge becomes the next rung. It stops
// where the strip widens beyond a row or no quad is good enough.
void Paver::zip(Fronts& fronts, std::size_t which, Index u, Index v) {
  std::vector<Index>& f = fronts[which];
  while (f.size() > 4) {
    const std::size_t m = f.size();
    std::size_t k = 0;
    while (k < m && !(f[k] == u && f[(k + 1) % m] == v)) ++k;
    if (k == m) return;
    double best = kZipQuality;
    std::size_t chosen = m;
    for (std::size_t s : {(k + m - 1) % m, (k + m - 2) % m, k}) {
      const std::array<Index, 4> q{f[s], f[(s + 1) % m], f[(s + 2) % m], f[(s + 3) % m]};
      const std::array<Vec2, 4> p{pts_[q[0]], pts_[q[1]], pts_[q[2]], pts_[q[3]]};
      if (q[0] == q[3] || (p[3] - p[0]).norm() >= kJoinGap * h_ || !strictly_convex(p)) continue;
      const double jac = jacobian(p);
      if (jac <= best) continue;
      const bool clear = bridge_clear(fronts, q, false);
      if (clear) best = jac, chosen = s;
    }
    if (chosen == m) return;
    const std::array<Index, 4> q{f[chosen], f[(chosen + 1) % m], f[(chosen + 2) % m], f[(chosen + 3) % m]};
    quads_.push_back(q);
    std::vector<Index> next;
    for (std::size_t i = 0; i < m; ++i)
      if (f[i] != q[1] && f[i] != q[2]) next.push_back(f[i]);
    f = std::move(next);
    u = q[0], v = q[3];
  }
}

}  // namespace tendril::meshing::detail
