#pragma once
// A model built by applying every registered command at least once through
// the registry (C++, no Lua): the replay and JSON tests start from it.
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "command/registry.hpp"
#include "edge_classification.hpp"
#include "command/session.hpp"
#include "io/model_xml.hpp"
#include "physics/solver.hpp"

namespace tendril::test {

using command::Args;
using command::Value;

inline Value id(std::uint64_t i) { return Value::of_id(i); }
inline Value num(double x) { return Value::of_number(x); }
inline Value vec(double x, double y, double z) { return Value::of_vector(Vec3(x, y, z)); }
inline Value word(const char* w) { return Value::of_word(w); }
inline Value ids(std::vector<std::uint32_t> v) { return Value::of_ids(std::move(v)); }
inline Value none() { return Value::absent(); }

struct Recorded {
  Model model;
  Solver solver{model};
  Trace trace;
  Journal journal;
  command::Session session{model, solver, &trace, &journal};
  std::set<std::string> used;

  command::Result run(const char* name, Args args) {
    used.insert(name);
    return command::apply(session, name, std::move(args));
  }
  std::uint32_t particle(double x, double y, double z) { return run("particle", {vec(x, y, z)}).ids[0]; }
  std::string xml() const { return model_xml_string(model, solver.settings); }
  std::string journal_text() const {
    std::string out;
    for (const std::string& line : trace.lines(solver)) out += line + "\n";
    return out;
  }
};

// EA, EI, prestress, line_mass.
inline Args section(double EA, double EI) { return {num(EA), num(EI), num(0), num(0)}; }
inline Args join(Args a, const Args& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Starts from `base` (a model database written here), then applies every command.
inline void apply_every_command(Recorded& r, const std::filesystem::path& base) {
  {
    Model m;
    Solver s(m);
    m.add_particle(Vec3(0, 0, -5));
    save_model_xml(m, s.settings, base.string());
  }
  r.run("open", {word(base.string().c_str())});
  r.run("newton_steps", {id(2)});  // "auto", the default, as a run takes Newton's steps
  r.run("settings", {num(0.5), word("kinetic"), none(), none(), num(1.5), word("leapfrog"), none(), none(), none(),
                     none(), none()});
  r.run("gravity", {vec(0, 0, -9.81)});
  // Two beams crossing at x (a joint), grown, split, shortened.
  const std::uint32_t a0 = r.particle(-1, 0, 0), x = r.particle(0, 0, 0), a1 = r.particle(1, 0, 0);
  const std::uint32_t b0 = r.particle(0, -1, 0), b1 = r.particle(0, 1, 0);
  const std::uint32_t beam_a = r.run("beam", join(join({id(0)}, section(1e4, 10)), {ids({a0, x, a1})})).ids[0];
  r.run("beam", join(join({id(0)}, section(1e4, 10)), {ids({b0, x, b1})}));
  const std::size_t joint = r.run("joint", {id(x), num(1.5707963267948966), num(100)}).index;
  r.run("joint_angle", {id(joint), num(1.4)});
  const std::uint32_t tip = r.particle(2, 0, 0);
  r.run("extend", {id(beam_a), id(a1), id(tip)});
  const std::uint32_t mid = r.run("insert", {id(a1), id(tip)}).ids[0];
  r.run("remove_from_beam", {id(mid)});
  r.run("rest_length", {id(a1), id(tip), num(1.1)});
  const auto [q, beam_c] = [&] {
    const auto split = r.run("split", {id(beam_a), id(a1)});
    return std::pair{split.ids[0], split.ids[1]};
  }();
  r.run("section6", {id(beam_c), num(5), num(6), num(7)});
  Args six(10, none());
  six[0] = id(beam_c);
  six[1] = word("6");
  r.run("formulation", six);
  r.run("orientation", {id(q), num(1), num(0), num(0), num(0.1)});
  r.run("torque", {id(q), vec(0, 0, 0.5)});
  // A beam curved at rest, clamped at both ends, one released.
  const std::uint32_t k0 = r.particle(0, -3, 0), k1 = r.particle(1, -3, 0.2), k2 = r.particle(2, -3, 0);
  const std::uint32_t bent = r.run("beam", join(join({id(0)}, section(1e4, 10)), {ids({k0, k1, k2})})).ids[0];
  r.run("rest_shape", {id(bent), word("current")});
  r.run("clamp", {id(k0), id(bent), vec(0, 0, 0)});
  r.run("clamp", {id(k2), id(bent), vec(-1, 0, 0)});
  r.run("unclamp", {id(k2), id(bent)});
  // Two 3-DOF beams meeting at a corner, rigid there, then pinned again.
  const std::uint32_t f0 = r.particle(5, 0, 0), f1 = r.particle(5, 1, 0), f2 = r.particle(6, 1, 0);
  const std::uint32_t post = r.run("beam", join(join({id(0)}, section(1e4, 10)), {ids({f0, f1})})).ids[0];
  const std::uint32_t lintel = r.run("beam", join(join({id(0)}, section(1e4, 10)), {ids({f1, f2})})).ids[0];
  r.run("connection", {id(f1), id(post), id(lintel), word("rigid")});
  r.run("connection", {id(f1), id(lintel), id(post), word("pinned")});
  r.run("connection", {id(f1), id(post), id(lintel), word("rigid")});
  // A beam from a particle, merged onto a cable's end, exploded, detached.
  const std::uint32_t c0 = r.particle(0, 3, 0), c1 = r.particle(1, 3, 0);
  const std::uint32_t cable = r.run("cable", join({id(c0), id(c1)}, join(section(1e3, 0), {num(0)}))).ids[0];
  const std::uint32_t from = r.particle(0, 3, 1);
  const std::uint32_t beam_d = r.run("beam_from", join({id(from), vec(2, 0, 0), id(4)}, section(1e4, 10))).ids[0];
  const std::uint32_t merged = r.run("merge", {ids({c1, from})}).ids[0];
  const auto parts = r.run("explode", {id(merged)}).ids;
  const std::uint32_t joined = r.run("merge", {ids({parts[0], parts[1]})}).ids[0];
  r.run("explode_from", {id(joined), id(beam_d)});
  r.run("delete", {id(cable)});
  (void)c0;  // the cable's delete took its isolated end along
  // A two-way bar with a rest length of its own, deleted again.
  const std::uint32_t s0 = r.particle(0, 4, 0), s1 = r.particle(1, 4, 0);
  const std::uint32_t strut = r.run("bar", join({id(s0), id(s1)}, join(section(1e3, 0), {num(0.9)}))).ids[0];
  r.run("rest_length", {id(s0), id(s1), num(0.95)});
  r.run("delete", {id(strut)});
  r.run("delete_particle", {id(r.particle(9, 9, 9))});
  // Two patches side by side, sewn, cut, switched to CST.
  std::vector<std::uint32_t> grid;
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) grid.push_back(r.particle(j, i, 5));
  const std::uint32_t patch_a = r.run("quad_grid", join(join({id(3), id(3)}, section(1e3, 0)), {ids(grid)})).ids[0];
  const std::uint32_t e0 = r.particle(3, 0, 5), e1 = r.particle(3, 1, 5);
  const std::uint32_t patch_b = r.run("patch", join(section(1e3, 0), {ids({grid[2], e0, e1, grid[5]})})).ids[0];
  r.run("merge_patches", {id(patch_a), id(patch_b)});
  r.run("remove_from_patch", {id(e0)});
  // Warp and weft prestress on its bars, the edges from classification.
  std::vector<std::uint32_t> warp_weft, weft_sides;
  for (const auto& t : meshing::cst_triangulation(r.model, patch_a).triangles) {
    warp_weft.insert(warp_weft.end(), {t[0], t[1]});
    weft_sides.insert(weft_sides.end(), {t[1], t[2]});
  }
  const std::size_t warp_pairs = warp_weft.size() / 2;
  warp_weft.insert(warp_weft.end(), weft_sides.begin(), weft_sides.end());
  r.run("patch_prestress", {id(patch_a), num(3), num(1.5), id(warp_pairs), ids(warp_weft)});
  // Three patch particles as a rigid body.
  r.run("rigid", {num(1e3), ids({grid[0], grid[1], grid[3]})});
  // A bending hinge on the patch's middle edge grid[1]-grid[4].
  r.run("bend", {num(2), ids({grid[1], grid[4], grid[0], grid[2]})});
  Args form(10, none());
  form[0] = id(patch_a);
  form[1] = word("form");
  form[2] = num(10);
  form[3] = num(20);
  std::vector<std::uint32_t> corners;
  for (const auto& t : meshing::cst_triangulation(r.model, patch_a).triangles) corners.insert(corners.end(), t.begin(), t.end());
  form[9] = ids(corners);
  r.run("formulation", form);
  // Supports, roles, loads, masses, goals; steps between.
  r.run("lock", {id(grid[0]), id(7)});
  r.run("lock", {id(grid[2]), id(63)});
  r.run("role", {id(grid[8]), id(2)});
  r.run("passive", {id(grid[6]), id(1)});
  r.run("load", {id(grid[4]), vec(0, 0, -1)});
  r.run("pressure", {id(patch_a), num(2), vec(0, 0, 1)});
  r.run("pressure", {id(patch_a), num(-1), none()});
  r.run("area_load", {id(patch_a), num(0.5), none()});
  r.run("area_load", {id(patch_a), num(0.25), vec(1, 0, -1)});
  r.run("mass", {id(grid[4]), num(0.25)});
  r.run("position", {id(grid[7]), vec(1, 2, 5.1)});
  const std::size_t g = r.run("goal", {word("plane"), id(b1), none(), none(), vec(0, 0, 0), vec(0, 0, 1), num(10)}).index;
  r.run("goal", {word("length"), id(a0), id(b0), num(1.2), none(), none(), num(5)});
  r.run("goal_weight", {id(g), num(20)});
  r.run("planarity", {num(7), ids({a0, b0, b1, a1})});
  r.run("steps", {id(3)});
  r.run("remove_goal", {id(g)});
  r.run("steps", {id(2)});
  // A step that fails (physical masses, and particles without any), journaled as such.
  Args physical(11, none()), fictitious(11, none());
  physical[6] = word("physical");
  fictitious[6] = word("fictitious");
  r.run("settings", physical);
  r.run("failed_step", {none()});
  r.run("settings", fictitious);
}

}  // namespace tendril::test
