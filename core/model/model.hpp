#pragma once
// The model: a generalized map whose 0-embedding is the particle buffer, the
// building blocks (connected components), and element buffers derived from
// both. Every primitive operation of thesis 4.2.7 patches only the darts,
// particles and elements it touches; rebuild_elements() recomputes all of
// them from the map and exists to check that claim (and to measure it).
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "model/elements.hpp"
#include "model/particles.hpp"
#include "model/types.hpp"
#include "topology/gmap.hpp"

namespace tendril {

// The rest shape of a beam (rest_shape.cpp): Straight, the bending-active
// default (a beam built curved is prestressed by bending), or Current: the
// shape it had when it was set is stress free (3-DOF hinges keep the rest
// curvature of their vertex, 6-DOF beam ends the rest frames of appendix
// A.2, fig. A.1b).
enum class RestShape : std::uint8_t { Straight, Current };
const char* rest_shape_name(RestShape r);  // "straight", "current"
bool parse_rest_shape(const std::string& name, RestShape& out);

// How two beams that share a particle are connected there (rigid_joints.cpp):
// Pinned, no moment crosses (what 3-DOF beams sharing a particle always
// were), or Rigid, the connection keeps its built angle and carries moment.
enum class JointKind : std::uint8_t { Pinned, Rigid };
const char* joint_kind_name(JointKind k);  // "pinned", "rigid"
bool parse_joint_kind(const std::string& name, JointKind& out);  // also "pin"

// A rigid joint of two 3-DOF beams at a shared particle (Model::set_joint):
// the segments of darts a and b (their darts at the particle) keep the
// included angle `angle`. mark_a, mark_b: the darts' rigid_mark when the
// joint was made; a dart freed and reused gets another, so a joint whose
// dart went is inert (no bookkeeping when darts go).
struct RigidJoint {
  Dart a = kNoDart, b = kNoDart;
  std::uint32_t mark_a = 0, mark_b = 0;
  double angle = 0;  // [rad], 0 .. pi
};

struct Block {
  BlockKind kind = BlockKind::Cable;
  bool closed = false;  // a beam ring
  RestShape rest = RestShape::Straight;  // beams
  // Beams: 3 (spline beam, bars and hinges, eq. 3.41-3.43) or 6 DOF per
  // particle (Beam6 elements, eq. 3.44-3.50). Other blocks: 3.
  std::uint8_t dofs = 3;
  Section section;
  Membrane membrane;  // patches: bars or CST (patch_formulations.cpp)
  // Patches: a uniform pressure [Pa] on the faces and the side it pushes
  // towards (zero: outward), pressure.cpp.
  double pressure = 0;
  Vec3 pressure_towards = Vec3::Zero();
  // Patches: a load [N/m^2] on the area projected on the plane normal to
  // its unit direction (snow: {0, 0, -1}), pressure.cpp.
  double area_load = 0;
  Vec3 area_load_direction = Vec3::Zero();
  Dart dart = kNoDart;  // any dart of the component
  std::size_t darts = 0;
  bool alive = false;
  std::uint32_t generation = 0;
};

// What a production created and deleted, collected while a change record is
// open (the journal's "created and deleted ids"), and the blocks whose darts
// it added, removed or moved to another particle (a beam grown by rule 9,
// the blocks rule 3 connects or rule 4 disconnects), in order of first touch.
struct ChangeSet {
  std::vector<ParticleId> created_particles, deleted_particles;
  std::vector<BlockId> created_blocks, deleted_blocks, changed_blocks;
  bool empty() const {
    return created_particles.empty() && deleted_particles.empty() && created_blocks.empty() &&
           deleted_blocks.empty() && changed_blocks.empty();
  }
};

// What a dart remembers of the particle it had before rule 3 merged it into
// another (thesis 6.2: "reverting the connection"): that particle's position
// relative to the merged one, its locks and the merged particle's locks at
// the merge. Rules 4 and 5 put the particle they make for the dart there.
struct MergeOrigin {
  Vec3 offset = Vec3::Zero();
  std::uint8_t lock = 0, merged_lock = 0;
  bool set = false;
};

class Model {
 public:
  Model();
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  // --- particles (rules 1-5) -------------------------------------------
  ParticleId add_particle(const Vec3& x);                    // rule 1
  void delete_particle(ParticleId p);                        // rule 2
  // Rule 3. Each dart remembers the particle it came from (MergeOrigin).
  ParticleId merge(const std::vector<ParticleId>& ps);
  // Rule 4: one particle per reference of p (references_of), in that order.
  // A reference that rule 3 brought to p returns to where its particle was
  // relative to p, with that particle's locks (locks set or cleared on p
  // since the merge apply to all): exploding a merge reverts it.
  std::vector<ParticleId> explode(ParticleId p);
  // Rule 5: detaches block b from p, on a particle of its own placed as rule
  // 4 places it. When b is all p holds (a beam joined to itself), detaches
  // b's last reference only: the loop opens at p.
  ParticleId explode_from(ParticleId p, BlockId b);

