#pragma once
// Element buffers derived from the map. Each element remembers one dart of the
// cell it belongs to, so a swap-remove can re-point that cell in O(1).
#include <vector>

#include "model/membrane.hpp"
#include "model/types.hpp"
#include "model/undo_log.hpp"

namespace tendril {

// Elastic bar / cable on an edge (eq. 3.32-3.35).
struct Bar {
  ParticleId i, j;
  double rest_length;
  double EA;
  double prestress;
  double line_mass;  // kg/m
  std::uint8_t tension_only;
  std::uint32_t dart;  // a dart of the edge
};

// Spline-beam hinge with 3 DOF per particle at a beam vertex j between the
// links i-j and j-k (eq. 3.41-3.43). rest_curvature is 0 for a straight beam.
struct Hinge {
  ParticleId i, j, k;
  double EI;
  double rest_curvature;
  std::uint32_t dart;  // a dart of the vertex j inside the beam
};

// Li's co-rotational Euler-Bernoulli beam with 6 DOF per particle on an edge
// of a 6-DOF beam block (eq. 3.44-3.50): it carries the axial force of the
// edge too (no Bar, no Hinge there). end_i and end_j are the beam-end
// orientations relative to the node frames of i and j (appendix A); they
// co-rotate with the nodes. The element is stress free when both beam ends
// align with its chord and its length is the rest length.
struct Beam6 {
  ParticleId i, j;
  Quat end_i = Quat::Identity(), end_j = Quat::Identity();
  double rest_length;
  double EA, EIy, EIz, GJ;
  double prestress;
  double line_mass;    // kg/m
  std::uint32_t dart;  // a dart of the edge, embedding i
};

// Rotational joint of an adaptive structure (thesis 6.5.2, fig. 6.32) at a
// particle shared by two beams crossing there. Its four neighbours are read
// from the map at every evaluation, so rules may rewrite the beams around it.
struct RotationalJoint {
  ParticleId particle;
  double angle;      // target included angle between the two beams [rad]
  double stiffness;  // fictitious stiffness of the projections [N/m]
};

// Constant strain triangle of a patch in CST mode (thesis 3.2.8.2): side
// i -> j along the warp (the first side, eq. 3.36), j -> k along the weft,
// k -> i the diagonal of its quad. Form-finding: the prescribed stresses
// sigma (eq. 3.36). Analysis: sigma is the prestress, plus the orthotropic
// stresses of the strains against `ref` (eq. 3.37-3.39). dart: the dart of
// its quad at i on side i -> j.
struct Cst {
  ParticleId i, j, k;
  Membrane membrane;
  CstReference ref;
  std::uint32_t dart;
};

template <class E>
struct ElementBuffer {
  LoggedVector<E> items;
  std::size_t size() const { return items.size(); }
  E& operator[](std::size_t n) { return items[n]; }
  const E& operator[](std::size_t n) const { return items[n]; }
};

}  // namespace tendril
