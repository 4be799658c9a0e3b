#pragma once
// The planarity goal of a quad face (thesis fig. 6.6, 6.1: glass or sheet
// panels on a form-found grid): its four corners projected onto their
// best-fit plane (least squares: through their centroid, normal the
// eigenvector of least eigenvalue of their scatter), each pulled towards its
// projection with the goal's weight [N/m] (ShapeOp's plane constraint). The
// pulls sum to zero, and so do their moments about the centroid (the normal
// is an eigenvector of the scatter): the goal bends the face flat and moves
// it nowhere as a whole.
#include "model/elements.hpp"

namespace tendril {

struct PlanarityPulls {
  ParticleId p[4];
  Vec3 f[4];
};

// Goal::Planar: its corners g.i, g.j, g.k, g.l.
PlanarityPulls planarity_pulls(const Goal& g, const Vec3* x);

// The largest distance of four points from their best-fit plane [m].
double planarity_gap(const Vec3 (&c)[4]);

}  // namespace tendril
