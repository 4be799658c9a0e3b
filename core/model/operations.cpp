// Primitive operations with the semantics of thesis 4.2.7 (rules 1-18 that do
// not need meshing). Each one validates its arguments before touching the
// model, so a ModelError leaves the model exactly as it was.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

#include "model/frames.hpp"
#include "model/limits.hpp"
#include "model/model.hpp"

namespace tendril {

namespace {
std::string pid(ParticleId p) { return std::to_string(p); }
}  // namespace

// --- particles ---------------------------------------------------------------

ParticleId Model::add_particle(const Vec3& x) {
  if (!x.allFinite()) throw ModelError("add_particle: position is not finite");
  check_coordinates(x, "add_particle");  // (finite: checked above, for its message)
  return new_particle(x);
}

void Model::delete_particle(ParticleId p) {
  require_particle(p, "delete_particle");
  if (particles.degree[p] != 0)
    throw ModelError("delete_particle: particle " + pid(p) + " is not isolated (state " +
                     state_name(state(p)) + "); delete or explode its blocks first");
  free_particle(p);
}

ParticleId Model::merge(const std::vector<ParticleId>& ps) {
  std::set<ParticleId> set(ps.begin(), ps.end());
  if (set.size() < 2) throw ModelError("merge: needs at least two distinct particles");
  for (ParticleId p : set) {
    require_particle(p, "merge");
    State s = state(p);
    if (s == State::Isolated || s == State::Passive)
      throw ModelError("merge: particle " + pid(p) + " is " + state_name(s) +
                       "; only simple or shared particles (locked or not) merge");
  }
  // Refuse merges that would collapse an edge or fold a beam onto itself.
  for (ParticleId p : set) {
    for (Dart d : darts_of(p)) {
      Dart n = map.alpha(0, d);
      if (n != d && set.count(dart_particle[n]))
        throw ModelError("merge: particles " + pid(p) + " and " + pid(dart_particle[n]) +
                         " share an edge; merging them would collapse it");
      if (n != d && !map.is_free(1, n)) {
        Dart far = map.alpha(0, map.alpha(1, n));
        if (far != map.alpha(1, n) && set.count(dart_particle[far]) && dart_particle[far] != p) {
          if (blocks[dart_block[d]].kind == BlockKind::Beam)
            throw ModelError("merge: particles " + pid(p) + " and " + pid(dart_particle[far]) +
                             " are two apart on a beam; merging them would fold it");
          if (blocks[dart_block[d]].kind == BlockKind::Patch)
            throw ModelError("merge: particles " + pid(p) + " and " + pid(dart_particle[far]) +
                             " are diagonal corners of a patch quad; merging them would collapse it");
        }
      }
    }
  }
  // Two particles joined to one neighbour in one patch (two apart along a
  // row, not only diagonal corners) would join it twice: a patch the model
  // database cannot hold (fuzz_commands found such a merge that passed check()).
  std::map<std::pair<BlockId, ParticleId>, ParticleId> joined;
  for (ParticleId p : set)
    for (Dart d : darts_of(p)) {
      const Dart n = map.alpha(0, d);
      if (n == d || blocks[dart_block[d]].kind != BlockKind::Patch) continue;
      const auto [at, fresh] = joined.emplace(std::pair{dart_block[d], dart_particle[n]}, p);
      if (!fresh && at->second != p)
        throw ModelError("merge: particles " + pid(at->second) + " and " + pid(p) + " are both joined to particle " +
                         pid(dart_particle[n]) + " in patch " + std::to_string(dart_block[d]) +
                         "; merging them would join it twice");
    }
  Vec3 x = Vec3::Zero(), v = Vec3::Zero(), load = Vec3::Zero(), moment = Vec3::Zero(), w = Vec3::Zero();
  std::uint8_t lock = 0;
  double point_mass = 0;
  // The frame: the first rotating particle's (beam ends elsewhere are
  // re-expressed in it), else the first particle's.
  ParticleId framed = *set.begin();
  int spinning = 0;
  for (ParticleId p : set) {
    x += particles.position[p];
    v += particles.velocity[p];
    load += particles.load[p];
    moment += particles.moment[p];
    lock |= particles.lock[p];
    point_mass += particles.point_mass[p];
    if (particles.rot_degree[p] > 0) {
      if (spinning++ == 0) framed = p;
      w += particles.angular_velocity[p];
    }
  }
  const double n = static_cast<double>(set.size());
  const Quat frame = particles.orientation[framed];
  ParticleId q = new_particle(x / n);
  particles.velocity[q] = v / n;
  particles.load[q] = load;
  particles.moment[q] = moment;
  particles.lock[q] = lock;
  particles.point_mass[q] = point_mass;
  particles.orientation[q] = frame;
  if (spinning) particles.angular_velocity[q] = w / spinning;
  for (ParticleId p : set) {
    for (Dart d : darts_of(p)) {
      // Where the dart's own particle was, and its locks, relative to q:
      // through earlier merges back to the particle it was built on.
      MergeOrigin o = merge_origin[d];
      const Vec3 own = particles.position[p] + o.offset;
      o.lock = o.set ? std::uint8_t(particles.lock[p] & (o.lock | ~o.merged_lock)) : particles.lock[p];
      o.offset = own - particles.position[q];
      o.merged_lock = lock;
      o.set = true;
      merge_origin[d] = o;
      rehome_dart(d, q);
    }
    free_particle(p);
  }
  return q;
}

ParticleId Model::detach(ParticleId p, const std::vector<Dart>& group, bool first) {
  Vec3 offset = Vec3::Zero();
  std::uint8_t lock = particles.lock[p];
  for (Dart d : group) {
    const MergeOrigin& o = merge_origin[d];
    offset += o.offset;
    if (o.set) lock = particles.lock[p] & (o.lock | ~o.merged_lock);
  }
  ParticleId q = new_particle(particles.position[p] + offset / double(group.size()));
  particles.velocity[q] = particles.velocity[p];
  particles.lock[q] = lock;
  particles.orientation[q] = particles.orientation[p];
  particles.angular_velocity[q] = particles.angular_velocity[p];
  if (first) {  // the particle's own load, moment and mass go with the first reference
    particles.load[q] = particles.load[p];
    particles.moment[q] = particles.moment[p];
    particles.point_mass[q] = particles.point_mass[p];
  }
  for (Dart d : group) {
    merge_origin[d] = MergeOrigin{};
    rehome_dart(d, q);
  }
  return q;
}

std::vector<ParticleId> Model::explode(ParticleId p) {
  require_particle(p, "explode");
  if (particles.passive[p]) throw ModelError("explode: particle " + pid(p) + " is passive");
  const std::vector<std::vector<Dart>> groups = reference_groups(p);
  if (groups.size() < 2)
    throw ModelError("explode: particle " + pid(p) + " has " + std::to_string(groups.size()) +
                     " reference(s) to blocks; only shared particles explode");
  std::vector<ParticleId> out;
  for (const auto& group : groups) out.push_back(detach(p, group, out.empty()));
  free_particle(p);
  return out;
}

ParticleId Model::explode_from(ParticleId p, BlockId b) {
  require_particle(p, "explode_from");
  require_block(b, "explode_from");
  if (particles.passive[p]) throw ModelError("explode_from: particle " + pid(p) + " is passive");
  const std::vector<std::vector<Dart>> groups = reference_groups(p);
  if (groups.size() < 2)
    throw ModelError("explode_from: particle " + pid(p) + " is not shared");
  bool only_b = true;
  std::vector<Dart> mine;
  for (const auto& group : groups) {
    if (dart_block[group[0]] != b) only_b = false;
    else mine.insert(mine.end(), group.begin(), group.end());
  }
  if (only_b) mine = groups.back();  // a loop: its last reference goes, the loop opens
  if (mine.empty()) throw ModelError("explode_from: particle " + pid(p) + " is not on block " + std::to_string(b));
  return detach(p, mine, false);
}

// --- cables ------------------------------------------------------------------

namespace {
void check_section(const Section& s, const char* what, bool beam) {
  auto bad = [&](const char* key) {
    throw ModelError(std::string(what) + ": " + key + " must be a finite number >= 0");
  };
  if (!(s.EA >= 0) || !std::isfinite(s.EA)) bad("EA");
  if (!(s.EI >= 0) || !std::isfinite(s.EI)) bad("EI");
  if (!std::isfinite(s.prestress)) bad("prestress");
  if (!(s.line_mass >= 0) || !std::isfinite(s.line_mass)) bad("line_mass");
  if (!(s.GJ >= 0) || !std::isfinite(s.GJ)) bad("GJ");
  if (!(s.EIy >= 0) || !std::isfinite(s.EIy)) bad("EIy");
  if (!(s.EIz >= 0) || !std::isfinite(s.EIz)) bad("EIz");
  if (s.EA <= 0) throw ModelError(std::string(what) + ": EA must be > 0");
  if (beam && s.EI <= 0) throw ModelError(std::string(what) + ": EI must be > 0");
}
}  // namespace

BlockId Model::add_cable(ParticleId a, ParticleId b, const Section& s, double rest) {
  return add_link(BlockKind::Cable, a, b, s, rest, "cable");
}

BlockId Model::add_elastic_bar(ParticleId a, ParticleId b, const Section& s, double rest) {
  return add_link(BlockKind::Bar, a, b, s, rest, "bar");
}

// One edge with one Bar element; add_bar reads tension_only from the kind.
BlockId Model::add_link(BlockKind kind, ParticleId a, ParticleId b, const Section& s, double rest, const char* fn) {
  const std::string f = fn;
  require_particle(a, fn);
  require_particle(b, fn);
  if (a == b) throw ModelError(f + ": both ends are particle " + pid(a));
  check_section(s, fn, false);
  if (!std::isfinite(rest)) throw ModelError(f + ": rest_length must be finite");
  double length = rest > 0 ? rest : (particles.position[a] - particles.position[b]).norm();
  if (length <= 0) throw ModelError(f + ": particles " + pid(a) + " and " + pid(b) + " coincide; give a rest_length");
  BlockId blk = new_block(kind, s, false);
  Dart d = new_dart(blk, a), e = new_dart(blk, b);
  map.link(0, d, e);
  set_edge_rest_length(d, length);
  add_bar(d);
  return blk;
}

void Model::delete_cable(BlockId b) {
  require_block(b, "delete_cable");
  if (blocks[b].kind != BlockKind::Cable) throw ModelError("delete_cable: block " + std::to_string(b) + " is not a cable");
  delete_component(b);
}

void Model::delete_elastic_bar(BlockId b) {
  require_block(b, "delete_bar");
  if (blocks[b].kind != BlockKind::Bar) throw ModelError("delete_bar: block " + std::to_string(b) + " is not a bar");
  delete_component(b);
}

void Model::delete_component(BlockId b) {
  std::vector<Dart> darts = map.orbit(kComponentOrbit, blocks[b].dart);
  std::sort(darts.begin(), darts.end());
  std::vector<ParticleId> touched;
  for (Dart d : darts) {
    remove_hinge(d);
    remove_edge_element(d);
    remove_cst(d);
    touched.push_back(dart_particle[d]);
  }
  for (Dart d : darts) free_dart(d);
  free_block(b);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (ParticleId p : touched)
    if (particles.degree[p] == 0) free_particle(p);  // rule 2 on what is left isolated
}

// --- beams -------------------------------------------------------------------

BlockId Model::add_beam(const std::vector<ParticleId>& ps, const Section& s, bool closed) {
  const std::size_t n = ps.size();
  if (n < (closed ? 3u : 2u))
    throw ModelError(std::string("beam: needs at least ") + (closed ? "3" : "2") + " particles, got " + std::to_string(n));
  for (ParticleId p : ps) require_particle(p, "beam");
  check_section(s, "beam", true);
  const std::size_t segments = closed ? n : n - 1;
  // A particle may come back on the same beam (a loop or a drop, as merging
  // its ends makes: ring_loop, drop_single), but not one or two places on,
  // which would collapse a segment or fold the beam onto itself (the merges
  // that make those are refused too).
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t gap = 1; gap <= 2; ++gap)
      if ((closed || k + gap < n) && ps[k] == ps[(k + gap) % n])
        throw ModelError("beam: particle " + pid(ps[k]) + " appears twice " + (gap == 1 ? "in a row" : "two apart") +
                         (gap == 1 ? "; a segment needs two particles" : "; the beam would fold onto itself"));
  for (std::size_t k = 0; k < segments; ++k) {
    ParticleId a = ps[k], b = ps[(k + 1) % n];
    if ((particles.position[a] - particles.position[b]).norm() <= 0)
      throw ModelError("beam: consecutive particles " + pid(a) + " and " + pid(b) + " coincide");
  }
  BlockId blk = new_block(BlockKind::Beam, s, closed);
  Dart first = kNoDart, prev_end = kNoDart;
  for (std::size_t k = 0; k < segments; ++k) {
    ParticleId a = ps[k], b = ps[(k + 1) % n];
    Dart d = new_dart(blk, a), e = new_dart(blk, b);
    map.link(0, d, e);
    set_edge_rest_length(d, (particles.position[a] - particles.position[b]).norm());
    if (prev_end != kNoDart) map.link(1, prev_end, d);
    if (first == kNoDart) first = d;
    prev_end = e;
  }
  if (closed) map.link(1, prev_end, first);
  blocks[blk].dart = first;
  for (Dart d : map.orbit(kComponentOrbit, first)) {
    if (dart_bar[d] == kNone) add_bar(d);
    if (dart_hinge[d] == kNone && !map.is_free(1, d)) add_hinge(d);
  }
  return blk;
}

