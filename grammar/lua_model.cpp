// Lua bindings of the model. A model userdata owns a Model and its Solver;
// particle and block handles carry (id, generation) so a handle to something
// deleted is refused with a clear error instead of aliasing a recycled slot.
#include "lua_model.hpp"

#include <cmath>
#include <initializer_list>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "folded_quads.hpp"
#include "io/atomic_file.hpp"
#include "ply_openmesh.hpp"
#include "io/model_xml.hpp"
#include "io/ccx.hpp"
#include "io/obj.hpp"
#include "io/ply.hpp"
#include "command/registry.hpp"
#include "lua_args.hpp"
#include "lua_clamp.hpp"
#include "lua_commands.hpp"
#include "lua_files.hpp"
#include "lua_csv.hpp"
#include "lua_sections.hpp"
#include "lua_meshing.hpp"
#include "lua_multires.hpp"
#include "lua_params.hpp"
#include "lua_patch_formulation.hpp"
#include "lua_goals.hpp"
#include "lua_handles.hpp"
#include "lua_import.hpp"
#include "lua_query.hpp"
#include "lua_readouts.hpp"
#include "lua_rules.hpp"
#include "lua_scene.hpp"
#include "lua_section_args.hpp"
#include "lua_patch_prestress.hpp"
#include "lua_strip.hpp"
#include "model/model.hpp"
#include "physics/settings_check.hpp"
#include "physics/solver.hpp"
#include "run_progress.hpp"

