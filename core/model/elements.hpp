#pragma once
// Element buffers derived from the map. Each element remembers one dart of the
// cell it belongs to, so a swap-remove can re-point that cell in O(1).
#include <array>
#include <cstdint>
#include <utility>
#include <string>
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
// interior: bit 0, 1, 2 set when i, j, k is an interior vertex of the patch
// (no boundary edge there): in form-finding such a corner is pulled along
// the surface normal only (cst_forces.cpp).
struct Cst {
  ParticleId i, j, k;
  Membrane membrane;
  CstReference ref;
  std::uint32_t dart;
  std::uint8_t interior;
};

// A goal of the constraint-based solvers (thesis 3.3.5: a constraint that
// attaches a fixed point or a geometric condition to particles), with a
// weight [N/m]: the stiffness of its potential (eq. 3.59). Anchor: i to
// `point`. Plane: i onto the plane through `point` with normal
// `direction`. Line: i onto the line through `point` along `direction`
// (either of any non-zero length, stored as given). Length: i and j at
// `length` apart. Planar: the quad face i, j, k, l onto its best-fit plane
// (physics/planarity.hpp). Rigid: the particles `members` move as one body
// (thesis 6.1: the textile module as a rigid body; 6 DOF for three or more
// particles not on a line), each pulled towards where the body's rest shape
// `rest` (offsets from its centroid) puts it, fitted to the current
// positions by the best rotation about their centroid (shape matching,
// physics/rigid_body.hpp); i is members[0]. The explicit integrators read it as a spring of
// stiffness `weight` to the same projection (into S, eq. 3.4), so every
// integrator honours it. Bend: the hinge of edge i-j between the triangles
// (i, j, k) and (i, j, l) of a surface flat at rest, with the corners'
// cotangent weights `hinge`, the two triangles' area `hinge_area` and the
// plate's bending stiffness D [N m] as its weight (physics/shell_bending.hpp).
// goals.cpp.
struct Goal {
  enum Kind : std::uint8_t { Anchor, Plane, Line, Length, Planar, Rigid, Bend };
  Kind kind = Anchor;
  ParticleId i = kNone, j = kNone;  // j: Length and Planar
  ParticleId k = kNone, l = kNone;  // Planar and Bend only
  Vec3 point = Vec3::Zero(), direction = Vec3::Zero();
  double length = 0;
  double weight = 0;
  std::vector<ParticleId> members;  // Rigid only
  std::vector<Vec3> rest;           // Rigid: each member's offset from the rest centroid [m]
  std::array<double, 4> hinge{};    // Bend: the cotangent weights of i, j, k, l
  double hinge_area = 0;            // Bend: the two triangles' area [m^2]
};
const char* goal_kind_name(Goal::Kind k);  // "anchor", "plane", "line", "length", "planar", "rigid", "bend"
bool parse_goal_kind(const std::string& name, Goal::Kind& out);

// A flat element buffer, partitioned for multi-resolution (thesis 5.5.2.3):
// items[0, awake) touch no passive particle and are all the solver
// evaluates; items[awake, size) are dormant and cost nothing in a step. An
// element changes side by one swap with the border, so the partition is
// kept by O(1) work per element a change touches, and every swap goes
// through the undo log. `repoint(k)` (given by the model) re-points the cell
// of the element that now sits at index k (its dart column).
// A new element type joins the partition by calling place() whenever its
// particles change (and erase() to remove it), and the solver loops over
// awake_end() only; Model::set_passive then has to re-place it too.
// `edits` lists the indices written since the solver's lean copy last
// caught up (bar_chunks.hpp and hinge_chunks.hpp patch themselves from it).
template <class E>
struct ElementBuffer {
  LoggedVector<E> items;
  std::size_t awake = 0;
  UndoLog* log = nullptr;
  EditList edits;

  void attach(UndoLog* undo) {
    log = undo;
    items.attach(undo);
    items.watch(&edits);
  }
  std::size_t size() const { return items.size(); }
  E& operator[](std::size_t n) { return items[n]; }
  const E& operator[](std::size_t n) const { return items[n]; }
  const E* awake_begin() const { return items.data(); }
  const E* awake_end() const { return items.data() + awake; }
  void clear() {
    items.clear();
    if (log) log->scalar(awake);
    awake = 0;
  }
  // Moves element n to the awake side (wake) or the dormant side; returns
  // its new index.
  template <class Repoint>
  std::uint32_t place(std::uint32_t n, bool wake, Repoint&& repoint) {
    if (wake == (n < awake)) return n;
    if (log) log->scalar(awake);
    std::uint32_t border;
    if (wake) border = static_cast<std::uint32_t>(awake++);
    else border = static_cast<std::uint32_t>(--awake);
    if (border != n) {
      const E moved = std::as_const(items)[border];
      items[border] = std::as_const(items)[n];
      items[n] = moved;
      repoint(n);
      repoint(border);
    }
    return border;
  }
  // Removes element n; the last element takes its place.
  template <class Repoint>
  void erase(std::uint32_t n, Repoint&& repoint) {
    n = place(n, false, repoint);
    const std::uint32_t last = static_cast<std::uint32_t>(items.size() - 1);
    if (n != last) {
      items[n] = items.back();
      repoint(n);
    }
    items.pop_back();
  }
};

}  // namespace tendril