BlockId Model::add_beam_from(ParticleId start, const Vec3& span, int segments, const Section& s) {
  require_particle(start, "beam_from");
  if (segments < 1) throw ModelError("beam_from: segments must be >= 1, got " + std::to_string(segments));
  if (!(span.norm() > 0) || !span.allFinite()) throw ModelError("beam_from: direction must be a finite non-zero vector");
  check_section(s, "beam_from", true);
  // Every point is checked before any particle exists, so a refusal leaves
  // the model as it was.
  std::vector<Vec3> points{particles.position[start]};
  for (int k = 1; k <= segments; ++k) {
    points.push_back(points[0] + span * (double(k) / segments));
    if (!points.back().allFinite() || points.back() == points[k - 1])
      throw ModelError("beam_from: the segments are too short to tell their ends apart at this position");
    check_coordinates(points.back(), "beam_from");
  }
  std::vector<ParticleId> ps{start};
  for (int k = 1; k <= segments; ++k) ps.push_back(new_particle(points[k]));
  return add_beam(ps, s, false);
}

Dart Model::find_edge(ParticleId a, ParticleId b, BlockKind k) const {
  for (Dart d : darts_of(a)) {
    Dart e = map.alpha(0, d);
    if (e != d && dart_particle[e] == b && blocks[dart_block[d]].kind == k) return d;
  }
  return kNoDart;
}

