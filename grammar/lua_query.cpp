#include "lua_query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lua_args.hpp"
#include "io/gltf.hpp"
#include "io/vtk.hpp"
#include "query/element_results.hpp"
#include "query/fabric_utilisation.hpp"
#include "query/member_forces.hpp"
#include "lua_commands.hpp"
#include "lua_rules.hpp"
#include "lua_scene.hpp"

namespace tendril::lua {

namespace {

// m:neighbours(centre, radius) -> particles within radius, nearest first;
// centre is a particle (left out of the answer) or {x, y, z}.
int l_neighbours(lua_State* L) {
  const char* fn = "neighbours";
  Scene& s = check_scene(L, fn);
  Vec3 centre;
  ParticleId self = kNone;
  if (luaL_testudata(L, 2, kParticleMeta)) {
    self = check_particle(L, 2, s, fn);
    centre = s.model.particles.position[self];
  } else {
    centre = check_vec3(L, 2, fn);
  }
  const double radius = check_number(L, 3, fn);
  if (!(radius > 0)) arg_error(fn, 3, "the radius must be > 0");
  const std::pair<std::uint64_t, std::size_t> now{s.solver.steps(), s.trace.mark().lines};
  const double cell = s.neighbours.cell();
  if (now != s.neighbours_built_at || radius > 4 * cell || radius < cell / 4) {
    s.neighbours.build(s.model.particles, radius);
    s.neighbours_built_at = now;
  }
  std::vector<ParticleId> found = s.neighbours.within(s.model.particles, centre, radius);
  lua_createtable(L, int(found.size()), 0);
  lua_Integer n = 0;
  for (ParticleId p : found) {
    if (p == self) continue;
    push_particle(L, s, p);
    lua_rawseti(L, -2, ++n);
  }
  return 1;
}

// m:references(p): one block per reference of p, a block twice where a
// loop joins it to itself at p (Model::references_of).
int l_references(lua_State* L) {
  Scene& s = check_scene(L, "references");
  const std::vector<BlockId> bs = s.model.references_of(check_particle(L, 2, s, "references"));
  lua_createtable(L, int(bs.size()), 0);
  for (std::size_t k = 0; k < bs.size(); ++k) {
    push_block(L, s, bs[k]);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
  return 1;
}

bool read_stress_section(lua_State* L, int idx, const char* fn, StressSection& sec);
bool read_beam_sections(lua_State* L, int idx, const char* fn, Scene& s, BeamSections& out);

// m:summary([sections]): figures of a grown structure for reports and sweeps.
int l_summary(lua_State* L) {
  Scene& s = check_scene(L, "summary");
  BeamSections sections;
  const bool has_section = read_beam_sections(L, 2, "summary", s, sections);  // before the answer takes index 2
  const Model& m = s.model;
  const Vec3* x = m.particles.position.data();
  double beam_length = 0, max_strain = 0, min_radius = std::numeric_limits<double>::infinity();
  for (const Bar& b : m.bars.items) {
    const double L = (x[b.j] - x[b.i]).norm();
    const bool slack = b.tension_only && L < b.rest_length;  // a slack cable carries nothing: no strain to report
    if (!slack) max_strain = std::max(max_strain, std::abs(L - b.rest_length) / b.rest_length);
    if (m.blocks[m.dart_block[b.dart]].kind == BlockKind::Beam) beam_length += L;
  }
  // The radius of the circle through three consecutive particles of a beam
  // (eq. 3.41's Lc / 2 sin alpha).
  auto bend = [&](ParticleId i, ParticleId j, ParticleId k) {
    const Vec3 a = x[j] - x[i], c = x[k] - x[j];
    const double sin_alpha = a.cross(c).norm() / (a.norm() * c.norm());
    if (sin_alpha > 0) min_radius = std::min(min_radius, (x[k] - x[i]).norm() / (2 * sin_alpha));
  };
  for (const Hinge& h : m.hinges.items) bend(h.i, h.j, h.k);
  // 6-DOF beams have no hinges and no bars: their vertices and segments
  // from the path (a ring round its closure too).
  for (const Beam6& b : m.beam6s.items) beam_length += (x[b.j] - x[b.i]).norm();
  for (const BlockId b : m.live_blocks()) {
    if (m.blocks[b].kind != BlockKind::Beam || m.blocks[b].dofs != 6) continue;
    const std::vector<ParticleId> ps = m.particles_of(b);
    const std::size_t n = ps.size();
    const bool closed = m.blocks[b].closed;
    for (std::size_t k = closed ? 0 : 1; n >= 3 && k + (closed ? 0 : 1) < n; ++k)
      bend(ps[(k + n - 1) % n], ps[k], ps[(k + 1) % n]);
  }
  lua_createtable(L, 0, 8);
  auto set = [&](const char* k, double v) {
    lua_pushnumber(L, v);
    lua_setfield(L, -2, k);
  };
  set("particles", double(m.particle_count()));
  set("beams", double(m.block_count(BlockKind::Beam)));
  set("cables", double(m.block_count(BlockKind::Cable)));
  set("patches", double(m.block_count(BlockKind::Patch)));
  set("beam_length", beam_length);
  set("min_bending_radius", min_radius);
  set("max_strain", max_strain);
  set("steps", double(m.steps));
  // How the last m:run{} ended (run_verdict.hpp), "none" before any: a
  // sweep's table tells a converged shape from one that is not.
  lua_pushstring(L, s.last_verdict);
  lua_setfield(L, -2, "verdict");
  // With a section: the most stressed beam, where, and its utilisation.
  if (has_section) {
    double worst = 0, utilisation = 0;
    BlockId worst_block = kNone;
    ParticleId worst_particle = kNone;
    for (const BlockId b : m.live_blocks()) {
      if (m.blocks[b].kind != BlockKind::Beam || !sections.of(b)) continue;
      for (const LineResult& e : element_results(m, b, sections.of(b)).lines) {
        if (e.stress > worst) worst = e.stress, worst_block = b, worst_particle = e.at;
        if (e.utilisation > utilisation) utilisation = e.utilisation;
      }
    }
    set("max_stress", worst);
    if (sections.any_strength()) set("max_utilisation", utilisation);
    if (worst_block != kNone) {
      set("max_stress_block", double(worst_block));
      set("max_stress_particle", double(worst_particle));
    }
  }
  return 1;
}

// The fields m:forces and m:results share for a bar, a cable or a beam
// segment, set on the table on top of the stack.
void set_link_fields(lua_State* L, Scene& s, ParticleId a, ParticleId b, double axial, double strain, bool slack) {
  push_particle(L, s, a);
  lua_setfield(L, -2, "a");
  push_particle(L, s, b);
  lua_setfield(L, -2, "b");
  lua_pushnumber(L, axial);
  lua_setfield(L, -2, "axial");
  lua_pushnumber(L, strain);
  lua_setfield(L, -2, "strain");
  lua_pushboolean(L, slack);
  lua_setfield(L, -2, "slack");
}

// m:forces(block) -> {segments = {{a =, b =, axial =, strain =, slack =}, ...},
// vertices = {{particle =, curvature =, moment =}, ...}}: what the block
// carries now (query/member_forces.hpp), in path order.
int l_forces(lua_State* L) {
  const char* fn = "forces";
  Scene& s = check_scene(L, fn);
  const BlockId b = check_block(L, 2, s, fn);
  if (s.model.blocks[b].kind == BlockKind::Beam && s.model.blocks[b].dofs == 6)
    arg_error(fn, 2, "a 6-DOF beam: read its forces with m:results(beam)");
  const MemberForces f = member_forces(s.model, b);
  auto number = [&](const char* key, double x) { lua_pushnumber(L, x), lua_setfield(L, -2, key); };
  lua_createtable(L, 0, 2);
  lua_createtable(L, int(f.segments.size()), 0);
  for (std::size_t k = 0; k < f.segments.size(); ++k) {
    const SegmentForce& e = f.segments[k];
    lua_createtable(L, 0, 5);
    set_link_fields(L, s, e.a, e.b, e.axial, e.strain, e.slack);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
  lua_setfield(L, -2, "segments");
  lua_createtable(L, int(f.vertices.size()), 0);
  for (std::size_t k = 0; k < f.vertices.size(); ++k) {
    const VertexMoment& v = f.vertices[k];
    lua_createtable(L, 0, 3);
    push_particle(L, s, v.p);
    lua_setfield(L, -2, "particle");
    number("curvature", v.curvature);
    number("moment", v.moment);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
  lua_setfield(L, -2, "vertices");
  return 1;
}

// The section argument of m:results and m:export_vtk (absent: false).
bool read_stress_section(lua_State* L, int idx, const char* fn, StressSection& sec) {
  if (lua_isnoneornil(L, idx)) return false;
  check_table(L, idx, fn);
  for (const char* key : {"A", "Wy", "Wz"}) {
    if (!has_field(L, idx, key)) key_error(fn, key, "is required in the section (tendril.section.rod/tube/rect give it)");
    if (!(field_number(L, idx, key, fn, 0) > 0)) key_error(fn, key, "must be > 0");
  }
  sec.A = field_number(L, idx, "A", fn, 0);
  sec.Wy = field_number(L, idx, "Wy", fn, 0);
  sec.Wz = field_number(L, idx, "Wz", fn, 0);
  sec.strength = field_number(L, idx, "strength", fn, 0);
  if (sec.strength < 0 || !std::isfinite(sec.strength)) key_error(fn, "strength", "must be >= 0 [Pa]");
  return true;
}

// The sections of m:summary, m:export_vtk and m:export_gltf: one for every
// beam (a table with A) or one per beam, {[beam] = section} or {[id] =
// section} (absent: false).
bool read_beam_sections(lua_State* L, int idx, const char* fn, Scene& s, BeamSections& out) {
  if (lua_isnoneornil(L, idx)) return false;
  check_table(L, idx, fn);
  idx = lua_absindex(L, idx);
  if (has_field(L, idx, "A")) return read_stress_section(L, idx, fn, out.all);
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    BlockId b;
    if (lua_isinteger(L, -2)) {
      const lua_Integer id = lua_tointeger(L, -2);
      if (id < 0 || id >= lua_Integer(kNone)) arg_error(fn, idx, "no block " + std::to_string(id));
      b = BlockId(id);
      s.model.require_block(b, fn);
    } else {
      b = check_block(L, lua_gettop(L) - 1, s, fn);
    }
    if (s.model.blocks[b].kind != BlockKind::Beam)
      arg_error(fn, idx, "block " + std::to_string(b) + " is a " + block_kind_name(s.model.blocks[b].kind) +
                             "; sections give beams their stress");
    read_stress_section(L, lua_gettop(L), fn, out.by_block[b]);
    lua_pop(L, 1);
  }
  return out.any();
}

// m:results(block [, section]): what every element of the block carries now
// (query/element_results.hpp), docs/lua-api.md "Results". `section`: a
// table with A, Wy, Wz (tendril.section.*) and optionally strength, for the
// stress and utilisation of a beam.
int l_results(lua_State* L) {
  const char* fn = "results";
  Scene& s = check_scene(L, fn);
  const BlockId b = check_block(L, 2, s, fn);
  // A patch of fabric: {strength_warp =, strength_weft =} (tendril.fabric);
  // a beam: a section.
  double strength_warp = 0, strength_weft = 0;
  const bool fabric = lua_istable(L, 3) && s.model.blocks[b].kind == BlockKind::Patch;
  if (fabric) {
    for (auto [key, strength] : {std::pair{"strength_warp", &strength_warp}, std::pair{"strength_weft", &strength_weft}}) {
      if (!has_field(L, 3, key)) key_error(fn, key, "is required for a patch's utilisation (tendril.fabric gives it)");
      *strength = field_number(L, 3, key, fn, 0);
      if (!(*strength > 0 && std::isfinite(*strength))) key_error(fn, key, "must be > 0 [N/m]");
    }
  }
  StressSection sec;
  const bool has_section = !fabric && read_stress_section(L, 3, fn, sec);
  const BlockResults r = element_results(s.model, b, has_section ? &sec : nullptr);
  auto number = [&](const char* key, double x) { lua_pushnumber(L, x), lua_setfield(L, -2, key); };
  double max_axial = 0, max_moment = 0, max_stress = 0, max_utilisation = 0;
  lua_createtable(L, 0, 8);
  lua_createtable(L, int(r.lines.size()), 0);
  for (std::size_t k = 0; k < r.lines.size(); ++k) {
    const LineResult& e = r.lines[k];
    lua_createtable(L, 0, 14);
    set_link_fields(L, s, e.a, e.b, e.axial, e.strain, e.slack);
    number("My", e.My);
    number("Mz", e.Mz);
    number("torsion", e.torsion);
    number("moment", e.moment);
    number("curvature", e.curvature);
    number("radius", e.radius);
    push_particle(L, s, e.at);
    lua_setfield(L, -2, "at");
    if (!std::isnan(e.stress)) number("stress", e.stress);
    if (!std::isnan(e.utilisation)) number("utilisation", e.utilisation);
    lua_rawseti(L, -2, lua_Integer(k + 1));
    max_axial = std::max(max_axial, std::abs(e.axial));
    max_moment = std::max(max_moment, e.moment);
    if (!std::isnan(e.stress)) max_stress = std::max(max_stress, e.stress);
    if (!std::isnan(e.utilisation)) max_utilisation = std::max(max_utilisation, e.utilisation);
  }
  lua_setfield(L, -2, "elements");
  lua_createtable(L, int(r.vertices.size()), 0);
  for (std::size_t k = 0; k < r.vertices.size(); ++k) {
    const VertexResult& v = r.vertices[k];
    lua_createtable(L, 0, 4);
    push_particle(L, s, v.p);
    lua_setfield(L, -2, "particle");
    number("curvature", v.curvature);
    number("moment", v.moment);
    number("radius", v.radius);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
  lua_setfield(L, -2, "vertices");
  lua_createtable(L, int(r.triangles.size()), 0);
  for (std::size_t k = 0; k < r.triangles.size(); ++k) {
    const TriangleResult& t = r.triangles[k];
    lua_createtable(L, 0, 10);
    lua_createtable(L, 3, 0);
    const ParticleId corners[3] = {t.i, t.j, t.k};
    for (int c = 0; c < 3; ++c) {
      push_particle(L, s, corners[c]);
      lua_rawseti(L, -2, c + 1);
    }
    lua_setfield(L, -2, "particles");
    number("warp", t.warp);
    number("weft", t.weft);
    number("shear", t.shear);
    number("s1", t.s1);
    number("s2", t.s2);
    push_vec3(L, t.d1);
    lua_setfield(L, -2, "d1");
    push_vec3(L, t.d2);
    lua_setfield(L, -2, "d2");
    if (fabric) {
      const double u = fabric_utilisation(t, strength_warp, strength_weft);
      number("utilisation", u);
      max_utilisation = std::max(max_utilisation, u);
    }
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
  lua_setfield(L, -2, "triangles");
  number("max_axial", max_axial);
  number("max_moment", max_moment);
  if (has_section) number("max_stress", max_stress);
  if ((has_section && sec.strength > 0) || fabric) number("max_utilisation", max_utilisation);
  return 1;
}

// m:reactions() -> {{particle =, force = {x, y, z}, moment = {x, y, z}}, ...}:
// every locked particle's support reaction (Solver::reaction), in id order.
int l_reactions(lua_State* L) {
  Scene& s = check_scene(L, "reactions");
  const Particles& P = s.model.particles;
  lua_newtable(L);
  lua_Integer n = 0;
  for (ParticleId p = 0; p < P.capacity(); ++p) {
    if (!P.valid(p) || !P.lock[p]) continue;
    lua_createtable(L, 0, 3);
    push_particle(L, s, p);
    lua_setfield(L, -2, "particle");
    push_vec3(L, s.solver.reaction(p));
    lua_setfield(L, -2, "force");
    push_vec3(L, s.solver.reaction_moment(p));
    lua_setfield(L, -2, "moment");
    lua_rawseti(L, -2, ++n);
  }
  return 1;
}

// m:export_vtk(path [, sections]): the current state and its results for
// ParaView (io/vtk.hpp); `sections` give beams their stress.
int l_export_vtk(lua_State* L) {
  const char* fn = "export_vtk";
  Scene& s = check_scene(L, fn);
  if (lua_type(L, 2) != LUA_TSTRING) arg_error(fn, 2, "expected a file name");
  BeamSections sections;
  const bool has_section = read_beam_sections(L, 3, fn, s, sections);
  save_vtk(s.model, lua_tostring(L, 2), has_section ? &sections : nullptr);
  return 0;
}

// m:export_gltf(path [, {colour =, section =}]): the current state as glTF
// 2.0 binary (io/gltf.hpp), coloured by kind or by a result.
int l_export_gltf(lua_State* L) {
  const char* fn = "export_gltf";
  Scene& s = check_scene(L, fn);
  if (lua_type(L, 2) != LUA_TSTRING) arg_error(fn, 2, "expected a file name");
  GltfOptions o;
  BeamSections sections;
  if (!lua_isnoneornil(L, 3)) {
    check_table(L, 3, fn);
    check_keys(L, 3, fn, {"colour", "section"});
    lua_getfield(L, 3, "colour");
    if (!lua_isnil(L, -1)) {
      if (lua_type(L, -1) != LUA_TSTRING) key_error(fn, "colour", "must be a string");
      o.colour = lua_tostring(L, -1);
      if (!gltf_colour_known(o.colour))
        key_error(fn, "colour", "'" + o.colour + "' is none of kind, axial, moment, stress, utilisation, s1");
    }
    lua_pop(L, 1);
    lua_getfield(L, 3, "section");
    if (!lua_isnil(L, -1) && read_beam_sections(L, lua_gettop(L), fn, s, sections)) o.sections = &sections;
    lua_pop(L, 1);
  }
  save_gltf(s.model, lua_tostring(L, 2), o);
  return 0;
}

// m:joint(p, {angle =, stiffness =}): a rotational joint at the crossing p
// (thesis 6.5.2); returns its index. angle: the target included angle
// [deg] between the two beams (default: the current one).
int l_joint(lua_State* L) {
  const char* fn = "joint";
  Scene& s = check_scene(L, fn);
  const ParticleId p = check_particle(L, 2, s, fn);
  check_table(L, 3, fn);
  check_keys(L, 3, fn, {"angle", "stiffness"});
  ParticleId n[4];
  if (!s.model.joint_neighbours(p, n)) arg_error(fn, 2, "the particle is not an interior crossing of exactly two beams");
  const Vec3* x = s.model.particles.position.data();
  const Vec3 ta = x[n[1]] - x[n[0]], tb = x[n[3]] - x[n[2]];
  const double current = std::atan2(ta.cross(tb).norm(), ta.dot(tb));
  const double angle = has_field(L, 3, "angle") ? field_number(L, 3, "angle", fn, 0) * M_PI / 180 : current;
  if (!has_field(L, 3, "stiffness")) key_error(fn, "stiffness", "is required [N/m]");
  const double k = field_number(L, 3, "stiffness", fn, 0);
  using command::Value;
  return push_result(L, s,
                     apply_command(L, s, "joint", {Value::of_id(p), Value::of_number(angle), Value::of_number(k)}, fn));
}

// m:joint_angle(j): the joint's current included angle [deg];
// m:joint_angle(j, deg): sets its target (a value per step, as a sensor sends it).
int l_joint_angle(lua_State* L) {
  const char* fn = "joint_angle";
  Scene& s = check_scene(L, fn);
  const std::int64_t number = check_integer(L, 2, fn);  // 1-based; math.mininteger - 1 would overflow
  if (number < 1 || std::uint64_t(number) > s.model.joints.size()) arg_error(fn, 2, "no such joint");
  const std::int64_t j = number - 1;
  if (lua_isnoneornil(L, 3)) {
    ParticleId n[4];
    if (!s.model.joint_neighbours(s.model.joints[std::size_t(j)].particle, n)) {
      lua_pushnil(L);
      return 1;
    }
    const Vec3* x = s.model.particles.position.data();
    const Vec3 ta = x[n[1]] - x[n[0]], tb = x[n[3]] - x[n[2]];
    lua_pushnumber(L, std::atan2(ta.cross(tb).norm(), ta.dot(tb)) * 180 / M_PI);
    return 1;
  }
  const double angle = check_number(L, 3, fn) * M_PI / 180;
  apply_command(L, s, "joint_angle", {command::Value::of_id(std::uint64_t(j)), command::Value::of_number(angle)}, fn);
  return 0;
}

}  // namespace

void add_query_methods(lua_State* L) {
  set_fn<l_neighbours>(L, "neighbours");
  set_fn<l_references>(L, "references");
  set_fn<l_summary>(L, "summary");
  set_fn<l_forces>(L, "forces");
  set_fn<l_results>(L, "results");
  set_fn<l_reactions>(L, "reactions");
  set_fn<l_export_vtk>(L, "export_vtk");
  set_fn<l_export_gltf>(L, "export_gltf");
  set_fn<l_joint>(L, "joint");
  set_fn<l_joint_angle>(L, "joint_angle");
}

}  // namespace tendril::lua
