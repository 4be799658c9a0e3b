#pragma once
// The planar core of paving (rule 20): an advancing-front quad mesher after
// Blacker & Stephenson (1991), kept simple. One row per front:
//  - row choice: every front node is classified by its interior angle as a
//    row end (< 135 deg: no new node, one quad turns the corner), side
//    (< 225: one node on the bisector) or corner (3 nodes, 3 quads); the
//    first row steps by the boundary's local spacing, later rows by the
//    target size h (the mean boundary edge);
//  - row adjustment: on inner fronts, extra row ends (sharpest side nodes
//    first, spread along the front) keep the node count near
//    (perimeter - 2 pi h) / h as the front shrinks; the given boundary never
//    gets extra ends, so its quads keep at least half its angles;
//  - seams: where rows from opposite sides meet, the new front folds back at
//    near-zero angles and is zipped shut by merging across the fold;
//  - intersection: a row is accepted only if its quads are strictly convex,
//    the new front is a simple polygon and does not touch the old one
//    (CGAL exact predicates); otherwise a row of 0.6 h is tried, then a
//    closure;
//  - closure: fronts of up to 8 nodes, or fronts a row could not advance,
//    close with the best (max min scaled Jacobian) of a strip closure
//    without new nodes (ladders, L-bends; dynamic programming), a star
//    around the centroid (6 to 12 nodes) and, for 4 nodes, a quad inside a
//    ring of four;
//  - smoothing: after each row, enclosed nodes by Laplacian smoothing and
//    front nodes isoparametrically (they only have the quads behind them)
//    with a slide along the front towards even spacing; at the end all new
//    nodes by Laplacian smoothing, then a local search that maximises the
//    worst scaled Jacobian around nodes whose quads are below 0.7. No move
//    may invert a quad.
// Not done: wedges (node insertion on concave fronts), front splitting when
// distant parts of a front meet other than by seams, clean-up by element
// deletion, and size grading inside the domain. Strongly concave boundaries
// (stars, T-junctions) still mesh but with a worst scaled Jacobian nearer
// 0.2-0.5 than the 0.7 of convex or orthogonal ones.
#include <Eigen/Core>
#include <vector>

#include "quad_mesh.hpp"

namespace tendril::meshing {

using Vec2 = Eigen::Vector2d;

struct Mesh2 {
  std::vector<Vec2> points;  // the loop first, unmoved, then the new nodes
  std::vector<QuadIndices> quads;  // counter-clockwise
};

struct PavingOptions {
  int max_rows = 1000;
  int row_smoothing = 3;     // iterations on enclosed nodes after each row
  int final_smoothing = 40;  // iterations on every new node at the end
};

// True when no two edges of the closed polygon meet except adjacent ones at
// their shared corner (exact predicates; a fold back along an edge counts).
bool simple_polygon(const std::vector<Vec2>& loop);

// Paves the inside of a simple counter-clockwise polygon with an even number
// (>= 4) of corners. Throws ModelError("paving: ...") when it cannot.
Mesh2 pave_2d(const std::vector<Vec2>& loop, const PavingOptions& options = {});

}  // namespace tendril::meshing