ParticleId Model::insert_particle(ParticleId a, ParticleId b) {
  require_particle(a, "insert_particle");
  require_particle(b, "insert_particle");
  Dart d = find_edge(a, b, BlockKind::Beam);
  if (d == kNoDart)
    throw ModelError("insert_particle: particles " + pid(a) + " and " + pid(b) + " are not consecutive on a beam");
  const BlockId blk = dart_block[d];
  const Dart e = map.alpha(0, d);
  const double half = 0.5 * rest_length[d];
  const bool six = six_dof(d);
  // On a 6-DOF beam the new node sits at the middle of the element's cubic
  // deflection curve with that curve's frame, and both new beam ends
  // coincide with it: the element is split without changing its state.
  Vec3 x = 0.5 * (particles.position[a] + particles.position[b]);
  Quat frame = Quat::Identity();
  if (six)
    beam6_midpoint(particles.position[a], particles.position[b], particles.orientation[a] * beam_end[d],
                   particles.orientation[b] * beam_end[e] * end_flip(), x, frame);
  remove_edge_element(d);
  map.unlink(0, d);
  ParticleId q = new_particle(x);
  particles.velocity[q] = 0.5 * (particles.velocity[a] + particles.velocity[b]);
  if (six) {
    particles.orientation[q] = frame;
    particles.angular_velocity[q] = 0.5 * (particles.angular_velocity[a] + particles.angular_velocity[b]);
  }
  Dart d2 = new_dart(blk, q), e2 = new_dart(blk, q);
  beam_end[d2] = end_flip();  // looking back to a
  beam_end[e2] = Quat::Identity();
  map.link(0, d, d2);
  map.link(1, d2, e2);
  map.link(0, e2, e);
  if (six) {  // each half keeps the element's axial strain
    const double l = (particles.position[b] - particles.position[a]).norm();
    const double scale = l > 0 ? 2 * half / l : 1.0;
    set_edge_rest_length(d, scale * (x - particles.position[a]).norm());
    set_edge_rest_length(e, scale * (particles.position[b] - x).norm());
  } else {
    set_edge_rest_length(d, half);
    set_edge_rest_length(e, half);
  }
  add_edge_element(d);
  add_edge_element(e);
  // The new vertex's rest curvature: the mean of its neighbours' (those that
  // are beam vertices), which keep theirs: a refined arc keeps its radius.
  double kappa = 0;
  int vertices = 0;
  for (Dart x : {d, e})
    if (!map.is_free(1, x)) kappa += rest_curvature[x], ++vertices;
  rest_curvature[d2] = rest_curvature[e2] = vertices ? kappa / vertices : 0.0;
  add_vertex_element(d2);
  refresh_hinge(d);
  refresh_hinge(e);
  return q;
}

