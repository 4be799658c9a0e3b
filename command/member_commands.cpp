// Settings of beams, patches and joints: sections, formulations (thesis
// 5.5.2), node frames, moments, rest lengths and rotational joints (6.5.2).
#include <cmath>

#include "command/declare.hpp"

namespace tendril::command {

namespace {

// formulation B 3|6, or B bars | form SW SF TRIS | analysis SW SF DXX DXY DYX DYY G TRIS.
enum FormulationParam { kBlock, kKind, kSigmaWarp, kSigmaWeft, kDxx, kDxy, kDyx, kDyy, kG, kTriangles };

bool formulation_on_line(const Args& a, std::size_t next) {
  const std::string& kind = a[kKind].word;
  if (kind == "3" || kind == "6") return false;  // a beam: nothing after the kind
  if (next == kTriangles) return true;
  if (next <= kSigmaWeft) return kind != "bars";
  return kind == "analysis";
}

Result apply_formulation(Target& t, Args& a) {
  Model& m = t.model;
  const BlockId b = block(a, kBlock);
  const std::string& kind = a[kKind].word;
  const bool patch = m.blocks[b].kind == BlockKind::Patch;
  if ((kind == "3" || kind == "6") == patch)
    throw ArgumentError(kKind, patch ? "a patch is \"bars\", \"form\" or \"analysis\"" : "a beam is 3 or 6 (DOF per particle)");
  if (!patch) {
    m.set_beam_formulation(b, kind == "3" ? 3 : 6);
    return nothing();
  }
  Membrane mem;
  mem.mode = kind == "bars" ? Membrane::Bars : kind == "form" ? Membrane::FormFinding : Membrane::Analysis;
  if (mem.cst()) {
    mem.sigma_warp = a[kSigmaWarp].number;
    mem.sigma_weft = a[kSigmaWeft].number;
  }
  if (mem.mode == Membrane::Analysis) {
    mem.dxx = a[kDxx].number;
    mem.dxy = a[kDxy].number;
    mem.dyx = a[kDyx].number;
    mem.dyy = a[kDyy].number;
    mem.G = a[kG].number;
  }
  const std::vector<std::uint32_t>& ids = a[kTriangles].ids;
  if (ids.size() % 3) throw ArgumentError(kTriangles, "needs three particles per triangle");
  std::vector<Model::Triangle> tris;
  for (std::size_t k = 0; k < ids.size(); k += 3) tris.push_back({ids[k], ids[k + 1], ids[k + 2]});
  m.set_patch_formulation(b, mem, tris);
  return nothing();
}

}  // namespace

void declare_members(std::vector<Command>& out) {
  out.push_back({"section6", "a beam's 6-DOF stiffnesses, set while it is still 3 DOF (0: EI)", Effect::Setting,
                 {{"beam", Type::Block, "a 3-DOF beam"},
                  {"GJ", Type::Number, "torsional stiffness [N m^2]", {0, kInf}},
                  {"EIy", Type::Number, "bending about the section's y axis [N m^2]", {0, kInf}},
                  {"EIz", Type::Number, "bending about the section's z axis [N m^2]", {0, kInf}}},
                 Returns::Nothing, [](Target& t, Args& a) {
                   Model& m = t.model;
                   const BlockId b = block(a, 0);
                   if (m.blocks[b].kind != BlockKind::Beam) throw ArgumentError(0, "is not a beam");
                   if (m.blocks[b].dofs != 3) throw ArgumentError(0, "is already 6 DOF");
                   Section sec = m.blocks[b].section;
                   sec.GJ = a[1].number;
                   sec.EIy = a[2].number;
                   sec.EIz = a[3].number;
                   m.blocks[b].section = sec;
                   return nothing();
                 }});
  out.back().lua = "";  // m:beam{GJ =, EIy =, EIz =}
  out.push_back({"formulation",
                 "switches a beam between 3 and 6 DOF, or a patch between bars and CST membranes (thesis 5.5.2)",
                 Effect::Topology,
                 {{"block", Type::Block, "a beam or a patch"},
                  {"kind", Type::Word, "beam: 3 or 6; patch: bars, form (form-finding) or analysis", {}, {"3", "6", "bars", "form", "analysis"}},
                  {"sigma_warp", Type::Number, "prescribed (form) or carried (analysis) warp stress [N/m]", {}, {}, true},
                  {"sigma_weft", Type::Number, "weft stress [N/m]", {}, {}, true},
                  {"dxx", Type::Number, "analysis stiffness [N/m]", {}, {}, true},
                  {"dxy", Type::Number, "analysis stiffness [N/m]", {}, {}, true},
                  {"dyx", Type::Number, "analysis stiffness [N/m]", {}, {}, true},
                  {"dyy", Type::Number, "analysis stiffness [N/m]", {}, {}, true},
                  {"G", Type::Number, "analysis shear stiffness [N/m]", {}, {}, true},
                  {"triangles", Type::Particles, "CST triangles, three particles each, the first side along the warp", {}, {}, true}},
                 Returns::Nothing, apply_formulation, 0, Returns::Nothing, nullptr, false, formulation_on_line});
  out.push_back({"patch_prestress",
                 "warp and weft prestress of a patch's bars [N]: the first warp_edges pairs of `edges` are warp, the "
                 "rest weft; an edge in both (a seam) takes the mean",
                 Effect::Setting,
                 {{"patch", Type::Block, "a patch"},
                  {"warp", Type::Number, "prestress of a warp bar [N]", {0, kInf}},
                  {"weft", Type::Number, "prestress of a weft bar [N]", {0, kInf}},
                  {"warp_edges", Type::Count, "how many of the pairs are warp", {0, kInf}},
                  {"edges", Type::Particles, "particle pairs: every edge of the patch, warp first"}},
                 Returns::Nothing, [](Target& t, Args& a) {
                   const std::vector<std::uint32_t>& ids = a[4].ids;
                   if (ids.size() % 2) throw ArgumentError(4, "needs two particles per edge");
                   const std::size_t warp = std::size_t(a[3].id);
                   if (2 * warp > ids.size()) throw ArgumentError(3, "is more than the pairs given");
                   std::vector<Model::EdgePair> warp_edges, weft_edges;
                   for (std::size_t k = 0; k < ids.size(); k += 2)
                     (k < 2 * warp ? warp_edges : weft_edges).push_back({ids[k], ids[k + 1]});
                   t.model.set_patch_prestress(block(a, 0), a[1].number, a[2].number, warp_edges, weft_edges);
                   return nothing();
                 }});
  out.back().lua = "";  // m:patch_prestress(patch, {warp, weft} [, {warp =, seams =}]) (grammar/lua_patch_formulation.cpp)
  out.push_back({"orientation", "sets a particle's node frame (a rotation quaternion; normalised)", Effect::Setting,
                 {{"particle", Type::Particle, "a particle"},
                  {"w", Type::Number, "quaternion w"},
                  {"x", Type::Number, "quaternion x"},
                  {"y", Type::Number, "quaternion y"},
                  {"z", Type::Number, "quaternion z"}},
                 Returns::Nothing, [](Target& t, Args& a) {
                   // Recorded as given: replay normalises the same numbers the
                   // same way (a normalised copy would normalise again to other bits).
                   t.model.set_orientation(particle(a, 0), Quat(a[1].number, a[2].number, a[3].number, a[4].number));
                   return nothing();
                 }});
  out.push_back({"rest_shape",
                 "a beam's rest shape: straight (bending-active: the built curve is prestress) or current (stress free as it is now)",
                 Effect::Topology,
                 {{"beam", Type::Block, "a beam"}, {"shape", Type::Word, "", {}, {"straight", "current"}}},
                 Returns::Nothing,
                 [](Target& t, Args& a) {
                   RestShape r;
                   parse_rest_shape(a[1].word, r);
                   t.model.set_rest_shape(block(a, 0), r);
                   return nothing();
                 },
                 1, Returns::Word, [](Target& t, const Args& a) {
                   Result r;
                   r.kind = Returns::Word;
                   r.word = rest_shape_name(t.model.rest_shape(block(a, 0)));
                   return r;
                 }});
  out.push_back({"clamp", "fixes the tangent of a 3-DOF beam at its end particle (a clamp hinge)", Effect::Topology,
                 {{"particle", Type::Particle, "the beam's end"},
                  {"beam", Type::Block, "the beam"},
                  {"direction", Type::Vector, "the fixed tangent into the beam; 0 0 0: along its end segment now"}},
                 Returns::Nothing, [](Target& t, Args& a) {
                   t.model.set_clamp(particle(a, 0), block(a, 1), a[2].vector);
                   return nothing();
                 }});
  out.back().lua = "";  // m:clamp(p, beam [, direction]) (grammar/lua_clamp.cpp)
  out.push_back({"unclamp", "frees a clamped beam end", Effect::Topology,
                 {{"particle", Type::Particle, "the beam's end"}, {"beam", Type::Block, "the beam"}}, Returns::Nothing,
                 [](Target& t, Args& a) {
                   t.model.remove_clamp(particle(a, 0), block(a, 1));
                   return nothing();
                 }});
  out.push_back({"connection",
                 "how two beams sharing a particle are connected there: pinned (no moment) or rigid (keeps its built "
                 "angle, carries moment)",
                 Effect::Topology,
                 {{"particle", Type::Particle, "the shared particle"},
                  {"a", Type::Block, "a beam at it"},
                  {"b", Type::Block, "another beam at it (a: the beam's two ends)"},
                  {"kind", Type::Word, "", {}, {"rigid", "pinned"}}},
                 Returns::Nothing,
                 [](Target& t, Args& a) {
                   JointKind k;
                   parse_joint_kind(a[3].word, k);
                   t.model.set_joint(particle(a, 0), block(a, 1), block(a, 2), k);
                   return nothing();
                 },
                 3, Returns::Word, [](Target& t, const Args& a) {
                   Result r;
                   r.kind = Returns::Word;
                   r.word = joint_kind_name(t.model.joint_kind(particle(a, 0), block(a, 1), block(a, 2)));
                   return r;
                 }});
  out.push_back({"torque",
                 "an external moment on a particle [N m]: on a 6-DOF beam a torque, on a 3-DOF beam force couples across "
                 "its segments",
                 Effect::Setting,
                 {{"particle", Type::Particle, "a particle"}, {"moment", Type::Vector, "the moment [N m]"}},
                 Returns::Nothing,
                 [](Target& t, Args& a) {
                   t.model.set_moment(particle(a, 0), a[1].vector);
                   return nothing();
                 },
                 1, Returns::Vector,
                 [](Target& t, const Args& a) { return vector_result(t.model.particles.moment[particle(a, 0)]); }});
  out.push_back({"rest_length", "the rest length of the beam (else cable) edge between consecutive particles",
                 Effect::Setting,
                 {{"a", Type::Particle, "one particle"}, {"b", Type::Particle, "its neighbour"},
                  {"length", Type::Number, "rest length [m]", {0, kMaxRestLength, true}}},
                 Returns::Nothing,
                 [](Target& t, Args& a) {
                   t.model.set_rest_length(particle(a, 0), particle(a, 1), a[2].number);
                   return nothing();
                 },
                 2, Returns::Number,
                 [](Target& t, const Args& a) { return number_result(t.model.edge_rest_length(particle(a, 0), particle(a, 1))); }});
  out.push_back({"pressure",
                 "a uniform pressure on a patch [Pa], a follower load along its faces' normals: towards `towards` "
                 "when given, else outward; negative sucks",
                 Effect::Setting,
                 {{"patch", Type::Block, "a patch"},
                  {"p", Type::Number, "the pressure [Pa]"},
                  {"towards", Type::Vector, "the side it pushes (default or {0, 0, 0}: outward, away from the patch's centroid)",
                   {}, {}, true}},
                 Returns::Nothing,
                 [](Target& t, Args& a) {
                   if (!a[2].given) {  // outward; the journal line always carries the side
                     a[2].vector = Vec3::Zero();
                     a[2].given = true;
                   }
                   t.model.set_pressure(block(a, 0), a[1].number, a[2].vector);
                   return nothing();
                 },
                 1, Returns::Number,
                 [](Target& t, const Args& a) { return number_result(t.model.blocks[block(a, 0)].pressure); }});
  out.push_back({"area_load",
                 "a load on a patch per area projected along a direction [N/m^2], acting along it: snow on the plan "
                 "area by default",
                 Effect::Setting,
                 {{"patch", Type::Block, "a patch"},
                  {"q", Type::Number, "the load per projected area [N/m^2]; 0 removes it"},
                  {"direction", Type::Vector, "the direction it acts along and projects on (default {0, 0, -1}: snow)", {}, {}, true}},
                 Returns::Nothing,
                 [](Target& t, Args& a) {
                   if (!a[2].given) {  // snow; the journal line always carries the direction
                     a[2].vector = Vec3(0, 0, -1);
                     a[2].given = true;
                   }
                   t.model.set_area_load(block(a, 0), a[1].number, a[2].vector);
                   return nothing();
                 },
                 1, Returns::Number,
                 [](Target& t, const Args& a) { return number_result(t.model.blocks[block(a, 0)].area_load); }});
  out.push_back({"joint", "a rotational joint where exactly two beams cross (thesis 6.5.2)", Effect::Setting,
                 {{"particle", Type::Particle, "the crossing"},
                  {"angle", Type::Number, "the target included angle [rad]"},
                  {"stiffness", Type::Number, "[N/m]", {0, kInf}}},
                 Returns::Joint, [](Target& t, Args& a) {
                   Result r;
                   r.kind = Returns::Joint;
                   r.index = t.model.add_joint(particle(a, 0), a[1].number, a[2].number);
                   return r;
                 }});
  out.push_back({"joint_angle", "sets a joint's target angle (a value per step, as a sensor sends it)", Effect::Setting,
                 {{"joint", Type::Joint, "a joint"}, {"angle", Type::Number, "the target included angle [rad]"}},
                 Returns::Nothing, [](Target& t, Args& a) {
                   t.model.set_joint_angle(std::size_t(a[0].id), a[1].number);
                   return nothing();
                 }});
}

}  // namespace tendril::command
