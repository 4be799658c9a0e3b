#pragma once
// The published benchmark models, built once for both `tendril validate`
// (validate/cases/) and the doctest suites, so a case and its test cannot
// drift apart: the pin-ended elastica, the hanging chain, the straight
// cantilever, Bathe & Bolourchi's 45-degree bend and the prestressed ring of
// thesis 5.4.1.2, and the frames
// whose limit loads test joints (Lee's frame, Williams' toggle).
#include <cstdint>
#include <functional>
#include <numbers>
#include <vector>

#include "model/model.hpp"
#include "model/strip_grillage.hpp"
#include "physics/solver.hpp"

namespace tendril::validate {

// Pin-ended strut of thesis 5.4.1.2 (Adriaenssens & Barnes 2001): L = 10 m,
// EI = 100 kNm^2, EA = 100 MN, n segments (even), 3 DOF (switch with
// set_beam_formulation), buckled by moving one pin towards the other until
// the end slope is theta0. Rest lengths from the straight strut; it starts
// as a half sine wave of the exact amplitude over the exact chord. Against the
// exact inextensible elastica (complete elliptic integrals K, E of
// k = sin(theta0 / 2)): chord = L (2E/K - 1), mid-span deflection k L / K,
// axial load P = EI (2K / L)^2.
struct Elastica {
  Model m;
  std::vector<ParticleId> ps;
  BlockId beam;
  double exact_deflection = 0, exact_load = 0;
  explicit Elastica(double theta0_deg = 80, int n = 64, int dofs = 3);
  // |measured / exact - 1|. The strut buckles either way; both are exact.
  double deflection_error() const;
  double load_error(const Solver& s) const;
};

// A chain of n cables hanging under its own weight: 10 m span, 12 m
// unstretched, 2 kg/m, EA = 100 kN, ends pinned, started as a shallow
// parabola. Against the elastic catenary (Irvine 1981): for span s,
// unstretched length L0, weight W and horizontal tension H,
//   s   = (2 H L0 / W) asinh(W / 2H) + H L0 / EA
//   sag = (H L0 / W) (sqrt(1 + (W / 2H)^2) - 1) + W L0 / (8 EA),
// H from the first by bisection, then the mid-span sag from the second.
struct HangingChain {
  static constexpr double span = 10, length = 12, rho = 2.0, EA = 1e5, g = 9.81;
  Model m;
  std::vector<ParticleId> ps;
  explicit HangingChain(int n = 80);  // n even: a particle at mid-span
  double sag() const;                 // of the mid-span particle [m]
  static double exact_sag();
  double sag_error() const;           // |sag / exact - 1|
};

// A straight cantilever along x from the origin, n segments, 6 DOF, root
// fully locked.
struct Cantilever {
  Model m;
  std::vector<ParticleId> ps;
  BlockId beam;
  Cantilever(int n, double L, const Section& s);
  ParticleId tip() const { return ps.back(); }
};

// A straight cantilever along x from the origin, n segments, 3 DOF: the
// root held in place and clamped along x (Model::set_clamp).
struct Cantilever3 {
  Model m;
  std::vector<ParticleId> ps;
  BlockId beam;
  Cantilever3(int n, double L, const Section& s);
  ParticleId tip() const { return ps.back(); }
};

// Mattiasson's cantilever (1981): L = 1 m, EI = 1 N m^2, EA = 1e5 N (an
// axial strain of 1e-4 at most), n segments, 3 DOF (Cantilever3: root held
// and clamped) or 6 DOF (root fully locked), under a tip load P in -y of
// PL^2/EI = 1 ... 10. kTable: his horizontal and vertical tip
// displacements u/L, w/L of the inextensible elastica (reproduced to 5
// digits by shooting on theta'' = -(P/EI) cos(theta), theta(0) = 0,
// theta'(L) = 0).
struct Mattiasson {
  static constexpr double kTable[10][2] = {{0.05643, 0.30172}, {0.16064, 0.49346}, {0.25442, 0.60325},
                                           {0.32894, 0.66996}, {0.38763, 0.71379}, {0.43459, 0.74457},
                                           {0.47293, 0.76737}, {0.50483, 0.78498}, {0.53182, 0.79906},
                                           {0.55500, 0.81061}};
  Model m;
  std::vector<ParticleId> ps;
  BlockId beam;
  Mattiasson(int n, int dofs);
  void set_load(double PL2_EI);  // the tip load in units of EI / L^2
  double u() const;              // (L - x_tip) / L
  double w() const;              // -y_tip / L
  // The larger relative error of u and w against kTable[k] (PL^2/EI = k + 1).
  double error(int k) const;
};

// Mattiasson's cantilever as a bending strip (model/strip_grillage.hpp):
// L = 1 m, W = 0.2 m, t = 10 mm, nu = 0.3, E such that D W = 1 N m^2 (the
// beam's EI), n quads along and `across` quads across, every row's root
// held and clamped along x. Tip loads and moments go on the rows' tips by
// their share of the width.
struct StripCantilever {
  static constexpr double kWidth = 0.2;
  Model m;
  std::vector<std::vector<ParticleId>> ps;  // ps[row][along]
  StripMembers members;
  StripCantilever(int n, int across);
  double share(std::size_t row) const;  // the row's tributary width over W
  void set_tip_load(const Vec3& total);
  void set_tip_moment(const Vec3& total);
  // The larger relative error of u and w of the worst row against
  // Mattiasson's table (tip load -z, PL^2/EI = k + 1).
  double error(int k) const;
};

// Bathe & Bolourchi's 45-degree bend: R = 100 in, 1 x 1 in section,
// E = 1e7 psi, G = E/2 (EA = 1e7 lb, EI = E/12, GJ = G/6 lb in^2), n
// elements (the published 8), 6 DOF, root fully locked, 600 lb at the tip
// normal to the bend's plane. The bend starts at the origin along x and
// turns towards +y; it is one beam whose curved shape is its rest shape
// (Model::set_rest_shape Current, m:beam{rest = "current"}: appendix A.1b,
// no pre-stress). Simo & Vu-Quoc's tip displacement under 600 lb:
// kReference; their tip positions under 300 and 600 lb (their x and y are
// our y and x): tip_reference.
struct BentCantilever {
  static inline const Vec3 kReference{-23.48, -13.50, 53.37};  // in
  Model m;
  std::vector<ParticleId> ps;
  BlockId beam;
  Vec3 start;  // the tip before loading
  explicit BentCantilever(int n = 8, double load = 600);
  ParticleId tip() const { return ps.back(); }
  Vec3 displacement() const { return m.particles.position[tip()] - start; }
  // The largest of the three components' relative errors (600 lb).
  double error() const;
  // Simo & Vu-Quoc (1986), 8 elements: the tip under 300 lb at (58.84,
  // 22.33, 40.08) in, under 600 lb at (47.23, 15.79, 53.37) in.
  static Vec3 tip_reference(double load);
  // |tip - reference| / |reference - start|: the tip's distance from the
  // reference over the reference's displacement.
  double tip_error(double load) const;
};

// A thin circular ring built curved at rest (Model::set_rest_shape
// Current), 3 DOF: radius R = 1 m, EI = 1 N m^2, EA = 1e5 N, n segments (a
// multiple of 4), in the plane z = 0 (held in z), squeezed along its y
// diameter by P (down at the top node, up at the bottom one). The top and
// bottom stay on x = 0 and the sides on y = 0 by symmetry, so those locks
// take the rigid motions without a force. Exact (thin ring in bending,
// Roark): the loaded diameter shortens by delta = P R^3 / EI (pi/4 - 2/pi);
// EA adds P R / EA (pi/4 + ...) ~ 1e-5 of it.
struct SqueezedRing {
  static constexpr double R = 1, EI = 1, EA = 1e5;
  Model m;
  std::vector<ParticleId> ps;
  BlockId beam;
  ParticleId top, bottom;
  double P;
  SqueezedRing(int n, double load = 1e-3);
  static double exact_shortening(double P) { return P * R * R * R / EI * (std::numbers::pi / 4 - 2 / std::numbers::pi); }
  double shortening() const;  // of the loaded diameter [m]
  double error() const;       // |shortening / exact - 1|
};

// Prestressed ring under out-of-plane loads (thesis 5.4.1.2, fig. 5.14;
// Adriaenssens & Barnes 2001): an initially straight beam (EI = 100 kNm^2,
// EA = 100 MN) closed into a ring of diameter 10 m, so it is prestressed by
// bending (M = EI / R). Nodes 1-4 at 0, 90, 180, 270 degrees; the quadrants
// 1-2, 2-3, 3-4, 4-1 have n, 2n, 4n, 8n segments (15n in all). 10 kN act
// downwards (-z) at nodes 1 and 3; nodes 2 and 4 are held in z.
//
// Delta (Barnes & Adriaenssens' 2.42 m for n = 8) is the drop of the loaded
// nodes 1 and 3 below the held nodes 2 and 4: the ring folds into a saddle.
// Both loads point the same way: opposite loads would be a couple about the
// axis 2-4, which the z supports at 2 and 4 cannot resist. By symmetry nodes
// 1 and 3 drop alike; the uneven quadrants make them differ by the
// discretisation error, so both are measured.
//
// The z supports leave three rigid in-plane motions (x, y, rotation about
// z), taken by the least restraint the symmetric solution needs no force
// from: x at nodes 2 and 4 (both stay on the plane x = 0, the mirror plane
// that swaps 1 and 3) and y at node 1 (on y = 0, the mirror plane that swaps
// 2 and 4). With 6 DOF one more zero-energy mode appears: every node frame
// rolling about the ring's tangent at the same rate (an isotropic ring turns
// inside out for free), which kinetic damping never stops because its energy
// never peaks; a rotation lock about x at node 2 (where the tangent stays
// along x by the same symmetry) stops it. The twist of the saddle is zero
// (a mirror-symmetric closed curve has no writhe, so no twist either), hence
// GJ does not enter and the 6-DOF ring answers the same question as Barnes'
// torsion-free spline beam.
struct PrestressedRing {
  static constexpr double kReference = 2.42;  // m
  Model m;
  std::vector<ParticleId> ps;
  BlockId beam;
  ParticleId node[4];  // nodes 1-4
  PrestressedRing(int n, int dofs);
  double drop(int node_number) const;  // below the start plane z = 0 [m], node 1..4
  double error() const;                // the larger of nodes 1 and 3
};

// The limit load of a structure under displacement control: `set` prescribes
// the displacement v of the loaded particle, `load` reads the force that
// holds it there. v grows by dv from 0, each state relaxed (to `tolerance`)
// from the last, until the load falls; then parabolas through three
// equilibria around the highest, their spacing quartered each time
// (`refinements` times), place the peak. Its load and v, and the work spent.
struct LimitPoint {
  double load = 0, displacement = 0;
  std::uint64_t steps = 0, force_evaluations = 0, relaxations = 0;
  double wall_ms = 0;
  bool converged = true;
};
LimitPoint find_limit(Solver& s, const std::function<void(double)>& set, const std::function<double()>& load,
                      double dv, double tolerance, std::uint64_t max_steps, int refinements = 3);

// Lee's frame (Lee, Manuel & Rossow 1968; the classic snap-through frame of
// Schweizerhof & Wriggers 1986, Simo et al.): a column of length L = 120 in
// from a pinned base at the origin up to the corner (0, L), and a beam of
// the same length from the corner to a pinned support at (L, L); E = 720
// kip/in^2, A = 6 in^2, I = 2 in^4 (EA = 4320 kip, EI = 1440 kip in^2; units
// in and kip). The corner is rigid (Model::set_joint Rigid with 3 DOF; 6-DOF
// beams share its frame). A load P down at 24 in from the corner on the
// beam, under displacement control: the limit load PL^2/EI = 18.56
// (kReference). n segments per member, a multiple of 5 (so a particle sits
// at the load); in the plane z = 0 (held in z; 6 DOF: rotations only about
// z).
struct LeeFrame {
  static constexpr double L = 120, EI = 1440, EA = 4320, kReference = 18.56;
  Model m;
  std::vector<ParticleId> column, girder;
  BlockId column_beam, girder_beam;
  ParticleId corner, loaded;
  LeeFrame(int n, int dofs, JointKind joint = JointKind::Rigid);
  void set_drop(double v);                 // the loaded particle held v below where it started [in]
  double load(const Solver& s) const;      // P [kip]: what holds it there
  LimitPoint limit(Solver& s);             // under displacement control
  static double error(const LimitPoint& p) { return std::abs(p.load * L * L / EI / kReference - 1); }
};

// Williams' toggle (Williams 1964): two straight members from clamped
// supports at x = 0 and x = 2a to the apex (a, h), a = 12.943 in, h = 0.386
// in, rigidly joined there (Model::set_joint Rigid with 3 DOF; 6-DOF beams
// share the apex's frame); E = 10.3e6 psi, a 0.753 x 0.243 in section (EA =
// E b d, EI = E b d^3 / 12; units in and lb). A load P down at the apex,
// under displacement control: the limit load 33.86 lb (kReference). 3 DOF:
// the supports held and clamped along their members (Model::set_clamp); 6
// DOF: fully locked. n segments per member; plane z = 0 as LeeFrame.
struct WilliamsToggle {
  static constexpr double a = 12.943, h = 0.386, E = 10.3e6, b = 0.753, d = 0.243, kReference = 33.86;
  static constexpr double EA = E * b * d, EI = E * b * d * d * d / 12;
  Model m;
  std::vector<ParticleId> left, right;
  BlockId left_beam, right_beam;
  ParticleId apex;
  int dofs;
  WilliamsToggle(int n, int dofs, JointKind joint = JointKind::Rigid);
  void set_drop(double v);
  double load(const Solver& s) const;  // P [lb]
  LimitPoint limit(Solver& s);
  static double error(const LimitPoint& p) { return std::abs(p.load / kReference - 1); }
};

}  // namespace tendril::validate