void Model::remove_from_beam(ParticleId p) {
  require_particle(p, "remove_from_beam");
  State s = state(p);
  std::vector<Dart> ds = darts_of(p);
  if (s != State::Simple || blocks[dart_block[ds[0]]].kind != BlockKind::Beam || ds.size() > 2)
    throw ModelError("remove_from_beam: particle " + pid(p) + " is " + state_name(s) +
                     "; only a simple particle of one beam can be removed");
  const BlockId blk = dart_block[ds[0]];
  Block& block = blocks[blk];
  if (ds.size() == 2) {  // interior: bridge the two neighbours
    if (block.closed && block.darts <= 6)
      throw ModelError("remove_from_beam: a ring keeps at least 3 particles");
    Dart d = ds[0], e = map.alpha(1, d);
    if (e != ds[1])
      throw ModelError("remove_from_beam: particle " + pid(p) + " joins two ends of its beam; explode it first");
    Dart a = map.alpha(0, d), b = map.alpha(0, e);
    if (dart_particle[a] == dart_particle[b])
      throw ModelError("remove_from_beam: the neighbours of particle " + pid(p) + " are one particle; bridging would collapse the edge");
    const double length = rest_length[d] + rest_length[e];
    remove_hinge(d);
    remove_edge_element(d);
    remove_edge_element(e);
    free_dart(d);
    free_dart(e);
    map.link(0, a, b);
    set_edge_rest_length(a, length);
    add_edge_element(a);  // a 6-DOF edge keeps the outer beam ends of a and b
    refresh_hinge(a);
    refresh_hinge(b);
    if (block.dart == kNoDart) block.dart = a;
  } else if (block.darts == 2) {  // the last segment: the beam goes
    delete_component(blk);
    return;  // p was released as isolated by delete_component
  } else {  // an end: drop the end segment
    Dart d = ds[0], a = map.alpha(0, d), a1 = map.alpha(1, a);
    remove_hinge(a);
    remove_edge_element(d);
    free_dart(d);
    free_dart(a);
    if (block.dart == kNoDart) block.dart = a1;  // the start end went: a1 starts the path now
  }
  free_particle(p);
}