  // --- cables (rules 6-7) ----------------------------------------------
  // Rule 6. A rest length <= 0 takes the current distance.
  BlockId add_cable(ParticleId a, ParticleId b, const Section& s, double rest_length = 0);
  void delete_cable(BlockId b);                                       // rule 7
  // Rule 6 of kind "bar": a two-way elastic bar (BlockKind::Bar), the same
  // bar law (eq. 3.32) in compression as in tension (thesis 6.3.2, BAT02's
  // bars between the ring's quadrants). Rule 7 deletes it.
  BlockId add_elastic_bar(ParticleId a, ParticleId b, const Section& s, double rest_length = 0);
  void delete_elastic_bar(BlockId b);

  // --- beams (rules 8-18) ----------------------------------------------
  // Rule 8: a spline beam through existing particles (open path or ring).
  BlockId add_beam(const std::vector<ParticleId>& ps, const Section& s, bool closed = false);
  // Rule 10: from a particle along `span` (its full length) with n segments.
  BlockId add_beam_from(ParticleId start, const Vec3& span, int segments, const Section& s);
  // Rule 9: grows an open beam by one segment from its end particle `end` to
  // the particle `p` (rest length: their distance). extend.cpp.
  void extend_beam(BlockId b, ParticleId end, ParticleId p);
  // Rule 16 (split.cpp): breaks beam b at its interior particle p, on b alone
  // (not passive). A new particle q (same position, velocity, locks, frame)
  // takes the part after p in path order: a new open beam with b's section
  // and formulation, or, for a ring, the ring opens into one open beam that
  // starts at q and ends at p (the block returned is b). p's hinge goes.
  std::pair<ParticleId, BlockId> split_beam(BlockId b, ParticleId p);
  // The rest length of the beam (else cable) edge between consecutive
  // particles a and b: column, element and lumped masses. O(degree).
  void set_rest_length(ParticleId a, ParticleId b, double length);
  double edge_rest_length(ParticleId a, ParticleId b) const;
  ParticleId insert_particle(ParticleId a, ParticleId b);  // rule 13
  void remove_from_beam(ParticleId p);                     // rule 11
  void delete_beam(BlockId b);                              // rule 18

  // --- beam formulations (thesis 5.5.2.1), formulations.cpp ----------------
  // Switches a beam between 3 and 6 DOF per particle between steps, at a cost
  // proportional to the beam. 3 -> 6: node frames from the current polyline
  // by parallel transport, beam ends of every joint averaged (appendix A.2:
  // the pre-stress of an initially straight joint, so the beam keeps the
  // straight rest shape of its 3-DOF hinges); the twist reference is the
  // frame of the first rotation-locked particle on the beam (else appendix
  // A.1's global z), and every rotation-locked particle imposes its own
  // frame's twist on its beam end. Particles already on another 6-DOF beam
  // keep their frames. 6 -> 3: bars and hinges again; rotations drop.
  void set_beam_formulation(BlockId b, int dofs);
  int beam_formulation(BlockId b) const;
  // 6-DOF beams: the current shape becomes the rest shape (appendix A.1,
  // fig. A.1b, no pre-stress): every beam end along its element's chord,
  // rest lengths the current lengths. For analysing initially curved beams.
  // Also marks the beam's rest shape Current.
  void release_beam_prestress(BlockId b);

