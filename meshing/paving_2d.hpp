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
//  - holes: each hole is a front of its own, clockwise, growing with wedges
//    (reflex side nodes made corners) while the outer one shrinks; two
//    fronts within a row of each other are joined by one quad into a
//    single front and the strip beside the bridge is zipped shut
//    (paving_fronts.cpp);
//  - splitting: a front that can neither advance nor close is cut in two
//    by one quad across a neck narrower than a row (then zipped), and each
//    piece is paved on its own.
//  - a second strategy (pave_2d): where the plain one fails or leaves a
//    quad below a scaled Jacobian of 0.5, a run that may also advance thin
//    rows (0.35 h) before forcing a closure; the better mesh is kept.
// Not done: wedges on concave outer fronts, clean-up by element deletion,
// and size grading inside the domain. Some strongly concave boundaries
// (T-junctions at fine spacing, deeply notched stars) and small holes near
// one side still mesh with a worst scaled Jacobian of 0.1-0.5, or fail.
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

// A domain with holes: `outer` as above (any count >= 4), each hole a simple
// polygon of >= 3 corners in either orientation, strictly inside `outer` and
// outside the other holes, no two loops touching; the total number of
// corners even. Mesh2::points are outer's, then each hole's, in the given
// order. Every loop starts as a front of its own (paving_fronts.cpp).
Mesh2 pave_2d(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
              const PavingOptions& options = {});

}  // namespace tendril::meshing