void Model::delete_beam(BlockId b) {
  require_block(b, "delete_beam");
  if (blocks[b].kind != BlockKind::Beam) throw ModelError("delete_beam: block " + std::to_string(b) + " is not a beam");
  delete_component(b);
}

// --- quad grid patch -----------------------------------------------------------

BlockId Model::add_quad_grid(const std::vector<ParticleId>& grid, int rows, int cols, const Section& s) {
  if (rows < 2 || cols < 2) throw ModelError("quad_grid: needs at least 2 rows and 2 columns");
  if (grid.size() != std::size_t(rows) * cols)
    throw ModelError("quad_grid: expected " + std::to_string(std::size_t(rows) * std::size_t(cols)) + " particles, got " + std::to_string(grid.size()));
  std::set<ParticleId> seen;
  for (ParticleId p : grid) {
    require_particle(p, "quad_grid");
    if (!seen.insert(p).second) throw ModelError("quad_grid: particle " + pid(p) + " appears twice");
  }
  check_section(s, "quad_grid", false);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const Vec3& x = particles.position[grid[r * cols + c]];
      if ((c + 1 < cols && x == particles.position[grid[r * cols + c + 1]]) ||
          (r + 1 < rows && x == particles.position[grid[(r + 1) * cols + c]]))
        throw ModelError("quad_grid: the grid edge at row " + std::to_string(r) + ", column " + std::to_string(c) +
                         " joins coincident particles");
    }
  std::vector<Quad> quads;
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < cols; ++c)
      quads.push_back({grid[r * cols + c], grid[r * cols + c + 1], grid[(r + 1) * cols + c + 1], grid[(r + 1) * cols + c]});
  return add_patch(quads, s);
}

