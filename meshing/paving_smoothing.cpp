// Paving: smoothing and local optimisation of the new nodes.
#include "paving_paver.hpp"

#include <set>

namespace tendril::meshing::detail {

double Paver::worst_jacobian(const std::vector<std::size_t>& quads) {
  double j = 1;
  for (std::size_t q : quads) j = std::min(j, jacobian(corners(quads_[q])));
  return j;
}

// Smoothing of the movable nodes (roots only). Enclosed nodes move to the
// mean of their neighbours (Laplacian). A node on the front has quads on one
// side only, so Laplacian would pull it back into the finished rows: it moves
// isoparametrically instead (the mean over its quads of the corner that
// makes each a parallelogram) and slides along the front towards the middle
// of its two front neighbours. A move that would invert an incident quad
// (or make an inverted one worse) is refused.
void Paver::smooth(const std::vector<bool>& movable, const Fronts& fronts, int iterations) {
  if (iterations <= 0) return;
  const std::size_t np = pts_.size();
  std::vector<std::set<Index>> neighbours(np);
  std::vector<std::vector<std::size_t>> incident(np);
  for (std::size_t q = 0; q < quads_.size(); ++q) {
    QuadIndices c = quads_[q];
    for (Index& v : c) v = find(v);
    for (int k = 0; k < 4; ++k) {
      neighbours[c[k]].insert(c[(k + 1) % 4]);
      neighbours[c[k]].insert(c[(k + 3) % 4]);
      incident[c[k]].push_back(q);
    }
  }
  std::vector<bool> on_front(np, false);
  std::vector<Index> front_prev(np), front_next(np);
  for (const std::vector<Index>& front : fronts)
    for (std::size_t k = 0; k < front.size(); ++k) {
      const Index v = find(front[k]);
      on_front[v] = true;
      front_prev[v] = find(front[(k + front.size() - 1) % front.size()]);
      front_next[v] = find(front[(k + 1) % front.size()]);
    }
  auto worst = [&](Index v) { return worst_jacobian(incident[v]); };
  for (int it = 0; it < iterations; ++it)
    for (Index v = 0; v < np; ++v) {
      if (v >= movable.size() || !movable[v] || neighbours[v].empty()) continue;
      Vec2 target = Vec2::Zero();
      for (Index u : neighbours[v]) target += pts_[u];
      target /= double(neighbours[v].size());
      if (on_front[v]) {
        // Isoparametric: the mean over its quads of the corner that would
        // make each quad a parallelogram; uses only the quads it has.
        target = Vec2::Zero();
        for (std::size_t q : incident[v]) {
          QuadIndices c = quads_[q];
          int k = 0;
          while (find(c[k]) != v) ++k;
          target += pts_[find(c[(k + 1) % 4])] + pts_[find(c[(k + 3) % 4])] - pts_[find(c[(k + 2) % 4])];
        }
        target /= double(incident[v].size());
        // And slide along the front towards even spacing.
        const Vec2 a = pts_[front_prev[v]], b = pts_[front_next[v]];
        const Vec2 t = (b - a).normalized();
        target += t * t.dot((a + b) / 2 - target);
      }
      const Vec2 old = pts_[v];
      const double before = worst(v);
      pts_[v] = target;
      const double after = worst(v);
      if (!(after > 0 || after >= before)) pts_[v] = old;
    }
}

// Where Laplacian smoothing leaves a bad quad, a node is moved by a small
// pattern search to the place that maximises the worst scaled Jacobian of
// its quads (nodes whose quads are all good are left alone).
void Paver::optimise(const std::vector<bool>& movable, int iterations) {
  const std::size_t np = pts_.size();
  std::vector<std::vector<std::size_t>> incident(np);
  std::vector<double> reach(np, 0);
  for (std::size_t q = 0; q < quads_.size(); ++q)
    for (int k = 0; k < 4; ++k) {
      incident[quads_[q][k]].push_back(q);
      reach[quads_[q][k]] += (pts_[quads_[q][(k + 1) % 4]] - pts_[quads_[q][k]]).norm();
    }
  auto worst = [&](Index v) { return worst_jacobian(incident[v]); };
  for (int it = 0; it < iterations; ++it)
    for (Index v = 0; v < np; ++v) {
      if (!movable[v] || incident[v].empty()) continue;
      double best = worst(v);
      if (best >= 0.7) continue;
      double step = 0.1 * reach[v] / double(incident[v].size());
      for (int shrink = 0; shrink < 6; ++shrink, step /= 2)
        for (bool improved = true; improved;) {
          improved = false;
          const Vec2 here = pts_[v];
          for (int d = 0; d < 8; ++d) {
            const double a = d * std::numbers::pi / 4;
            pts_[v] = here + step * Vec2(std::cos(a), std::sin(a));
            const double j = worst(v);
            if (j > best + 1e-12) {
              best = j;
              improved = true;
              break;
            }
            pts_[v] = here;
          }
        }
    }
}

}  // namespace tendril::meshing::detail