  // --- rest shape of beams (rest_shape.cpp) ----------------------------------
  // Current: the beam's shape now becomes its rest shape, 3 or 6 DOF: rest
  // lengths the current lengths; 3-DOF hinges the current curvature of their
  // vertex (eq. 3.41's 2 sin(alpha) / Lc); 6-DOF beam ends along their
  // chords (release_beam_prestress). Straight: every vertex straight at rest
  // again (hinges 0; 6-DOF joints share one beam end, A.4, averaged from the
  // two they had); rest lengths stay. Set again, Current takes the shape of
  // that moment. Switching 3 <-> 6 DOF keeps a Current rest shape: the
  // turning angle of the rest polygon at each vertex goes from the hinge's
  // rest curvature to the two beam ends and back. Rules keep a curved rest
  // shape: rule 13 gives the new vertex the mean rest curvature of its two
  // neighbours (theirs stay, so a refined arc keeps its radius; 6-DOF:
  // unchanged, the element is split at its cubic's middle), rule 9 on a
  // Current beam takes the joint it makes as it is (no prestress), rules 11
  // and 16 leave the other vertices as they were.
  void set_rest_shape(BlockId b, RestShape r);
  RestShape rest_shape(BlockId b) const;

  // --- clamps of 3-DOF beam ends (clamps.cpp) ------------------------------
  // A clamp fixes the tangent of beam b at its end particle p: a hinge
  // between the end segment and the fixed unit `direction` (pointing into
  // the beam; zero: along the end segment now), with M = 2 EI sin(alpha) /
  // L1 (alpha the angle between them, L1 the segment's length): the end
  // vertex owns half of its segment, so twice an interior hinge's stiffness,
  // and a circle through the particles is exact. It is a moment on the
  // beam only (p's locks hold it in place or not); straight at rest. A
  // 3-DOF boundary condition: refused on 6-DOF beams (lock the end's
  // rotations), kept while a beam switches to 6 DOF and back, inert
  // meanwhile. The clamp goes with its end (rules 11, 18); rule 9 refuses
  // to grow a clamped end.
  void set_clamp(ParticleId p, BlockId b, const Vec3& direction = Vec3::Zero());
  void remove_clamp(ParticleId p, BlockId b);
  bool clamped(ParticleId p, BlockId b, Vec3* direction = nullptr) const;
  // Whether dart d carries a clamp that acts now (a live end dart of a
  // 3-DOF beam with a direction).
  bool clamp_acts(Dart d) const;

  // --- joints between members (rigid_joints.cpp) ---------------------------
  // Where beams a and b share particle p, their connection is pinned (the
  // default: no moment crosses) or rigid: the segment of a and the segment
  // of b at p keep their included angle (`angle` in 0 .. pi; negative: the
  // angle they make now, as built) and carry moment across the joint like a
  // hinge (physics/element_forces.hpp: rigid_joint_forces). A joint acts on
  // a's end segment when p is an end of a, else on a's segment towards its
  // neighbour with the smaller id (moment crosses either way; the beam
  // carries it on); a == b joins the two ends of one beam that meet at p.
  // 3-DOF beams: both must be 3 DOF to be made rigid; 6-DOF beams sharing a
  // particle share its frame and are rigid there already (Pinned refused).
  // A rigid joint is kept while a beam switches formulation (inert unless
  // both are 3 DOF), moves with merges of its particle, and goes when its
  // end segment does (rules 4, 5, 11, 18) or its darts part.
  void set_joint(ParticleId p, BlockId a, BlockId b, JointKind kind, double angle = -1);
  JointKind joint_kind(ParticleId p, BlockId a, BlockId b, double* angle = nullptr) const;
  // Whether the joint acts now (both darts live and its own, at one particle,
  // two 3-DOF beams), and its rotational stiffness: half of each end
  // segment in series, 1 / (La / 2 EIa + Lb / 2 EIb) (rest lengths), the
  // stiffness of a hinge at an interior vertex of one beam.
  bool rigid_acts(const RigidJoint& j) const;
  // Whether the joint is still made (its darts live, its own, at one
  // particle), acting or not (a beam switched to 6 DOF): what is saved.
  bool rigid_joined(const RigidJoint& j) const;
  // The model database: a rigid joint of the segments p -> a_to of beam a
  // and p -> b_to of beam b, at `angle`, as saved.
  void set_rigid_joint(ParticleId p, BlockId a, ParticleId a_to, BlockId b, ParticleId b_to, double angle);
  double rigid_stiffness(const RigidJoint& j) const;
  // Every rigid joint made since (rigid_acts tells which still act).
  LoggedVector<RigidJoint> rigid_joints;