namespace tendril::lua {

namespace {

using command::Value;

// The particle list, or the particle, stored under `key` of the table at idx.
std::vector<ParticleId> field_particle_list(lua_State* L, int idx, const char* key, Scene& s, const char* fn) {
  lua_getfield(L, idx, key);
  try {
    std::vector<ParticleId> out = check_particle_list(L, lua_gettop(L), s, fn);
    lua_pop(L, 1);
    return out;
  } catch (...) {
    lua_pop(L, 1);
    throw;
  }
}

ParticleId field_particle(lua_State* L, int idx, const char* key, Scene& s, const char* fn) {
  lua_getfield(L, idx, key);
  try {
    ParticleId p = check_particle(L, lua_gettop(L), s, fn);
    lua_pop(L, 1);
    return p;
  } catch (...) {
    lua_pop(L, 1);
    throw;
  }
}

std::uint8_t parse_axes(const std::string& axes, const char* fn) {
  if (axes == "all") return kLockTranslation;
  if (axes == "full") return kLockTranslation | kLockRotation;
  std::uint8_t bits = 0;
  bool rotation = false;
  for (char c : axes) {
    switch (c) {
      case 'r': rotation = true; break;
      case ' ': case ',': rotation = false; break;
      case 'x': bits |= rotation ? kLockRX : kLockX; break;
      case 'y': bits |= rotation ? kLockRY : kLockY; break;
      case 'z': bits |= rotation ? kLockRZ : kLockZ; break;
      default:
        throw LuaArgError(std::string(fn) + ": axes '" + axes + "' must use x, y, z (translation) and r before rotations, e.g. \"xyz\", \"z\", \"xyz rxyz\", \"all\", \"full\"");
    }
  }
  return bits;
}

std::string axes_string(std::uint8_t bits) {
  std::string s;
  for (int k = 0; k < 3; ++k)
    if (bits & (1 << k)) s += char('x' + k);
  if (bits & kLockRotation) {
    s += s.empty() ? "r" : " r";
    for (int k = 0; k < 3; ++k)
      if (bits & (8 << k)) s += char('x' + k);
  }
  return s;
}

const std::initializer_list<const char*> kSettingKeys = {
    "dt",       "damping",   "viscous",        "geometric_factor", "mass_factor", "gravity",
    "integrator", "mass_mode", "vie_iterations", "vie_dt",           "mixed_switch",
    "mixed_implicit", "threads"};

// The option table at idx over the solver's current settings: the command
// takes every key (the journal keeps the whole set), then gravity; threads
// change no number and are not journaled.
void apply_settings(lua_State* L, int idx, Scene& s, const char* fn) {
  const SolverSettings& st = s.solver.settings;
  auto whole = [&](const char* key, double fallback, std::int64_t least, std::int64_t most) {
    const auto n = whole_number_in(field_number(L, idx, key, fn, fallback), least, most);
    if (!n) key_error(fn, key, "must be a whole number from " + std::to_string(least) + " to " + std::to_string(most));
    return *n;
  };
  const command::Args settings = {
      Value::of_number(field_number(L, idx, "dt", fn, st.dt)),
      Value::of_word(field_string(L, idx, "damping", fn, damping_name(st.damping))),
      Value::of_number(field_number(L, idx, "viscous", fn, st.viscous)),
      Value::of_number(field_number(L, idx, "geometric_factor", fn, st.geometric_factor)),
      Value::of_number(field_number(L, idx, "mass_factor", fn, st.mass_factor)),
      Value::of_word(field_string(L, idx, "integrator", fn, integrator_name(st.integrator))),
      Value::of_word(field_string(L, idx, "mass_mode", fn, mass_mode_name(st.mass_mode))),
      Value::of_id(std::uint64_t(whole("vie_iterations", st.vie_iterations, 0, kMaxVieIterations))),
      Value::of_number(field_number(L, idx, "vie_dt", fn, st.vie_dt)),
      Value::of_number(field_number(L, idx, "mixed_switch", fn, st.mixed_switch)),
      Value::of_word(field_string(L, idx, "mixed_implicit", fn, integrator_name(st.mixed_implicit)))};
  const Vec3 gravity = has_field(L, idx, "gravity") ? field_vec3(L, idx, "gravity", fn) : s.model.gravity;
  const int threads = int(whole("threads", st.threads, 1, kMaxThreads));
  apply_command(L, s, "settings", settings, fn);
  apply_command(L, s, "gravity", {Value::of_vector(gravity)}, fn);
  s.solver.settings.threads = threads;
}

Scene& push_new_scene(lua_State* L) {
  auto** slot = static_cast<Scene**>(lua_newuserdatauv(L, sizeof(Scene*), 0));
  *slot = nullptr;
  luaL_setmetatable(L, kModelMeta);
  *slot = new Scene();
  (*slot)->options = g_options;
  if (g_options) (*slot)->solver.settings.threads = int(g_options->threads);
  return **slot;
}

// The 6-DOF beam's keys of m:beam: dofs (3 or 6), GJ, EIy, EIz (0 or absent:
// as EI). Returns dofs.
int read_beam6_section(lua_State* L, int idx, const char* fn, Section& sec) {
  const double dofs = field_number(L, idx, "dofs", fn, 3);
  if (dofs != 3 && dofs != 6) key_error(fn, "dofs", "must be 3 or 6 (DOF per particle)");
  sec.GJ = field_number(L, idx, "GJ", fn, 0);
  sec.EIy = field_number(L, idx, "EIy", fn, 0);
  sec.EIz = field_number(L, idx, "EIz", fn, 0);
  for (auto [key, v] : {std::pair{"GJ", sec.GJ}, std::pair{"EIy", sec.EIy}, std::pair{"EIz", sec.EIz}})
    if (!(v >= 0) || !std::isfinite(v)) key_error(fn, key, "must be a finite number >= 0");
  return int(dofs);
}

// --- tendril.* ------------------------------------------------------------------

int l_new_model(lua_State* L) {
  const char* fn = "tendril.model";
  const bool has_options = !lua_isnoneornil(L, 1);
  if (has_options) {
    check_table(L, 1, fn);
    check_keys(L, 1, fn, kSettingKeys);
  }
  Scene& s = push_new_scene(L);
  if (has_options) apply_settings(L, 1, s, fn);
  return 1;
}

int l_load(lua_State* L) {
  const char* fn = "tendril.load";
  if (lua_type(L, 1) != LUA_TSTRING) arg_error(fn, 1, "expected a file name");
  std::string path = lua_tostring(L, 1);
  Scene& s = push_new_scene(L);
  apply_command(L, s, "open", {Value::of_word(path)}, fn);
  return 1;
}

int l_out(lua_State* L) {
  const char* fn = "tendril.out";
  if (lua_type(L, 1) != LUA_TSTRING) arg_error(fn, 1, "expected a file name");
  std::filesystem::path dir(g_options->out_dir);
  std::filesystem::create_directories(dir);
  std::string path = (dir / lua_tostring(L, 1)).string();
  lua_pushstring(L, path.c_str());
  return 1;
}

// --- model methods ---------------------------------------------------------------

int l_gc(lua_State* L) {
  auto** slot = static_cast<Scene**>(luaL_checkudata(L, 1, kModelMeta));
  delete *slot;
  *slot = nullptr;
  return 0;
}

// m:cable(a, b, {...}) and m:bar(a, b, {...}): the same arguments (rule 6).
int link(lua_State* L, const char* fn) {
  Scene& s = check_scene(L, fn);
  const ParticleId a = check_particle(L, 2, s, fn), b = check_particle(L, 3, s, fn);
  check_table(L, 4, fn);
  check_keys(L, 4, fn, {"EA", "E", "A", "prestress", "line_mass", "rest_length"});
  const Section sec = read_section(L, 4, fn, false);
  const double rest = field_number(L, 4, "rest_length", fn, 0);
  if (has_field(L, 4, "rest_length") && !(rest > 0)) key_error(fn, "rest_length", "must be > 0");
  command::Args args = {Value::of_id(a), Value::of_id(b)};
  append_section(args, sec);
  args.push_back(Value::of_number(rest));
  return push_result(L, s, apply_command(L, s, fn, std::move(args), fn, 2));
}

int l_cable(lua_State* L) { return link(L, "cable"); }
int l_bar(lua_State* L) { return link(L, "bar"); }

// The list of {x, y, z} under 'points' of the options at idx.
std::vector<Vec3> field_points(lua_State* L, int idx, const char* fn) {
  lua_getfield(L, idx, "points");
  const int t = lua_gettop(L);
  if (!lua_istable(L, t)) {
    lua_pop(L, 1);
    key_error(fn, "points", "must be a list of {x, y, z}");
  }
  std::vector<Vec3> pts;
  for (lua_Integer k = 1; k <= lua_Integer(lua_rawlen(L, t)); ++k) {
    lua_rawgeti(L, t, k);
    try {
      pts.push_back(check_vec3(L, lua_gettop(L), fn));
    } catch (...) {
      lua_pop(L, 2);
      throw LuaArgError("beam: points[" + std::to_string(k) + "] must be {x, y, z}");
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return pts;
}

// A ring (thesis 6.3.2: "a center point, a plane, a radius and a particle
// resolution"): 'segments' points on the circle of 'radius' about 'centre'
// in the plane normal to 'normal', counter-clockwise seen from the normal's
// tip, the first towards 'start' (default: global x projected on the plane,
// or global y when the normal is along x).
std::vector<Vec3> ring_points(lua_State* L, int idx, const char* fn) {
  const Vec3 centre = field_vec3(L, idx, "centre", fn);
  if (!has_field(L, idx, "normal")) key_error(fn, "normal", "is required with 'centre' (the ring's plane)");
  const Vec3 normal = field_vec3(L, idx, "normal", fn);
  if (!(normal.norm() > 0)) key_error(fn, "normal", "must be a non-zero vector");
  const Vec3 n = normal.normalized();
  const double radius = field_number(L, idx, "radius", fn, 0);
  if (!(radius > 0) || !std::isfinite(radius)) key_error(fn, "radius", "must be a finite number > 0 [m]");
  const double segments = field_number(L, idx, "segments", fn, 0);
  if (segments != std::floor(segments) || segments < 3 || segments > 1e6)
    key_error(fn, "segments", "must be a whole number >= 3 for a ring");
  Vec3 start = has_field(L, idx, "start") ? field_vec3(L, idx, "start", fn)
                                          : (std::abs(n.x()) > 0.9 ? Vec3::UnitY() : Vec3::UnitX());
  start -= start.dot(n) * n;
  if (!(start.norm() > 1e-9 * (1 + start.norm()))) key_error(fn, "start", "must not be along the normal");
  const Vec3 u = start.normalized(), v = n.cross(u);
  std::vector<Vec3> pts;
  for (int k = 0; k < int(segments); ++k) {
    const double t = 2 * M_PI * k / segments;
    pts.push_back(centre + radius * (std::cos(t) * u + std::sin(t) * v));
  }
  return pts;
}

int l_beam(lua_State* L) {
  const char* fn = "beam";
  Scene& s = check_scene(L, fn);
  command::Entry entry(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  check_table(L, 2, fn);
  check_keys(L, 2, fn, {"points", "particles", "from", "direction", "segments", "closed", "centre", "normal", "radius", "start",
                        "EA", "EI", "E", "A", "I", "prestress", "line_mass", "dofs", "GJ", "EIy", "EIz", "rest"});
  Section sec = read_section(L, 2, fn, true);
  const int dofs = read_beam6_section(L, 2, fn, sec);
  const std::string rest = field_string(L, 2, "rest", fn, "straight");
  if (rest != "straight" && rest != "current")
    key_error(fn, "rest", "must be \"straight\" or \"current\", got \"" + rest + "\"");
  const bool ring = has_field(L, 2, "centre");
  if (ring && has_field(L, 2, "closed") && !field_bool(L, 2, "closed", fn, true))
    key_error(fn, "closed", "cannot be false with 'centre': a ring is closed");
  if (!ring)
    for (const char* key : {"normal", "radius", "start"})
      if (has_field(L, 2, key)) key_error(fn, key, "belongs to a ring: give 'centre' too");
  const bool closed = ring || field_bool(L, 2, "closed", fn, false);
  const int ways = has_field(L, 2, "points") + has_field(L, 2, "particles") + has_field(L, 2, "from") + ring;
  if (ways != 1)
    throw LuaArgError("beam: give exactly one of 'points', 'particles', 'from' (with 'direction' and 'segments') or "
                      "'centre' (a ring, with 'normal', 'radius' and 'segments')");
  // One production: its particles, the beam, its 6-DOF section and
  // formulation, all or nothing.
  command::Result made;
  all_or_nothing(s, [&] {
    if (has_field(L, 2, "from")) {
      if (closed) key_error(fn, "closed", "is not available with 'from'");
      const ParticleId start = field_particle(L, 2, "from", s, fn);
      const Vec3 span = field_vec3(L, 2, "direction", fn);
      if (!has_field(L, 2, "segments")) key_error(fn, "segments", "is required with 'from'");
      const double seg = field_number(L, 2, "segments", fn, 0);
      if (seg != std::floor(seg) || seg < 1) key_error(fn, "segments", "must be an integer >= 1");
      command::Args args = {Value::of_id(start), Value::of_vector(span), Value::of_id(std::uint64_t(seg))};
      append_section(args, sec);
      made = apply_command(L, s, "beam_from", std::move(args), fn);
    } else {
      std::vector<ParticleId> ps;
      if (has_field(L, 2, "particles")) {
        ps = field_particle_list(L, 2, "particles", s, fn);
      } else {
        const std::vector<Vec3> pts = ring ? ring_points(L, 2, fn) : field_points(L, 2, fn);
        if (pts.size() < (closed ? 3u : 2u))
          key_error(fn, "points", closed ? "needs at least 3 points for a ring" : "needs at least 2 points");
        if (sec.EA <= 0 || sec.EI <= 0) throw LuaArgError("beam: EA and EI must be > 0");  // before any particle
        for (const Vec3& x : pts) ps.push_back(apply_command(L, s, "particle", {Value::of_vector(x)}, fn).ids[0]);
      }
      command::Args args = {Value::of_id(closed)};
      append_section(args, sec);
      args.push_back(Value::of_ids({ps.begin(), ps.end()}));
      made = apply_command(L, s, "beam", std::move(args), fn);
    }
    const Value beam = Value::of_id(made.ids[0]);
    if (sec.GJ != 0 || sec.EIy != 0 || sec.EIz != 0)
      apply_command(L, s, "section6", {beam, Value::of_number(sec.GJ), Value::of_number(sec.EIy), Value::of_number(sec.EIz)}, fn);
    if (dofs == 6) {
      command::Args args(command::get("formulation").params.size(), Value::absent());
      args[0] = beam;
      args[1] = Value::of_word("6");
      apply_command(L, s, "formulation", std::move(args), fn);
    }
    if (rest == "current") apply_command(L, s, "rest_shape", {beam, Value::of_word(rest)}, fn);
  });
  entry.done();
  return push_result(L, s, made);
}

int l_quad_grid(lua_State* L) {
  const char* fn = "quad_grid";
  Scene& s = check_scene(L, fn);
  check_table(L, 2, fn);
  check_keys(L, 2, fn, {"particles", "rows", "cols", "EA", "E", "A", "prestress", "line_mass"});
  const Section sec = read_section(L, 2, fn, false);
  auto count = [&](const char* key) {
    const auto n = whole_number_in(field_number(L, 2, key, fn, 0), 0, 1000000);
    if (!n) key_error(fn, key, "must be a whole number >= 1");
    return Value::of_id(std::uint64_t(*n));
  };
  command::Args args = {count("rows"), count("cols")};
  append_section(args, sec);
  const std::vector<ParticleId> ps = field_particle_list(L, 2, "particles", s, fn);
  args.push_back(Value::of_ids({ps.begin(), ps.end()}));
  return push_result(L, s, apply_command(L, s, "quad_grid", std::move(args), fn, 2));
}

int l_lock(lua_State* L) {
  Scene& s = check_scene(L, "lock");
  ParticleId p = check_particle(L, 2, s, "lock");
  std::string axes = lua_isnoneornil(L, 3) ? "all" : "";
  if (axes.empty()) {
    if (lua_type(L, 3) != LUA_TSTRING) arg_error("lock", 3, "expected axes such as \"xyz\"");
    axes = lua_tostring(L, 3);
  }
  const std::uint8_t bits = s.model.particles.lock[p] | parse_axes(axes, "lock");
  apply_command(L, s, "lock", {Value::of_id(p), Value::of_id(bits)}, "lock");
  return 0;
}

int l_unlock(lua_State* L) {
  Scene& s = check_scene(L, "unlock");
  ParticleId p = check_particle(L, 2, s, "unlock");
  std::uint8_t bits = kLockTranslation | kLockRotation;
  if (!lua_isnoneornil(L, 3)) {
    if (lua_type(L, 3) != LUA_TSTRING) arg_error("unlock", 3, "expected axes such as \"xyz\"");
    bits = parse_axes(lua_tostring(L, 3), "unlock");
  }
  apply_command(L, s, "lock", {Value::of_id(p), Value::of_id(s.model.particles.lock[p] & ~bits)}, "unlock");
  return 0;
}

int l_locks(lua_State* L) {
  Scene& s = check_scene(L, "locks");
  lua_pushstring(L, axes_string(s.model.particles.lock[check_particle(L, 2, s, "locks")]).c_str());
  return 1;
}

int l_role(lua_State* L) {
  Scene& s = check_scene(L, "role");
  ParticleId p = check_particle(L, 2, s, "role");
  if (lua_isnoneornil(L, 3)) {
    lua_pushstring(L, role_name(Role(s.model.particles.role[p])));
    return 1;
  }
  Role r;
  if (lua_type(L, 3) != LUA_TSTRING || !parse_role(lua_tostring(L, 3), r))
    arg_error("role", 3, "expected \"parent\", \"child\", \"volatile\" or \"none\"");
  apply_command(L, s, "role", {Value::of_id(p), Value::of_id(std::uint64_t(r))}, "role");
  return 0;
}

int l_settings(lua_State* L) {
  const char* fn = "settings";
  Scene& s = check_scene(L, fn);
  if (!lua_isnoneornil(L, 2)) {
    check_table(L, 2, fn);
    check_keys(L, 2, fn, kSettingKeys);
    apply_settings(L, 2, s, fn);
  }
  const SolverSettings& st = s.solver.settings;
  lua_createtable(L, 0, 14);
  auto number = [&](const char* key, double x) { lua_pushnumber(L, x), lua_setfield(L, -2, key); };
  auto word = [&](const char* key, const char* w) { lua_pushstring(L, w), lua_setfield(L, -2, key); };
  number("dt", st.dt);
  word("damping", damping_name(st.damping));
  number("viscous", st.viscous);
  number("geometric_factor", st.geometric_factor);
  number("mass_factor", st.mass_factor);
  push_vec3(L, s.model.gravity);
  lua_setfield(L, -2, "gravity");
  word("integrator", integrator_name(st.integrator));
  word("mass_mode", mass_mode_name(st.mass_mode));
  lua_pushinteger(L, st.vie_iterations);
  lua_setfield(L, -2, "vie_iterations");
  number("vie_dt", st.vie_dt);
  number("mixed_switch", st.mixed_switch);
  word("mixed_implicit", integrator_name(st.mixed_implicit));
  lua_pushinteger(L, st.threads);
  lua_setfield(L, -2, "threads");
  lua_pushstring(L, s.solver.phase());
  lua_setfield(L, -2, "phase");
  return 1;
}

// "patch 7 has 3 folded quads (worst scaled Jacobian -0.34 at particles 12
// 13 25 24): ...", or "" when none is.
std::string folded_warning(const std::vector<meshing::FoldedQuad>& folded) {
  if (folded.empty()) return "";
  const meshing::FoldedQuad& w = folded.front();
  std::size_t in_worst = 0;
  for (const auto& f : folded) in_worst += f.patch == w.patch;
  char jac[32];
  std::snprintf(jac, sizeof jac, "%.2f", w.jacobian);
  std::string text = "patch " + std::to_string(w.patch) + " has " + std::to_string(in_worst) + " folded quad" +
                     (in_worst == 1 ? "" : "s") + " (worst scaled Jacobian " + jac + " at particles";
  for (ParticleId p : w.corners) text += " " + std::to_string(p);
  text += ")";
  if (folded.size() > in_worst) text += ", other patches " + std::to_string(folded.size() - in_worst) + " more";
  return text + ": inverted faces, not a membrane's shape (a load or a boundary the prestress cannot hold, or a time "
                "step too large; docs/meshing.md)";
}

// {{patch =, particles = {...}, jacobian =}, ...}, worst first.
void push_folded(lua_State* L, Scene& s, const std::vector<meshing::FoldedQuad>& folded) {
  lua_createtable(L, int(folded.size()), 0);
  for (std::size_t k = 0; k < folded.size(); ++k) {
    lua_createtable(L, 0, 3);
    push_block(L, s, folded[k].patch);
    lua_setfield(L, -2, "patch");
    lua_createtable(L, 4, 0);
    for (int c = 0; c < 4; ++c) {
      push_particle(L, s, folded[k].corners[c]);
      lua_rawseti(L, -2, c + 1);
    }
    lua_setfield(L, -2, "particles");
    lua_pushnumber(L, folded[k].jacobian);
    lua_setfield(L, -2, "jacobian");
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
}

void push_run_result(lua_State* L, const RunResult& r) {
  lua_createtable(L, 0, 6);
  lua_pushinteger(L, lua_Integer(r.steps));
  lua_setfield(L, -2, "steps");
  lua_pushnumber(L, r.residual);
  lua_setfield(L, -2, "residual");
  lua_pushboolean(L, r.converged);
  lua_setfield(L, -2, "converged");
  lua_pushstring(L, verdict_name(r.verdict));
  lua_setfield(L, -2, "verdict");
  lua_pushnumber(L, r.force_scale);
  lua_setfield(L, -2, "force_scale");
  lua_pushnumber(L, r.relative_residual);
  lua_setfield(L, -2, "relative_residual");
}

int l_run(lua_State* L) {
  const char* fn = "run";
  Scene& s = check_scene(L, fn);
  RunLimits limits;  // tolerance 1e-3 N, no relative rule
  double max_steps = 100000;
  if (!lua_isnoneornil(L, 2)) {
    check_table(L, 2, fn);
    check_keys(L, 2, fn, {"tolerance", "relative", "max_steps"});
    // A relative tolerance alone is the only rule; with both, either suffices.
    auto given = [&](const char* key) {
      lua_getfield(L, 2, key);
      const bool is = !lua_isnil(L, -1);
      lua_pop(L, 1);
      return is;
    };
    const bool absolute_given = given("tolerance"), relative_given = given("relative");
    limits.relative = field_number(L, 2, "relative", fn, 0);
    if (relative_given && !(limits.relative > 0 && limits.relative < 1))
      key_error(fn, "relative", "must be > 0 and < 1");
    if (relative_given && !absolute_given) limits.tolerance = 0;
    else {
      limits.tolerance = field_number(L, 2, "tolerance", fn, limits.tolerance);
      if (!(limits.tolerance > 0)) key_error(fn, "tolerance", "must be > 0");
    }
    max_steps = field_number(L, 2, "max_steps", fn, max_steps);
  }
  if (!(max_steps >= 0) || max_steps != std::floor(max_steps)) key_error(fn, "max_steps", "must be an integer >= 0");
  auto cap = std::uint64_t(max_steps);
  const bool capped_by_option = s.options->max_steps >= 0 && std::uint64_t(s.options->max_steps) < cap;
  if (capped_by_option) cap = std::uint64_t(s.options->max_steps);
  limits.max_steps = cap;
  begin_stepping();
  RunProgress meter(s.options->progress, limits, cap, capped_by_option);
  auto progress = [&](const RunResult& r) { meter.update(r, s.solver.steps(), s.model.particle_count()); };
  auto finish = [&](const RunResult& r) {
    // A membrane that folded is not a shape, converged or not: said with
    // the worst quad, and listed in the result.
    const std::vector<meshing::FoldedQuad> folded = s.folded(s.model);
    g_report->ran = true;
    g_report->converged = r.converged;
    g_report->verdict = verdict_name(r.verdict);
    g_report->last_run = meter.finish(r, folded_warning(folded));
    s.last_verdict = verdict_name(r.verdict);
    push_run_result(L, r);
    push_folded(L, s, folded);
    lua_setfield(L, -2, "folded");
    return 1;
  };
  const auto& after_step = s.options->after_step;
  if (s.triggers.empty() && !after_step) return finish(s.solver.run(limits, progress, 100));
  // With triggers, rules run between steps; a rule that changes the model at
  // equilibrium keeps the run going.
  RunMonitor monitor(s.model, s.solver, limits);
  // Rules that count steps or watch the motion between them have
  // Leapfrog's steps (integrator "auto"); rules at equilibrium and a front
  // end's hook leave the run static.
  Solver::RunScope scope(s.solver, triggers_only_at_equilibrium(s));
  std::uint64_t at_rest_since = 0;  // the step the model came to rest at (0: moving)
  bool converged = false;
  while (monitor.result().steps < cap) {
    s.solver.step();
    const bool at_rest = monitor.observe();
    bool changed = !s.triggers.empty() && fire_triggers(L, s, at_rest);
    if (after_step) changed |= after_step(L);
    if (changed) monitor.model_changed();
    scope.stepped();
    if (!at_rest || changed) at_rest_since = 0;
    else if (at_rest_since == 0) at_rest_since = s.solver.steps();
    if (at_rest && !changed && every_triggers_had_their_turn(s, at_rest_since)) {
      converged = true;
      break;
    }
    if (monitor.failed()) break;
    if (monitor.result().steps % 100 == 0) progress(monitor.result());
  }
  return finish(monitor.finish(converged));
}

int l_step(lua_State* L) {
  Scene& s = check_scene(L, "step");
  std::int64_t n = lua_isnoneornil(L, 2) ? 1 : check_integer(L, 2, "step");
  if (n < 0) arg_error("step", 2, "must be >= 0");
  if (s.options->max_steps >= 0) n = std::min(n, s.options->max_steps);
  begin_stepping();
  for (std::int64_t k = 0; k < n; ++k) {
    s.solver.step();
    if (!s.triggers.empty()) fire_triggers(L, s, false);
    if (s.options->after_step) s.options->after_step(L);
  }
  lua_pushnumber(L, s.solver.residual());
  return 1;
}

// A Lua list of handles.
void push_list(lua_State* L, Scene& s, const std::vector<std::uint32_t>& ids, void (*push)(lua_State*, Scene&, std::uint32_t)) {
  lua_createtable(L, int(ids.size()), 0);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    push(L, s, ids[k]);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
}

int l_blocks(lua_State* L) {
  Scene& s = check_scene(L, "blocks");
  std::vector<BlockId> bs;
  if (lua_isnoneornil(L, 2)) bs = s.model.live_blocks();
  else bs = s.model.blocks_of(check_particle(L, 2, s, "blocks"));
  push_list(L, s, bs, push_block);
  return 1;
}

int l_particles(lua_State* L) {
  Scene& s = check_scene(L, "particles");
  std::vector<ParticleId> ps;
  if (lua_isnoneornil(L, 2)) {
    for (ParticleId p = 0; p < s.model.particles.capacity(); ++p)
      if (s.model.particles.valid(p)) ps.push_back(p);
  } else {
    ps = s.model.particles_of(check_block(L, 2, s, "particles"));
  }
  push_list(L, s, ps, push_particle);
  return 1;
}

int l_count(lua_State* L) {
  Scene& s = check_scene(L, "count");
  const Model& m = s.model;
  lua_createtable(L, 0, 8);
  auto set = [&](const char* k, std::size_t v) {
    lua_pushinteger(L, lua_Integer(v));
    lua_setfield(L, -2, k);
  };
  set("particles", m.particle_count());
  set("blocks", m.block_count());
  set("cables", m.block_count(BlockKind::Cable));
  set("two_way_bars", m.block_count(BlockKind::Bar));
  set("beams", m.block_count(BlockKind::Beam));
  set("patches", m.block_count(BlockKind::Patch));
  set("darts", m.map.dart_count());
  set("bars", m.bars.size());
  set("hinges", m.hinges.size());
  set("beam6s", m.beam6s.size());
  return 1;
}

int l_check(lua_State* L) {
  Scene& s = check_scene(L, "check");
  std::string err = s.model.check();
  if (!err.empty()) throw ModelError("check: the model is invalid: " + err);
  lua_pushboolean(L, 1);
  return 1;
}

int l_save(lua_State* L) {
  Scene& s = check_scene(L, "save");
  if (lua_type(L, 2) != LUA_TSTRING) arg_error("save", 2, "expected a file name");
  save_model_xml(s.model, s.solver.settings, lua_tostring(L, 2));
  return 0;
}

int l_save_obj(lua_State* L) {
  Scene& s = check_scene(L, "save_obj");
  if (lua_type(L, 2) != LUA_TSTRING) arg_error("save_obj", 2, "expected a file name");
  save_obj(s.model, lua_tostring(L, 2));
  return 0;
}

int l_save_ply(lua_State* L) {
  Scene& s = check_scene(L, "save_ply");
  if (lua_type(L, 2) != LUA_TSTRING) arg_error("save_ply", 2, "expected a file name");
  if (!lua_isnoneornil(L, 3)) {  // {binary = true}: the patches through OpenMesh
    check_table(L, 3, "save_ply");
    check_keys(L, 3, "save_ply", {"binary"});
    if (field_bool(L, 3, "binary", "save_ply", false)) {
      write_file_atomically(lua_tostring(L, 2), meshing::patches_ply_binary(s.model));
      return 0;
    }
  }
  save_ply(s.model, lua_tostring(L, 2));
  return 0;
}

// m:export_ccx(path): a CalculiX input deck of the current state (io/ccx.hpp).
int l_export_ccx(lua_State* L) {
  Scene& s = check_scene(L, "export_ccx");
  if (lua_type(L, 2) != LUA_TSTRING) arg_error("export_ccx", 2, "expected a file name");
  save_ccx(s.model, lua_tostring(L, 2));
  return 0;
}

// --- rotation: 6-DOF beams ---------------------------------------------------------

// m:formulation(beam) -> 3 or 6; m:formulation(beam, 3 | 6) switches it.
// Patches: bars or CST, lua_patch_formulation.cpp.
int l_formulation(lua_State* L) {
  const char* fn = "formulation";
  Scene& s = check_scene(L, fn);
  const BlockId b = check_block(L, 2, s, fn);
  if (s.model.blocks[b].kind == BlockKind::Patch) return patch_formulation(L, s, b);
  if (lua_isnoneornil(L, 3)) {
    lua_pushinteger(L, s.model.beam_formulation(b));
    return 1;
  }
  const std::int64_t dofs = check_integer(L, 3, fn);
  if (dofs != 3 && dofs != 6) arg_error(fn, 3, "must be 3 or 6 (DOF per particle)");
  command::Args args(command::get("formulation").params.size(), Value::absent());
  args[0] = Value::of_id(b);
  args[1] = Value::of_word(std::to_string(dofs));
  apply_command(L, s, "formulation", std::move(args), fn, 2);
  return 0;
}

// m:orientation(p) -> x, y, z: the node frame as its three column vectors.
// m:orientation(p, x, y, z) sets it (an orthonormal right-handed frame).
int l_orientation(lua_State* L) {
  const char* fn = "orientation";
  Scene& s = check_scene(L, fn);
  const ParticleId p = check_particle(L, 2, s, fn);
  if (lua_isnoneornil(L, 3)) {
    const Mat3 R = s.model.particles.orientation[p].toRotationMatrix();
    for (int k = 0; k < 3; ++k) push_vec3(L, R.col(k));
    return 3;
  }
  Mat3 R;
  for (int k = 0; k < 3; ++k) R.col(k) = check_vec3(L, 3 + k, fn);
  if (!((R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff() < 1e-6) || !(R.determinant() > 0))
    arg_error(fn, 3, "x, y, z must be orthonormal unit vectors forming a right-handed frame");
  const Quat q(R);
  apply_command(L, s, "orientation",
                {Value::of_id(p), Value::of_number(q.w()), Value::of_number(q.x()), Value::of_number(q.y()),
                 Value::of_number(q.z())},
                fn);
  return 0;
}


void register_model_meta(lua_State* L) {
  luaL_newmetatable(L, kModelMeta);
  lua_pushcfunction(L, l_gc);
  lua_setfield(L, -2, "__gc");
  lua_newtable(L);  // methods
  add_command_methods(L);  // first: the methods below take Lua shapes of their own
  add_readout_methods(L);
  set_fn<l_cable>(L, "cable");
  set_fn<l_bar>(L, "bar");
  set_fn<l_beam>(L, "beam");
  set_fn<l_quad_grid>(L, "quad_grid");
  set_fn<l_lock>(L, "lock");
  set_fn<l_unlock>(L, "unlock");
  set_fn<l_locks>(L, "locks");
  set_fn<l_role>(L, "role");
  set_fn<l_settings>(L, "settings");
  set_fn<l_run>(L, "run");
  set_fn<l_step>(L, "step");
  set_fn<l_blocks>(L, "blocks");
  set_fn<l_particles>(L, "particles");
  set_fn<l_count>(L, "count");
  set_fn<l_check>(L, "check");
  set_fn<l_save>(L, "save");
  set_fn<l_save_obj>(L, "save_obj");
  set_fn<l_save_ply>(L, "save_ply");
  set_fn<l_export_ccx>(L, "export_ccx");
  set_fn<l_formulation>(L, "formulation");
  set_fn<l_orientation>(L, "orientation");
  add_rule_methods(L);
  add_query_methods(L);
  add_goal_methods(L);
  add_meshing_methods(L);
  add_multires_methods(L);
  add_clamp_methods(L);
  add_strip_methods(L);
  add_patch_prestress_methods(L);
  add_import_methods(L);
  lua_setfield(L, -2, "__index");
  lua_pop(L, 1);
  register_handle_metatables(L);
}

}  // namespace

void open_tendril(lua_State* L, const SceneOptions& options) {
  g_options = &options;
  register_model_meta(L);
  lua_newtable(L);
  set_fn<l_new_model>(L, "model");
  set_fn<l_load>(L, "load");
  set_fn<l_out>(L, "out");
  add_param(L);
  add_csv(L);
  add_sections(L);
  add_file_functions(L);
  add_import_function(L);
  add_rule_constructor(L);
  lua_pushinteger(L, options.seed);
  lua_setfield(L, -2, "seed");
  lua_pushstring(L, options.out_dir.c_str());
  lua_setfield(L, -2, "out_dir");
  protect_metatables(L);
}

}  // namespace tendril::lua