BlockId Model::add_patch(const std::vector<Quad>& quads, const Section& s) {
  if (quads.empty()) throw ModelError("patch: needs at least one quad");
  check_section(s, "patch", false);
  // Validate everything first: corners, edges, and that the quads form one
  // connected quasi-manifold component (an edge in at most two quads).
  std::map<std::pair<ParticleId, ParticleId>, std::vector<std::pair<std::size_t, int>>> edges;
  for (std::size_t q = 0; q < quads.size(); ++q) {
    const Quad& quad = quads[q];
    for (int k = 0; k < 4; ++k) {
      require_particle(quad[k], "patch");
      for (int l = k + 1; l < 4; ++l)
        if (quad[k] == quad[l]) throw ModelError("patch: quad " + std::to_string(q) + " repeats particle " + pid(quad[k]));
      ParticleId a = quad[k], b = quad[(k + 1) % 4];
      if (particles.position[a] == particles.position[b])
        throw ModelError("patch: quad " + std::to_string(q) + " has an edge between coincident particles " + pid(a) + " and " + pid(b));
      auto& list = edges[{std::min(a, b), std::max(a, b)}];
      list.push_back({q, k});
      if (list.size() > 2)
        throw ModelError("patch: the edge " + pid(a) + "-" + pid(b) + " belongs to more than two quads");
    }
  }
  {  // connectivity: a patch is one connected component
    std::vector<std::size_t> parent(quads.size());
    for (std::size_t q = 0; q < quads.size(); ++q) parent[q] = q;
    auto root = [&](std::size_t q) {
      while (parent[q] != q) q = parent[q] = parent[parent[q]];
      return q;
    };
    std::size_t groups = quads.size();
    for (const auto& [key, list] : edges)
      if (list.size() == 2) {
        std::size_t a = root(list[0].first), b = root(list[1].first);
        if (a != b) {
          parent[a] = b;
          --groups;
        }
      }
    if (groups != 1) throw ModelError("patch: the quads form " + std::to_string(groups) + " separate pieces; a patch is one piece");
  }
  BlockId blk = new_block(BlockKind::Patch, s, false);
  // side[q][k][0|1]: dart of quad q on side k at its start / end corner.
  std::vector<std::array<std::array<Dart, 2>, 4>> side(quads.size());
  for (std::size_t q = 0; q < quads.size(); ++q) {
    for (int k = 0; k < 4; ++k) {
      side[q][k][0] = new_dart(blk, quads[q][k]);
      side[q][k][1] = new_dart(blk, quads[q][(k + 1) % 4]);
      map.link(0, side[q][k][0], side[q][k][1]);
    }
    for (int k = 0; k < 4; ++k) map.link(1, side[q][k][1], side[q][(k + 1) % 4][0]);
  }
  // Sew shared edges by alpha2, dart against the dart on the same particle.
  for (const auto& [key, list] : edges) {
    if (list.size() != 2) continue;
    const auto& s0 = side[list[0].first][list[0].second];
    const auto& s1 = side[list[1].first][list[1].second];
    const bool same = dart_particle[s0[0]] == dart_particle[s1[0]];
    map.link(2, s0[0], same ? s1[0] : s1[1]);
    map.link(2, s0[1], same ? s1[1] : s1[0]);
  }
  blocks[blk].dart = side[0][0][0];
  // Bars in quad order keep the step's memory accesses local.
  for (const auto& q : side)
    for (const auto& edge : q)
      if (dart_bar[edge[0]] == kNone) {
        set_edge_rest_length(edge[0], (pos(edge[0]) - pos(edge[1])).norm());
        add_bar(edge[0]);
      }
  return blk;
}

}  // namespace tendril