  // --- patches: a quad grid built by hand until meshing lands -------------
  // grid[r * cols + c] are existing particles; quads are sewn by alpha2 and
  // every edge carries a bar with the given section.
  BlockId add_quad_grid(const std::vector<ParticleId>& grid, int rows, int cols, const Section& s);
  // A patch from quads of existing particles (corners in order around each
  // quad). Quads sharing an edge are sewn by alpha2; the quads must form one
  // piece with every edge in at most two quads. Used by the meshing layer.
  using Quad = std::array<ParticleId, 4>;
  BlockId add_patch(const std::vector<Quad>& quads, const Section& s);
  void delete_patch(BlockId b);                   // rule 27: darts, bars, isolated particles (patch_ops.cpp)
  void remove_from_patch(ParticleId p);           // rule 23: a simple particle and its quads; splits the rest
  BlockId merge_patches(BlockId a, BlockId b);    // rule 26: sews b onto a along common boundary edges; returns a

  // --- patch formulations (thesis 5.5.2.2), patch_formulations.cpp --------
  // Switches a patch between elastic bars and constant strain triangles
  // between steps, at a cost proportional to the patch; the map (its quads)
  // does not change. In CST mode the bars of the interior edges go and the
  // triangles carry the membrane; the boundary edges keep their bars: they
  // are the edge cables a CST membrane needs (thesis 3.2.8.2), and the
  // patch's boundary behaves the same in both formulations. The triangles
  // come from the meshing layer (edge classification, fig. 5.30): two per
  // quad, (a, b, c) and (c, d, a) for its corners a, b, c, d in order round
  // the quad, side a-b along the warp. Mode Bars takes no triangles and
  // restores the interior bars with their rest lengths. Analysis mode takes
  // each triangle's reference geometry from the current positions, or from
  // `reference` (one per triangle, the model database). Switching a CST
  // patch again (form-finding -> analysis) replaces its triangles.
  // Topology rules that rewrite a CST patch's quads (remove_from_patch,
  // merge_patches, subdivision) refuse: switch it back to bars first.
  // delete_patch, and merge / explode of its particles, keep it consistent.
  using Triangle = std::array<ParticleId, 3>;
  void set_patch_formulation(BlockId b, const Membrane& m, const std::vector<Triangle>& triangles = {},
                             const std::vector<CstReference>* reference = nullptr);
  const Membrane& patch_formulation(BlockId b) const;

  // --- pressure on patches (pressure.cpp) -----------------------------------
  // A uniform pressure p [Pa] on every quad of patch b, along its normal
  // (a follower load: it turns with the faces). The quads are oriented
  // alike over the patch, then as a whole: towards `towards` (the sum of
  // the quads' area vectors has a positive component along it) when it is
  // not zero, else outward (the area vectors point away from the patch's
  // centroid: a cushion, a tube or a dome inflates); p > 0 pushes that
  // way, p < 0 sucks. Where the measure is zero (a flat patch, outward) the
  // quads' own order decides. Refused on a non-orientable patch.
  void set_pressure(BlockId b, double p, const Vec3& towards = Vec3::Zero());
  // The patch's quads, oriented as the pressure acts (corners in order, the
  // normal of (c - a) x (d - b)); empty when the patch has no pressure.
  std::vector<Quad> pressure_quads(BlockId b) const;
  // A load q [N/m^2] on patch b per area projected along `direction` (any
  // non-zero vector, kept as a unit vector), acting along it: snow on the
  // plan area is q with {0, 0, -1}. A dead load in direction, its size
  // following the projected area as the patch moves: a quad's corners take
  // q |A . d| / 4 each (A its area vector). 0 removes it.
  void set_area_load(BlockId b, double q, const Vec3& direction);
  // The quads of a patch under an area load (empty without one).
  std::vector<Quad> area_load_quads(BlockId b) const;
  // Warp and weft prestress of a patch's bars [N] (issue 11; the bar
  // counterpart of a CST patch's warp and weft stresses): every edge listed
  // in warp_edges takes `warp`, in weft_edges `weft`, one in both (a seam
  // of the edge classification, where the yarns turn) their mean. Every
  // edge of the patch must be listed; checked before anything changes.
  // The values live on the edges (edge_prestress), so bars a switch to CST
  // removes come back with them. edge_prestress.cpp.
  using EdgePair = std::array<ParticleId, 2>;
  void set_patch_prestress(BlockId b, double warp, double weft, const std::vector<EdgePair>& warp_edges,
                           const std::vector<EdgePair>& weft_edges);
  // The prestress a bar on edge d carries: the edge's own when it has one,
  // else its block's section prestress.
  double bar_prestress(Dart d) const;
  // The CST triangles of a patch (empty in bars mode) and their references,
  // in dart order.
  std::vector<Triangle> patch_triangles(BlockId b, std::vector<CstReference>* reference = nullptr) const;
  bool is_cst_patch(BlockId b) const { return blocks[b].kind == BlockKind::Patch && blocks[b].membrane.cst(); }

