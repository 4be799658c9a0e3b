// Model bookkeeping: blocks, darts, embeddings and element buffers. The rules
// themselves live in operations.cpp; the invariant check in model_check.cpp.
#include "model/model.hpp"

#include "model/frames.hpp"

#include <algorithm>
#include <cmath>

namespace tendril {

Model::Model()
    : dart_particle(map.add_column<ParticleId>(kNone)),
      dart_block(map.add_column<BlockId>(kNone)),
      dart_bar(map.add_column<ElementIndex>(kNone)),
      dart_hinge(map.add_column<ElementIndex>(kNone)),
      ring_next(map.add_column<Dart>(kNoDart)),
      ring_prev(map.add_column<Dart>(kNoDart)),
      rest_length(map.add_column<double>(0.0)),
      edge_prestress(map.add_column<double>(std::numeric_limits<double>::quiet_NaN())),
      dart_beam6(map.add_column<ElementIndex>(kNone)),
      beam_end(map.add_column<Quat>(Quat::Identity())),
      cst_first(map.add_column<std::uint8_t>(0)),
      cst_reference(map.add_column<CstReference>(CstReference{})),
      dart_cst(map.add_column<ElementIndex>(kNone)),
      merge_origin(map.add_column<MergeOrigin>(MergeOrigin{})),
      rest_curvature(map.add_column<double>(0.0)),
      clamp(map.add_column<Vec3>(Vec3::Zero())),
      rigid_mark(map.add_column<std::uint32_t>(0)) {
  UndoLog* log = &map.undo_log();
  particles.attach(log);
  blocks.attach(log);
  free_blocks_.attach(log);
  bars.attach(log);
  hinges.attach(log);
  beam6s.attach(log);
  joints.items.attach(log);
  goals.attach(log);
  csts.attach(log);
  clamp_darts.attach(log);
  rigid_joints.attach(log);
}

void Model::require_particle(ParticleId p, const char* what) const {
  if (!particles.valid(p))
    throw ModelError(std::string(what) + ": particle " + std::to_string(p) + " does not exist (deleted?)");
}

void Model::require_block(BlockId b, const char* what) const {
  if (!block_valid(b))
    throw ModelError(std::string(what) + ": block " + std::to_string(b) + " does not exist (deleted?)");
}

ParticleId Model::new_particle(const Vec3& x) {
  ParticleId p = particles.allocate(x);
  if (changes) changes->created_particles.push_back(p);
  return p;
}

void Model::free_particle(ParticleId p) {
  remove_goals_of(p);
  particles.release(p);
  if (!changes) return;
  // A particle born and gone within one record never existed for the journal.
  auto& born = changes->created_particles;
  if (auto it = std::find(born.begin(), born.end(), p); it != born.end()) born.erase(it);
  else changes->deleted_particles.push_back(p);
}

BlockId Model::new_block(BlockKind k, Section s, bool closed) {
  BlockId b;
  if (!free_blocks_.empty()) {
    b = free_blocks_.back();
    free_blocks_.pop_back();
  } else {
    b = static_cast<BlockId>(blocks.size());
    blocks.push_back(Block{});
  }
  Block& blk = blocks[b];
  blk.kind = k;
  blk.closed = closed;
  blk.rest = RestShape::Straight;
  blk.dofs = 3;
  blk.membrane = Membrane{};
  blk.section = s;
  blk.dart = kNoDart;
  blk.darts = 0;
  blk.alive = true;
  map.undo_log().scalar(live_blocks_);
  ++live_blocks_;
  if (changes) changes->created_blocks.push_back(b);
  return b;
}

void Model::free_block(BlockId b) {
  blocks[b].alive = false;
  blocks[b].dart = kNoDart;
  ++blocks[b].generation;
  free_blocks_.push_back(b);
  map.undo_log().scalar(live_blocks_);
  --live_blocks_;
  if (changes) {
    auto& born = changes->created_blocks;
    if (auto it = std::find(born.begin(), born.end(), b); it != born.end()) born.erase(it);
    else changes->deleted_blocks.push_back(b);
  }
}

Dart Model::new_dart(BlockId b, ParticleId p) {
  Dart d = map.create_dart();
  dart_block[d] = b;
  embed(d, p);
  if (blocks[b].dart == kNoDart) blocks[b].dart = d;
  ++blocks[b].darts;
  return d;
}

void Model::free_dart(Dart d) {
  for (int i = 0; i < 3; ++i) map.unlink(i, d);
  BlockId b = dart_block[d];
  unembed(d);
  --blocks[b].darts;
  if (blocks[b].dart == d) blocks[b].dart = kNoDart;
  map.delete_dart(d);
}

namespace {
void note_changed(ChangeSet* changes, BlockId b) {
  if (!changes) return;
  auto& v = changes->changed_blocks;
  if (std::find(v.begin(), v.end(), b) == v.end()) v.push_back(b);
}
}  // namespace

void Model::embed(Dart d, ParticleId p) {
  ++revision;
  note_changed(changes, dart_block[d]);
  dart_particle[d] = p;
  Dart head = particles.first_dart[p];
  if (head == kNone) {
    particles.first_dart[p] = d;
    ring_next[d] = ring_prev[d] = d;
  } else {
    Dart last = ring_prev[head];
    ring_next[last] = d;
    ring_prev[d] = last;
    ring_next[d] = head;
    ring_prev[head] = d;
  }
  ++particles.degree[p];
  particles.refresh_active(p);
}

void Model::unembed(Dart d) {
  ++revision;
  note_changed(changes, dart_block[d]);
  ParticleId p = dart_particle[d];
  Dart n = ring_next[d], pr = ring_prev[d];
  if (n == d) {
    particles.first_dart[p] = kNone;
  } else {
    ring_next[pr] = n;
    ring_prev[n] = pr;
    if (particles.first_dart[p] == d) particles.first_dart[p] = n;
  }
  ring_next[d] = ring_prev[d] = kNoDart;
  dart_particle[d] = kNone;
  --particles.degree[p];
  particles.refresh_active(p);
}

std::vector<Dart> Model::darts_of(ParticleId p) const {
  std::vector<Dart> out;
  Dart head = particles.first_dart[p];
  if (head == kNone) return out;
  Dart d = head;
  do {
    out.push_back(d);
    d = ring_next[d];
  } while (d != head);
  return out;
}

// --- bars --------------------------------------------------------------------

void Model::set_edge_rest_length(Dart d, double length) {
  ++revision;
  map.for_orbit(kEdgeOrbit, d, [&](Dart x) {
    rest_length[x] = length;
    return true;
  });
}

void Model::add_bar(Dart d) {
  const Block& blk = blocks[dart_block[d]];
  ElementIndex e = static_cast<ElementIndex>(bars.size());
  Bar bar{};
  bar.rest_length = rest_length[d];
  bar.EA = blk.section.EA;
  bar.prestress = bar_prestress(d);
  bar.line_mass = blk.section.line_mass;
  bar.tension_only = blk.kind == BlockKind::Cable;
  bar.dart = d;
  bars.items.push_back(bar);
  map.for_orbit(kEdgeOrbit, d, [&](Dart x) {
    dart_bar[x] = e;
    return true;
  });
  bind_bar(e);
}

// An element is awake when none of its particles is passive (thesis
// 5.5.2.3: the elements of passive particles leave the computation); only
// awake elements lump their mass.
void Model::bind_bar(ElementIndex e) {
  ++revision;
  Bar& bar = bars[e];
  bar.i = dart_particle[bar.dart];
  bar.j = dart_particle[map.alpha(0, bar.dart)];
  place_bar(e);
}

void Model::place_bar(ElementIndex e) {
  const Bar& bar = std::as_const(bars)[e];
  const bool wake = !particles.passive[bar.i] && !particles.passive[bar.j];
  e = bars.place(e, wake, [this](ElementIndex k) { repoint_bar(k); });
  if (e >= bars.awake) return;
  const Bar& b = std::as_const(bars)[e];
  double half = 0.5 * b.line_mass * b.rest_length;
  particles.add_lumped_mass(b.i, half);
  particles.add_lumped_mass(b.j, half);
}

void Model::repoint_bar(ElementIndex e) {
  map.for_orbit(kEdgeOrbit, std::as_const(bars)[e].dart, [&](Dart x) {
    dart_bar[x] = e;
    return true;
  });
}

void Model::unbind_bar(ElementIndex e) {
  ++revision;
  if (e >= bars.awake) return;
  const Bar& bar = std::as_const(bars)[e];
  double half = 0.5 * bar.line_mass * bar.rest_length;
  particles.add_lumped_mass(bar.i, -half);
  particles.add_lumped_mass(bar.j, -half);
}

void Model::remove_bar(Dart d) {
  ElementIndex e = dart_bar[d];
  if (e == kNone) return;
  unbind_bar(e);
  const Dart gone = std::as_const(bars)[e].dart;
  bars.erase(e, [this](ElementIndex k) { repoint_bar(k); });  // re-points gone's edge on the way
  map.for_orbit(kEdgeOrbit, gone, [&](Dart x) {
    dart_bar[x] = kNone;
    return true;
  });
}

// --- hinges ------------------------------------------------------------------

void Model::add_hinge(Dart d) {
  ++revision;
  Dart e = map.alpha(1, d);
  ElementIndex h = static_cast<ElementIndex>(hinges.size());
  Hinge hinge{};
  hinge.EI = blocks[dart_block[d]].section.EI;
  hinge.rest_curvature = rest_curvature[d];
  hinge.dart = d;
  hinges.items.push_back(hinge);
  dart_hinge[d] = dart_hinge[e] = h;
  refresh_hinge(d);
}

void Model::remove_hinge(Dart d) {
  ++revision;
  ElementIndex h = dart_hinge[d];
  if (h == kNone) return;
  const Dart hd = std::as_const(hinges)[h].dart;
  hinges.erase(h, [this](ElementIndex k) { repoint_hinge(k); });
  dart_hinge[hd] = dart_hinge[map.alpha(1, hd)] = kNone;
}

void Model::repoint_hinge(ElementIndex h) {
  const Dart hd = std::as_const(hinges)[h].dart;
  dart_hinge[hd] = dart_hinge[map.alpha(1, hd)] = h;
}

void Model::refresh_hinge(Dart d) {
  ++revision;
  ElementIndex h = dart_hinge[d];
  if (h == kNone) return;
  Hinge& hinge = hinges[h];
  Dart hd = hinge.dart;
  hinge.i = dart_particle[map.alpha(0, hd)];
  hinge.j = dart_particle[hd];
  hinge.k = dart_particle[map.alpha(0, map.alpha(1, hd))];
  place_hinge(h);
}

void Model::place_hinge(ElementIndex h) {
  const Hinge& hg = std::as_const(hinges)[h];
  const bool wake = !particles.passive[hg.i] && !particles.passive[hg.j] && !particles.passive[hg.k];
  hinges.place(h, wake, [this](ElementIndex k) { repoint_hinge(k); });
}

void Model::refresh_vertex(Dart d) {
  ElementIndex e = dart_bar[d];
  if (e != kNone) {
    unbind_bar(e);
    bind_bar(e);
  }
  e = dart_beam6[d];
  if (e != kNone) {
    unbind_beam6(e);
    bind_beam6(e);
  }
  refresh_hinge(d);
  refresh_hinge(map.alpha(0, d));
  refresh_csts(d);
}

// --- 6-DOF beam elements -------------------------------------------------------

void Model::add_beam6(Dart d) {
  const Section& s = blocks[dart_block[d]].section;
  ElementIndex e = static_cast<ElementIndex>(beam6s.size());
  Beam6 b{};
  b.rest_length = rest_length[d];
  b.EA = s.EA;
  b.EIy = s.bending_y();
  b.EIz = s.bending_z();
  b.GJ = s.torsion();
  b.prestress = s.prestress;
  b.line_mass = s.line_mass;
  b.dart = d;
  beam6s.items.push_back(b);
  map.for_orbit(kEdgeOrbit, d, [&](Dart x) {
    dart_beam6[x] = e;
    return true;
  });
  bind_beam6(e);
}

void Model::bind_beam6(ElementIndex e) {
  ++revision;
  Beam6& b = beam6s[e];
  const Dart other = map.alpha(0, b.dart);
  b.i = dart_particle[b.dart];
  b.j = dart_particle[other];
  b.end_i = beam_end[b.dart];
  b.end_j = Quat(beam_end[other] * end_flip());  // turned to look from i to j
  particles.add_rotational_end(b.i);
  particles.add_rotational_end(b.j);
  place_beam6(e);
}

void Model::place_beam6(ElementIndex e) {
  const Beam6& el = std::as_const(beam6s)[e];
  const bool wake = !particles.passive[el.i] && !particles.passive[el.j];
  e = beam6s.place(e, wake, [this](ElementIndex k) { repoint_beam6(k); });
  if (e >= beam6s.awake) return;
  const Beam6& b = std::as_const(beam6s)[e];
  const double half = 0.5 * b.line_mass * b.rest_length;
  particles.add_lumped_mass(b.i, half);
  particles.add_lumped_mass(b.j, half);
}

void Model::repoint_beam6(ElementIndex e) {
  map.for_orbit(kEdgeOrbit, std::as_const(beam6s)[e].dart, [&](Dart x) {
    dart_beam6[x] = e;
    return true;
  });
}

void Model::unlump_beam6(ElementIndex e) {
  ++revision;
  if (e >= beam6s.awake) return;
  const Beam6& b = std::as_const(beam6s)[e];
  const double half = 0.5 * b.line_mass * b.rest_length;
  particles.add_lumped_mass(b.i, -half);
  particles.add_lumped_mass(b.j, -half);
}

void Model::unbind_beam6(ElementIndex e) {
  unlump_beam6(e);
  const Beam6& b = std::as_const(beam6s)[e];
  particles.remove_rotational_end(b.i);
  particles.remove_rotational_end(b.j);
}

void Model::remove_beam6(Dart d) {
  ElementIndex e = dart_beam6[d];
  if (e == kNone) return;
  unbind_beam6(e);
  const Dart gone = std::as_const(beam6s)[e].dart;
  beam6s.erase(e, [this](ElementIndex k) { repoint_beam6(k); });
  map.for_orbit(kEdgeOrbit, gone, [&](Dart x) {
    dart_beam6[x] = kNone;
    return true;
  });
}

void Model::refresh_beam6(Dart d) {
  ElementIndex e = dart_beam6[d];
  if (e == kNone) return;
  unbind_beam6(e);
  beam6s[e].rest_length = rest_length[beam6s[e].dart];
  bind_beam6(e);
}

bool Model::six_dof(Dart d) const {
  const Block& b = blocks[dart_block[d]];
  return b.kind == BlockKind::Beam && b.dofs == 6;
}

void Model::add_edge_element(Dart d) {
  if (six_dof(d)) add_beam6(d);
  else add_bar(d);
}

void Model::remove_edge_element(Dart d) {
  remove_bar(d);
  remove_beam6(d);
}

void Model::add_vertex_element(Dart d) {
  if (blocks[dart_block[d]].kind == BlockKind::Beam && !six_dof(d) && !map.is_free(1, d)) add_hinge(d);
}

void Model::rehome_dart(Dart d, ParticleId q) {
  const ParticleId p = dart_particle[d];
  if (dart_beam6[d] != kNone && p != q)  // the beam end stays put in global terms
    beam_end[d] = Quat(particles.orientation[q].conjugate() * particles.orientation[p] * beam_end[d]).normalized();
  unembed(d);
  embed(d, q);
  refresh_vertex(d);
}

// --- full rebuild ------------------------------------------------------------

void Model::rebuild_elements() {
  bars.clear();
  hinges.clear();
  beam6s.clear();
  csts.clear();
  for (ParticleId p = 0; p < particles.capacity(); ++p) particles.clear_lumped_mass(p);
  particles.clear_rotational();
  const std::size_t n = map.capacity();
  for (Dart d = 0; d < n; ++d) {
    dart_bar[d] = kNone;
    dart_hinge[d] = kNone;
    dart_beam6[d] = kNone;
    dart_cst[d] = kNone;
  }
  for (Dart d = 0; d < n; ++d) {
    if (!map.alive(d)) continue;
    if (dart_bar[d] == kNone && dart_beam6[d] == kNone && !map.is_free(0, d) && edge_has_bar(d)) add_edge_element(d);
    if (dart_hinge[d] == kNone) add_vertex_element(d);
    if (cst_first[d] && is_cst_patch(dart_block[d])) add_cst(d);
  }
}

// --- constraints and queries -------------------------------------------------

void Model::set_lock(ParticleId p, std::uint8_t bits) {
  require_particle(p, "lock");
  ++revision;
  particles.lock[p] = bits;
}

void Model::set_orientation(ParticleId p, const Quat& q) {
  require_particle(p, "orientation");
  const double n = q.norm();
  if (!(n > 0) || !std::isfinite(n) || !q.coeffs().allFinite())
    throw ModelError("orientation: particle " + std::to_string(p) + ": not a rotation");
  particles.orientation[p] = Quat(q.coeffs() / n);
}

void Model::set_moment(ParticleId p, const Vec3& m) {
  require_particle(p, "torque");
  if (!m.allFinite()) throw ModelError("torque: the moment is not finite");
  if (!m.isZero(0) && particles.rot_degree[p] == 0) {
    bool segment = false;  // a 3-DOF beam segment to put the couple across
    for (Dart d : darts_of(p)) segment |= blocks[dart_block[d]].kind == BlockKind::Beam && !map.is_free(0, d);
    if (!segment)
      throw ModelError("torque: particle " + std::to_string(p) +
                       " is in no beam; a moment needs a 6-DOF beam (rotations) or a 3-DOF beam segment to act across");
  }
  ++moment_revision;
  particles.moment[p] = m;
}

void Model::set_passive(ParticleId p, bool passive) {
  require_particle(p, "set_passive");
  if (bool(particles.passive[p]) == passive) return;
  ++revision;
  particles.passive[p] = passive;
  particles.refresh_active(p);
  if (passive) {  // frozen where it is: nothing left to integrate or report
    particles.velocity[p].setZero();
    particles.angular_velocity[p].setZero();
    particles.force[p].setZero();
    particles.torque[p].setZero();
  }
  // Its elements (bars and 6-DOF beams on its edges, hinges at it and at its
  // neighbours) change sides: O(degree).
  for (Dart head = particles.first_dart[p], d = head; d != kNone;) {
    if (ElementIndex e = dart_bar[d]; e != kNone) {
      unbind_bar(e);
      place_bar(e);
    }
    if (ElementIndex e = dart_beam6[d]; e != kNone) {
      unlump_beam6(e);
      place_beam6(e);
    }
    if (ElementIndex h = dart_hinge[d]; h != kNone) place_hinge(h);
    if (ElementIndex h = dart_hinge[map.alpha(0, d)]; h != kNone) place_hinge(h);
    if (is_cst_patch(dart_block[d]))  // the triangles of its quads
      map.for_orbit(kFaceOrbit, d, [&](Dart x) {
        if (dart_cst[x] != kNone) place_cst(dart_cst[x]);
        return true;
      });
    d = ring_next[d];
    if (d == head) break;
  }
}

void Model::set_load(ParticleId p, const Vec3& f) {
  require_particle(p, "load");
  particles.load[p] = f;
}

void Model::set_point_mass(ParticleId p, double kg) {
  require_particle(p, "mass");
  if (!(kg >= 0)) throw ModelError("mass: must be a non-negative number of kg");
  ++revision;
  particles.point_mass[p] = kg;
}

std::vector<BlockId> Model::blocks_of(ParticleId p) const {
  std::vector<BlockId> out;
  for (Dart d : darts_of(p)) out.push_back(dart_block[d]);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

void Model::set_role(ParticleId p, Role r) {
  require_particle(p, "role");
  particles.role[p] = std::uint8_t(r);
}

State Model::state(ParticleId p) const {
  require_particle(p, "state");
  switch (Role(particles.role[p])) {
    case Role::Parent: return State::Parent;
    case Role::Child: return State::Child;
    case Role::Volatile: return State::Volatile;
    case Role::None: break;
  }
  if (particles.degree[p] == 0) return State::Isolated;
  if (particles.passive[p]) return State::Passive;
  if (particles.lock[p] & kLockRotation) return State::FullLock;
  if (particles.lock[p] & kLockTranslation) return State::Lock;
  return reference_groups(p).size() > 1 ? State::Shared : State::Simple;
}

std::vector<std::vector<Dart>> Model::reference_groups(ParticleId p) const {
  std::vector<std::vector<Dart>> groups;
  std::vector<Dart> seen;
  for (Dart d : darts_of(p)) {
    if (std::find(seen.begin(), seen.end(), d) != seen.end()) continue;
    std::vector<Dart> group = map.orbit(kVertexOrbit, d);
    std::sort(group.begin(), group.end());
    seen.insert(seen.end(), group.begin(), group.end());
    groups.push_back(std::move(group));
  }
  std::sort(groups.begin(), groups.end(), [&](const std::vector<Dart>& a, const std::vector<Dart>& b) {
    return std::pair{dart_block[a[0]], a[0]} < std::pair{dart_block[b[0]], b[0]};
  });
  return groups;
}

std::vector<BlockId> Model::references_of(ParticleId p) const {
  require_particle(p, "references");
  std::vector<BlockId> out;
  for (const auto& g : reference_groups(p)) out.push_back(dart_block[g[0]]);
  return out;
}

std::vector<ParticleId> Model::particles_of(BlockId b) const {
  require_block(b, "particles");
  const Block& blk = blocks[b];
  std::vector<ParticleId> out;
  if (blk.kind == BlockKind::Patch) {
    std::vector<Dart> darts = map.orbit(kComponentOrbit, blk.dart);
    std::sort(darts.begin(), darts.end());
    for (Dart d : darts) out.push_back(dart_particle[d]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  // A path or ring: walk edge by edge from the block's start dart.
  Dart d = blk.dart;
  while (true) {
    out.push_back(dart_particle[d]);
    Dart e = map.alpha(0, d);
    Dart next = map.alpha(1, e);
    if (next == e) {
      out.push_back(dart_particle[e]);
      break;
    }
    if (next == blk.dart) break;
    d = next;
  }
  return out;
}

std::size_t Model::block_count(BlockKind k) const {
  std::size_t n = 0;
  for (const Block& b : blocks) n += b.alive && b.kind == k;
  return n;
}

std::vector<BlockId> Model::live_blocks() const {
  std::vector<BlockId> out;
  for (BlockId b = 0; b < blocks.size(); ++b)
    if (blocks[b].alive) out.push_back(b);
  return out;
}

}  // namespace tendril
