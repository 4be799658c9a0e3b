// Paving: closing a front without another row.
#include "paving_paver.hpp"

#include <set>

namespace tendril::meshing::detail {

// Strip closure without new nodes: starting from the front edge
// (f[i-1], f[i]) as the first rung, each quad advances the rails a = f[i],
// f[i+1], ... and b = f[i-1], f[i-2], ... by one node each (a rung quad)
// or one rail by two (turning a corner), until the last rung is a front
// edge. Dynamic programming over (steps on a, steps on b) for every i
// maximises the minimum scaled Jacobian. Covers ladders across one-element
// strips, L-bends and the small-front splits.
Paver::Closure Paver::strip_closure(const std::vector<Index>& f) {
  const std::size_t m = f.size();
  Closure best;
  if (m < 4 || m > 200) return best;
  const std::size_t w = m - 1;  // p, q in [0, m - 2]
  const double none = -std::numeric_limits<double>::infinity();
  std::vector<double> value(w * w);
  std::vector<std::uint8_t> move(w * w);
  for (std::size_t i = 0; i < m; ++i) {
    auto a = [&](std::size_t p) { return f[(i + p) % m]; };
    auto b = [&](std::size_t q) { return f[(i + 2 * m - 1 - q) % m]; };
    auto quad = [&](std::size_t p, std::size_t q, int mv) -> QuadIndices {
      if (mv == 0) return {a(p), a(p + 1), b(q + 1), b(q)};
      if (mv == 1) return {a(p), a(p + 1), a(p + 2), b(q)};
      return {a(p), b(q + 2), b(q + 1), b(q)};
    };
    std::fill(value.begin(), value.end(), none);
    value[0] = std::numeric_limits<double>::infinity();
    for (std::size_t sum = 0; sum + 4 <= m; sum += 2)
      for (std::size_t p = 0; p <= sum; ++p) {
        const std::size_t q = sum - p;
        const double here = value[p * w + q];
        if (here == none) continue;
        const std::size_t dp[3] = {1, 2, 0}, dq[3] = {1, 0, 2};
        for (int mv = 0; mv < 3; ++mv) {
          const std::size_t np = p + dp[mv], nq = q + dq[mv];
          const double v = std::min(here, jacobian(corners(quad(p, q, mv))));
          if (v > value[np * w + nq]) value[np * w + nq] = v, move[np * w + nq] = std::uint8_t(mv);
        }
      }
    for (std::size_t p = 0; p + 2 <= m; ++p) {
      const std::size_t q = m - 2 - p;
      if (value[p * w + q] <= best.score) continue;
      best.score = value[p * w + q];
      best.quads.clear();
      for (std::size_t pp = p, qq = q; pp + qq > 0;) {
        const int mv = move[pp * w + qq];
        pp -= mv == 0 ? 1 : mv == 1 ? 2 : 0;
        qq -= mv == 0 ? 1 : mv == 2 ? 2 : 0;
        best.quads.push_back(quad(pp, qq, mv));
      }
    }
  }
  return best;
}

// Closure of the whole front by the best of: the strip closure, stars
// around the centroid (6 to 12 nodes: alternate nodes become row ends),
// and for 4 nodes a quad inside a ring of four. Taken if its minimum
// scaled Jacobian is positive, or, when `any_valid`, if no quad is
// inverted (final smoothing then repairs what it can).
bool Paver::close(std::vector<Index>& front, bool any_valid) {
  const std::size_t m = front.size();
  auto f = [&](std::size_t i) { return front[i % m]; };
  const Mark before = mark();
  Closure best = strip_closure(front);
  bool best_has_nodes = false;
  auto consider = [&](const std::vector<QuadIndices>& quads) {
    double score = 1;
    for (const QuadIndices& q : quads) score = std::min(score, jacobian(corners(q)));
    if (score > best.score) best = {score, quads}, best_has_nodes = true;
  };
  Vec2 centroid = Vec2::Zero();
  for (Index v : front) centroid += pts_[v] / double(m);
  if (m >= 6 && m <= 12) {
    const Index c = add(centroid);
    for (std::size_t o = 0; o < 2; ++o) {
      std::vector<QuadIndices> star;
      for (std::size_t e = o + 1; e < m + o; e += 2) star.push_back({f(e - 1), f(e), f(e + 1), c});
      consider(star);
    }
  }
  if (m == 4) {
    std::array<Index, 4> g;
    for (std::size_t k = 0; k < 4; ++k) g[k] = add(pts_[f(k)] + 0.5 * (centroid - pts_[f(k)]));
    std::vector<QuadIndices> ring{{g[0], g[1], g[2], g[3]}};
    for (std::size_t k = 0; k < 4; ++k) ring.push_back({f(k), f(k + 1), g[(k + 1) % 4], g[k]});
    consider(ring);
  }
  bool ok = best.score > 0;
  if (!ok && any_valid && !best.quads.empty()) {
    ok = true;
    for (const QuadIndices& q : best.quads) {
      const auto c = corners(q);
      ok = ok && signed_area({c.begin(), c.end()}) > 0;
    }
  }
  if (!ok) {
    rollback(before);
    return false;
  }
  // Keep only the new nodes the chosen closure uses.
  std::set<Index> used;
  for (const QuadIndices& q : best.quads) used.insert(q.begin(), q.end());
  if (!best_has_nodes || !used.count(Index(before.points))) rollback(before);
  else if (m >= 6) pts_.resize(before.points + 1), parent_.resize(before.points + 1);
  for (const QuadIndices& q : best.quads) quads_.push_back(q);
  front.clear();
  return true;
}

}  // namespace tendril::meshing::detail