  // --- constraints and loads --------------------------------------------
  void set_lock(ParticleId p, std::uint8_t bits);
  // Multi-resolution (thesis 5.5.2.3): a passive particle is frozen (its
  // velocity, force and torque zeroed) and every element touching it goes
  // dormant: neither is visited by a solver step. O(degree).
  void set_passive(ParticleId p, bool passive);
  void set_load(ParticleId p, const Vec3& f);
  void set_point_mass(ParticleId p, double kg);
  void set_role(ParticleId p, Role r);
  // Rotational joints (thesis 6.5.2): at a particle where exactly two beams
  // cross (four neighbours), drive the angle between them. joints.cpp.
  std::size_t add_joint(ParticleId p, double angle, double stiffness);
  void set_joint_angle(std::size_t joint, double angle);
  // The four neighbours (a1, a2 on one beam, b1, b2 on the other), or false
  // when the particle is not a crossing of two beams any more.
  bool joint_neighbours(ParticleId p, ParticleId out[4]) const;
  // The node frame of p; on a 6-DOF beam its beam ends turn with it. Must be
  // a rotation (normalised here).
  void set_orientation(ParticleId p, const Quat& q);
  // External moment [N m]. On a particle with rotations (a 6-DOF beam) a
  // torque; on one without, the equivalent force couples across its 3-DOF
  // beam segments (physics/couples.cpp). Refused on a particle in no beam
  // (a zero moment is always taken).
  void set_moment(ParticleId p, const Vec3& m);
  std::uint64_t moment_revision = 0;  // moves whenever set_moment is called
  // Goals (elements.hpp, goals.cpp): validated (live particles, finite
  // vectors, a non-zero normal or direction (kept as given), a length >= 0,
  // a weight > 0) before anything changes; returns its index. A goal goes
  // with its particles (delete, merge, explode): remove_goal shifts the later
  // indices down by one.
  std::size_t add_goal(Goal g);
  void check_rigid_members(Goal& g, const std::string& fn) const;  // goals.cpp
  void remove_goal(std::size_t index);
  void set_goal_weight(std::size_t index, double weight);
  Vec3 gravity = Vec3::Zero();

  // --- queries -----------------------------------------------------------
  State state(ParticleId p) const;
  std::vector<BlockId> blocks_of(ParticleId p) const;  // distinct, ascending
  // One block per reference of p (thesis 6.3.1: "cross-references to
  // multiple elements, and/or multiple references to the same element"): a
  // reference is a vertex orbit of the map, so a beam whose ends a loop
  // joins at p is there twice. Ascending. Two or more make p shared.
  std::vector<BlockId> references_of(ParticleId p) const;
  std::vector<ParticleId> particles_of(BlockId b) const;  // path order for beams/cables
  bool particle_valid(ParticleId p) const { return particles.valid(p); }
  bool block_valid(BlockId b) const { return b < blocks.size() && blocks[b].alive; }
  std::size_t particle_count() const { return particles.live; }
  std::size_t block_count() const { return live_blocks_; }
  std::size_t block_count(BlockKind k) const;
  std::vector<BlockId> live_blocks() const;

  // --- invariants -----------------------------------------------------------
  // Map validity, embeddings, block bookkeeping, and element buffers equal to
  // a fresh rebuild from the map. Empty when valid, else the first violation.
  std::string check() const;
  // The same checks, around the given particles only (their darts, edges and
  // hinges): what a production validates, at a cost independent of the model.
  std::string check_near(const std::vector<ParticleId>& ps) const;
  // Recomputes every element buffer from the map (the approach thesis 6.1
  // criticises; kept to check the local patches and to benchmark them).
  void rebuild_elements();

  // --- transactions (DESIGN principle 2) --------------------------------------
  // Between begin and commit every change is logged; rollback restores the
  // model exactly (topology, positions, velocities, element parameters) at a
  // cost proportional to what changed.
  void begin_transaction() { map.undo_log().begin(); }
  void commit_transaction() { map.undo_log().commit(); }
  void rollback_transaction() {
    map.undo_log().rollback();
    ++revision;
  }
  bool in_transaction() { return map.undo_log().recording(); }

  // While `changes` points somewhere, particle and block creation and
  // deletion are appended to it.
  ChangeSet* changes = nullptr;

  // Moves whenever elements, embeddings, locks, passivity, point masses or
  // rest lengths may have changed (never goes back, not even on rollback):
  // a solver that caches a factorisation compares it in O(1) per step.
  std::uint64_t revision = 0;

  // How far the model has been integrated: steps and simulated time [s]
  // over every run and solver, kept by the model database (a loaded model
  // goes on counting); not undone by rollback (steps are not productions).
  std::uint64_t steps = 0;
  double time = 0;

  GMap map;
  Particles particles;
  LoggedVector<Block> blocks;
  ElementBuffer<Bar> bars;
  ElementBuffer<Hinge> hinges;
  ElementBuffer<Beam6> beam6s;
  ElementBuffer<RotationalJoint> joints;  // joints.cpp
  LoggedVector<Goal> goals;               // goals.cpp
  ElementBuffer<Cst> csts;                // patches in CST mode

  // Per-dart columns: 0-embedding, owning block, element references, and the
  // ring of darts embedding the same particle.
  DartColumn<ParticleId>& dart_particle;
  DartColumn<BlockId>& dart_block;
  DartColumn<ElementIndex>& dart_bar;
  DartColumn<ElementIndex>& dart_hinge;
  DartColumn<Dart>& ring_next;
  DartColumn<Dart>& ring_prev;
  DartColumn<double>& rest_length;  // per edge: the bar's rest length [m]
  // Per edge: a patch bar's own prestress [N] (set_patch_prestress); NaN:
  // the block's section prestress.
  DartColumn<double>& edge_prestress;
  DartColumn<ElementIndex>& dart_beam6;
  // Per dart of a 6-DOF beam edge: the beam end at the dart's particle,
  // relative to that particle's frame, its x axis looking along the edge away
  // from the particle (see end_flip). Kept (unused) while the beam is 3 DOF.
  DartColumn<Quat>& beam_end;
  // CST patches: cst_first marks the dart at the first corner of a triangle
  // on its warp side (model state: the triangulation), cst_reference holds
  // that triangle's reference geometry, dart_cst its element.
  DartColumn<std::uint8_t>& cst_first;
  DartColumn<CstReference>& cst_reference;
  DartColumn<ElementIndex>& dart_cst;
  DartColumn<MergeOrigin>& merge_origin;  // rules 3-5 (operations.cpp)
  // Per dart of a beam vertex (both darts alike): the rest curvature [1/m]
  // its 3-DOF hinge takes (Hinge::rest_curvature), 0 when straight at rest.
  // Kept (unused) while the beam is 6 DOF. rest_shape.cpp.
  DartColumn<double>& rest_curvature;
  // Per end dart of a beam: the clamp's fixed unit tangent into the beam,
  // zero when unclamped (clamps.cpp); clamp_darts every dart clamped since
  // (clamp_acts tells which still are): what the solver walks.
  DartColumn<Vec3>& clamp;
  LoggedVector<Dart> clamp_darts;
  // Per dart in a rigid joint: a stamp no other dart had (RigidJoint), 0 when
  // in none.
  DartColumn<std::uint32_t>& rigid_mark;

  void require_particle(ParticleId p, const char* what) const;
  void require_block(BlockId b, const char* what) const;

 private:
  ParticleId new_particle(const Vec3& x);
  void free_particle(ParticleId p);
  void remove_goals_of(ParticleId p);  // goals.cpp
  BlockId new_block(BlockKind k, Section s, bool closed);
  BlockId add_link(BlockKind k, ParticleId a, ParticleId b, const Section& s, double rest, const char* fn);  // by value: s may live in `blocks`
  void free_block(BlockId b);
  Dart new_dart(BlockId b, ParticleId p);
  void free_dart(Dart d);
  void embed(Dart d, ParticleId p);
  void unembed(Dart d);
  // Edge d-alpha0(d) with a bar; vertex hinge at a beam vertex d-alpha1(d).
  void set_edge_rest_length(Dart d, double length);
  void add_bar(Dart d);  // parameters from the block's section and the edge
  void remove_bar(Dart d);
  void bind_bar(ElementIndex e);    // reads i, j from the map, then place_bar
  void unbind_bar(ElementIndex e);  // unlumps its mass if awake
  // Element partition (ElementBuffer): moves the element to the awake or
  // dormant side as its particles' passive flags ask, lumping its mass when
  // awake; repoint_* re-point the dart column of the element at an index.
  void place_bar(ElementIndex e);
  void repoint_bar(ElementIndex e);
  void place_hinge(ElementIndex h);
  void repoint_hinge(ElementIndex h);
  void place_beam6(ElementIndex e);
  void repoint_beam6(ElementIndex e);
  void unlump_beam6(ElementIndex e);
  void add_hinge(Dart d);
  void remove_hinge(Dart d);
  void refresh_hinge(Dart d);  // re-reads i, j, k of the hinge at vertex d, if any
  void refresh_vertex(Dart d);  // after re-embedding d: its bar and nearby hinges
  void add_beam6(Dart d);
  void remove_beam6(Dart d);
  void bind_beam6(ElementIndex e);
  void unbind_beam6(ElementIndex e);
  void refresh_beam6(Dart d);  // re-reads rest length and beam ends of the edge of d
  // The element of an edge and of a beam vertex as the block's formulation
  // asks: a bar or a Beam6; a hinge on 3-DOF beams only.
  bool six_dof(Dart d) const;
  void add_edge_element(Dart d);
  void remove_edge_element(Dart d);
  void add_vertex_element(Dart d);
  void init_beam_frames(BlockId b);          // formulations.cpp
  // rest_shape.cpp: a Current beam switching formulation. 3 -> 6: turns the
  // two beam ends of each joint apart by the rest turning angle of its
  // hinge; 6 -> 3: the hinges' rest curvatures from the beam ends.
  void tilt_rest_ends(BlockId b);
  void rest_curvature_from_ends(BlockId b);
  void set_vertex_rest_curvature(Dart d, double kappa);  // both darts of the vertex and its hinge
  std::vector<Dart> path_darts(BlockId b) const;  // per segment, its dart at the start node
  // CST elements (patch_formulations.cpp): one per dart marked cst_first.
  void add_cst(Dart d);
  void remove_cst(Dart d);
  void bind_cst(ElementIndex e);     // particles from the dart's face, then place_cst
  void place_cst(ElementIndex e);    // awake or dormant side (ElementBuffer)
  void refresh_csts(Dart d);         // after re-embedding d: the triangles of its face
  bool edge_has_bar(Dart d) const;   // not an interior edge of a CST patch
  std::string check_cst_face(Dart d) const;
  // Moves dart d from its particle to q, keeping its beam end where it was.
  void rehome_dart(Dart d, ParticleId q);
  std::string check_dart(Dart d) const;
  std::string check_beam6(Dart d) const;
  std::string check_rotation(ParticleId p) const;
  std::string check_integrated(ParticleId p) const;
  Dart find_edge(ParticleId a, ParticleId b, BlockKind k) const;
  std::vector<Dart> darts_of(ParticleId p) const;
  // p's darts grouped by reference (vertex orbit), ordered by block, then by
  // the smallest dart of the group.
  std::vector<std::vector<Dart>> reference_groups(ParticleId p) const;
  // A particle at p for the darts `group` leave it by (rules 4, 5): placed
  // and locked as MergeOrigin says; the darts move to it and forget.
  ParticleId detach(ParticleId p, const std::vector<Dart>& group, bool first);
  void delete_component(BlockId b);
  Vec3 pos(Dart d) const { return particles.position[dart_particle[d]]; }
  std::size_t live_blocks_ = 0;
  std::uint32_t rigid_stamp_ = 0;  // the last rigid_mark given (never reused)
  // rigid_joints.cpp: the dart of beam b a joint at p acts on (`skip`: the
  // one already taken when both are of b), the included angle of two
  // darts' segments now, and the live joint of two darts (else size()).
  Dart joint_dart(ParticleId p, BlockId b, Dart skip, const char* fn) const;
  double joint_angle_now(Dart a, Dart b) const;
  std::size_t find_rigid(Dart a, Dart b) const;
  void make_rigid(Dart a, Dart b, double angle);  // or sets the angle of the joint they make
  LoggedVector<BlockId> free_blocks_;
};

}  // namespace tendril
