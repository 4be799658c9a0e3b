#include "io/ccx.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "model/model.hpp"

namespace tendril {

namespace {

// ccx reads a number without a decimal point as an integer (a degree of
// freedom in *SPRING), so every real carries one or an exponent; and it reads
// at most 20 characters a field: 14 significant digits ("-1.2345678901234e-05").
std::string num(double v) {
  char buf[40];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 14);
  std::string s(buf, r.ptr);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".";
  return s;
}

std::string vec(const Vec3& v) { return num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()); }

// Some unit vector across the chord t, as steady as possible: the global axis
// least aligned with it, with its component along t removed.
Vec3 across(const Vec3& t) {
  int k = 0;
  for (int c = 1; c < 3; ++c)
    if (std::abs(t[c]) < std::abs(t[k])) k = c;
  const Vec3 axis = Vec3::Unit(k);
  return (axis - axis.dot(t) * t).normalized();
}

// An axial member that keeps its prestress: a SPRINGA (not expanded into
// solids as ccx's T3D2 is), force N0 + k (l - l0) against its length now l0,
// zero below the slack length when tension-only. The table spans elongations
// from -l0 (the two nodes on one another) to +l0 (twice as long); ccx holds
// the end values beyond it.
std::string spring_table(double N0, double k, double l0, bool tension_only) {
  std::string s;
  auto point = [&](double e) { s += num(N0 + k * e) + ", " + num(e) + "\n"; };
  auto zero = [&](double e) { s += "0., " + num(e) + "\n"; };
  if (tension_only && N0 <= 0) {
    // Slack now: no force until it is stretched by -N0 / k.
    const double slack = k > 0 ? -N0 / k : l0;
    zero(-l0);
    if (slack < l0) {
      zero(slack);
      s += num(k * (l0 - slack)) + ", " + num(l0) + "\n";
    } else {
      zero(l0);
    }
    return s;
  }
  if (tension_only && k > 0 && N0 / k < l0) {
    zero(-l0);
    zero(-N0 / k);
  } else {
    point(-l0);
  }
  point(0);
  point(l0);
  return s;
}

struct Deck {
  std::string nodes, elements, sets, properties, initial, boundary, equations, loads, dloads, notes;
  int next_element = 1;
};

// Whether beam b turns anywhere now (a straight-at-rest beam then carries
// bending that the deck cannot hold).
bool bent(const Model& m, BlockId b) {
  const std::vector<ParticleId> ps = m.particles_of(b);
  const std::size_t n = ps.size();
  const bool closed = m.blocks[b].closed;
  for (std::size_t k = closed ? 0 : 1; k < (closed ? n : n - 1); ++k) {
    const Vec3 a = m.particles.position[ps[k]] - m.particles.position[ps[(k + n - 1) % n]];
    const Vec3 c = m.particles.position[ps[(k + 1) % n]] - m.particles.position[ps[k]];
    if (a.cross(c).norm() > 1e-9 * a.norm() * c.norm()) return true;
  }
  return false;
}

// St Venant's torsion constant of a b x h rectangle over b h^3 (b >= h).
double torsion_factor(double b, double h) {
  const double r = h / b;
  return 1.0 / 3.0 - 0.21 * r * (1 - std::pow(r, 4) / 12);
}

}  // namespace

std::string ccx_string(const Model& m) {
  const Particles& P = m.particles;
  Deck d;
  std::vector<std::uint8_t> on_beam(P.capacity(), 0);
  int next_node = static_cast<int>(P.capacity()) + 1;  // duplicates of pinned beam joints

  // --- beams: B32R, a rectangle b x h that gives EA, EIy, EIz exactly ------
  // and GJ through Poisson's ratio, one element set per segment for its
  // section's orientation. Straight, with a middle node on the chord: ccx
  // expands a beam into solids, and its linear B31 bricks lock on a curved
  // beam (a polyline's bricks are trapezoids): a clamped GFRP arch of 16
  // segments came out 30 % too stiff, B32R within 0.5 % of the exact frame.
  std::map<std::pair<ParticleId, ParticleId>, const Beam6*> beam6_of;
  for (std::size_t e = 0; e < m.beam6s.size(); ++e) {
    const Beam6& b = m.beam6s[e];
    beam6_of[{std::min(b.i, b.j), std::max(b.i, b.j)}] = &b;
  }
  // Node of particle p for beam block b: p + 1, unless another beam took p
  // first and the two are pinned there (3-DOF beams meet pinned unless a
  // rigid joint joins them; 6-DOF beams share the particle's frame).
  std::map<ParticleId, std::vector<std::pair<BlockId, int>>> beam_nodes;  // p -> (block, node)
  std::set<std::pair<BlockId, BlockId>> rigid;  // blocks joined rigidly somewhere (3-DOF)
  for (const RigidJoint& j : m.rigid_joints)
    if (m.rigid_acts(j)) {
      const BlockId a = m.dart_block[j.a], b = m.dart_block[j.b];
      rigid.insert({std::min(a, b), std::max(a, b)});
    }
  auto node_for = [&](ParticleId p, BlockId b) {
    auto& taken = beam_nodes[p];
    for (auto& [blk, node] : taken)
      if (blk == b) return node;
    const bool six = m.blocks[b].dofs == 6;
    for (std::size_t k = 0; k < taken.size(); ++k) {
      const auto [blk, node] = taken[k];  // a copy: push_back below moves the vector
      const bool other_six = m.blocks[blk].dofs == 6;
      if ((six && other_six) || rigid.count({std::min(b, blk), std::max(b, blk)})) {
        taken.push_back({b, node});
        return node;
      }
    }
    if (taken.empty()) {
      taken.push_back({b, int(p) + 1});
      return int(p) + 1;
    }
    const int n = next_node++;
    taken.push_back({b, n});
    d.nodes += std::to_string(n) + ", " + vec(P.position[p]) + "\n";
    for (int dof = 1; dof <= 3; ++dof)
      d.equations += "2\n" + std::to_string(n) + ", " + std::to_string(dof) + ", 1., " + std::to_string(p + 1) +
                     ", " + std::to_string(dof) + ", -1.\n";
    return n;
  };

  std::string beam_elements;
  struct Prestress { int ni, nj; double N0, l0; };
  std::vector<Prestress> beam_prestress;  // on a parallel spring of no stiffness
  for (BlockId b : m.live_blocks()) {
    const Block& blk = m.blocks[b];
    if (blk.kind != BlockKind::Beam) continue;
    const Section& s = blk.section;
    const bool six = blk.dofs == 6;
    const double EIy = six ? s.bending_y() : s.EI, EIz = six ? s.bending_z() : s.EI;
    const double GJ = six ? s.torsion() : s.EI;
    if (!(s.EA > 0) || !(EIy > 0) || !(EIz > 0))
      throw ModelError("export_ccx: beam " + std::to_string(b) + " has no EA or EI; ccx needs both");
    // Section axis 1 along the beam's y (EIy = E a b^3 / 12 about it), 2 along z.
    const double a = std::sqrt(12 * EIz / s.EA), h = std::sqrt(12 * EIy / s.EA);
    const double E = s.EA / (a * h);
    const double J = torsion_factor(std::max(a, h), std::min(a, h)) * std::max(a, h) * std::pow(std::min(a, h), 3);
    double nu = E * J / (2 * GJ) - 1;
    if (nu < -0.95 || nu > 0.49) {
      d.notes += "** beam " + std::to_string(b) + ": GJ " + num(GJ) + " needs Poisson's ratio " + num(nu) +
                 "; clamped to [-0.95, 0.49]\n";
      nu = std::clamp(nu, -0.95, 0.49);
    }
    if (blk.rest == RestShape::Straight && bent(m, b))
      d.notes += "** beam " + std::to_string(b) +
                 ": straight at rest in tendril; exported stress free in its current shape (its bending "
                 "prestress is not in the deck)\n";
    if (!six) d.notes += "** beam " + std::to_string(b) + ": 3 DOF in tendril (no torsion); exported with GJ = EI\n";
    const std::string mat = "BEAM" + std::to_string(b);
    d.properties += "*MATERIAL, NAME=" + mat + "\n*ELASTIC\n" + num(E) + ", " + num(nu) + "\n";
    const std::vector<ParticleId> ps = m.particles_of(b);
    const std::size_t segments = blk.closed ? ps.size() : ps.size() - 1;
    for (std::size_t k = 0; k < segments; ++k) {
      const ParticleId i = ps[k], j = ps[(k + 1) % ps.size()];
      on_beam[i] = on_beam[j] = 1;
      const int ni = node_for(i, b), nj = node_for(j, b);
      const Vec3 chord = P.position[j] - P.position[i];
      const double l0 = chord.norm();
      const Vec3 t = chord / l0;
      Vec3 y = across(t);
      double L = m.edge_rest_length(i, j), prestress = s.prestress;
      if (six) {
        auto it = beam6_of.find({std::min(i, j), std::max(i, j)});
        if (it != beam6_of.end()) {
          const Beam6& e = *it->second;
          const ParticleId from = e.i;
          const Vec3 ey = (P.orientation[from] * e.end_i).toRotationMatrix().col(1);
          if ((ey - ey.dot(t) * t).norm() > 1e-6) y = (ey - ey.dot(t) * t).normalized();
          L = e.rest_length;
          prestress = e.prestress;
        }
      }
      const int el = d.next_element++, mid = next_node++;
      d.nodes += std::to_string(mid) + ", " + vec(0.5 * (P.position[i] + P.position[j])) + "\n";
      beam_elements += std::to_string(el) + ", " + std::to_string(ni) + ", " + std::to_string(mid) + ", " +
                       std::to_string(nj) + "\n";
      d.sets += "*ELSET, ELSET=B" + std::to_string(el) + "\n" + std::to_string(el) + "\n";
      d.properties += "*BEAM SECTION, ELSET=B" + std::to_string(el) + ", MATERIAL=" + mat +
                      ", SECTION=RECT\n" + num(a) + ", " + num(h) + "\n" + vec(y) + "\n";
      const double N0 = prestress + s.EA * (l0 - L) / L;
      if (N0 != 0) beam_prestress.push_back({ni, nj, N0, l0});
    }
  }
  if (!beam_elements.empty()) d.elements += "*ELEMENT, TYPE=B32R, ELSET=BEAMS\n" + beam_elements;

  // --- axial members: bars of cables and of bar patches (not of 3-DOF beams,
  // which are B31 above) as SPRINGA with their force now ------------------------
  std::string springs;
  auto add_spring = [&](int ni, int nj, double N0, double k, double l0, bool tension_only) {
    const int el = d.next_element++;
    springs += std::to_string(el) + ", " + std::to_string(ni) + ", " + std::to_string(nj) + "\n";
    const std::string set = "S" + std::to_string(el);
    d.sets += "*ELSET, ELSET=" + set + "\n" + std::to_string(el) + "\n";
    d.properties += "*SPRING, ELSET=" + set + ", NONLINEAR\n" + spring_table(N0, k, l0, tension_only);
  };
  std::size_t tension_only = 0;
  for (std::size_t e = 0; e < m.bars.size(); ++e) {
    const Bar& b = m.bars[e];
    if (m.blocks[m.dart_block[b.dart]].kind == BlockKind::Beam) continue;
    const double l0 = (P.position[b.j] - P.position[b.i]).norm();
    const double N0 = b.prestress + b.EA * (l0 - b.rest_length) / b.rest_length;
    add_spring(int(b.i) + 1, int(b.j) + 1, N0, b.EA / b.rest_length, l0, b.tension_only);
    tension_only += b.tension_only;
  }
  // A beam segment's axial force now: a spring of no stiffness beside it.
  for (const Prestress& q : beam_prestress) add_spring(q.ni, q.nj, q.N0, 0, q.l0, false);
  if (!beam_prestress.empty())
    d.notes += "** " + std::to_string(beam_prestress.size()) +
               " beam segments carry an axial force now: on parallel springs of no stiffness\n";
  if (!springs.empty()) d.elements += "*ELEMENT, TYPE=SPRINGA, ELSET=SPRINGS\n" + springs;

  // --- CST membranes: M3D3, thickness t, the in-plane stiffnesses d / t in
  // the triangle's warp frame (no coupling through the thickness, so the
  // expanded solid's plane stress is the membrane's), the stress now / t as
  // initial stress in global axes ---------------------------------------------
  std::string triangles;
  std::set<BlockId> membrane_materials;
  // Pressure (Model::set_pressure): each quad's area vector, oriented as the
  // pressure pushes, under each of its corner triples, so that a triangle
  // finds the side its pressure pushes.
  std::map<std::array<ParticleId, 3>, Vec3> pushes;
  std::vector<Vec3> pressure_force(P.capacity(), Vec3::Zero());
  for (BlockId b : m.live_blocks()) {
    const Block& blk = m.blocks[b];
    if (blk.kind != BlockKind::Patch || blk.pressure == 0) continue;
    for (const Model::Quad& q : m.pressure_quads(b)) {
      const Vec3 area = 0.5 * (P.position[q[2]] - P.position[q[0]]).cross(P.position[q[3]] - P.position[q[1]]);
      if (P.passive[q[0]] || P.passive[q[1]] || P.passive[q[2]] || P.passive[q[3]]) continue;  // dormant
      for (int skip = 0; skip < 4; ++skip) {
        std::array<ParticleId, 3> t;
        for (int k = 0, n = 0; k < 4; ++k)
          if (k != skip) t[n++] = q[k];
        std::sort(t.begin(), t.end());
        pushes[t] = area;
      }
      if (!blk.membrane.cst())  // bars: no face to load; the nodal forces of now, p A / 4 a corner
        for (ParticleId p : q) pressure_force[p] += 0.25 * blk.pressure * area;
    }
    d.notes += "** patch " + std::to_string(b) + ": pressure " + num(blk.pressure) +
               (blk.membrane.cst() ? " Pa on its triangles (*DLOAD, a follower load in ccx too; each corner takes a third of a triangle where tendril gives a quarter of a quad)\n"
                                   : " Pa as the nodal forces of its current shape (a bar patch has no faces in ccx): they keep their direction where tendril's turn with the quads\n");
  }
  // Area loads (Model::set_area_load): the nodal forces of the current
  // shape, q |A . d| d / 4 a corner, dead loads in ccx as in tendril (their
  // size follows the projected area in tendril only).
  for (BlockId b : m.live_blocks()) {
    const Block& blk = m.blocks[b];
    if (blk.kind != BlockKind::Patch || blk.area_load == 0) continue;
    for (const Model::Quad& q : m.area_load_quads(b)) {
      if (P.passive[q[0]] || P.passive[q[1]] || P.passive[q[2]] || P.passive[q[3]]) continue;  // dormant
      const Vec3 area = 0.5 * (P.position[q[2]] - P.position[q[0]]).cross(P.position[q[3]] - P.position[q[1]]);
      const Vec3 f = 0.25 * blk.area_load * std::abs(area.dot(blk.area_load_direction)) * blk.area_load_direction;
      for (ParticleId p : q) pressure_force[p] += f;
    }
    d.notes += "** patch " + std::to_string(b) + ": area load " + num(blk.area_load) +
               " N/m^2 as the nodal forces of its current shape\n";
  }
  const double t = kCcxMembraneThickness;
  for (std::size_t e = 0; e < m.csts.size(); ++e) {
    const Cst& c = m.csts[e];
    const BlockId b = m.dart_block[c.dart];
    const Membrane& mb = c.membrane;
    if (mb.mode != Membrane::Analysis)
      throw ModelError("export_ccx: patch " + std::to_string(b) +
                       " is a CST patch in form-finding: a stress no strain changes has no material in ccx; "
                       "switch it to analysis first (m:formulation(patch, \"cst\", {analysis = ...}))");
    if (membrane_materials.insert(b).second) {
      const double dxy = 0.5 * (mb.dxy + mb.dyx);
      if (mb.dxy != mb.dyx)
        d.notes += "** patch " + std::to_string(b) + ": dxy != dyx; ccx takes their mean " + num(dxy) + "\n";
      const double dmax = std::max({mb.dxx, mb.dyy, 1.0});
      const double G = mb.G > 0 ? mb.G : 1e-6 * dmax;
      if (!(mb.G > 0)) d.notes += "** patch " + std::to_string(b) + ": G = 0; ccx gets 1e-6 of dxx\n";
      d.properties += "*MATERIAL, NAME=MEMB" + std::to_string(b) + "\n*ELASTIC, TYPE=ORTHO\n" + num(mb.dxx / t) +
                      ", " + num(dxy / t) + ", " + num(mb.dyy / t) + ", 0., 0., " + num(dmax / t) + ", " +
                      num(G / t) + ", " + num(G / t) + "\n" + num(G / t) + ", 0.\n";
    }
    const Vec3 a = P.position[c.j] - P.position[c.i], bb = P.position[c.k] - P.position[c.i];
    const Vec3 n = a.cross(bb);
    const double twice_area = n.norm(), l1 = a.norm();
    if (!(twice_area > 1e-10 * std::max(a.squaredNorm(), bb.squaredNorm())))
      throw ModelError("export_ccx: patch " + std::to_string(b) + ": triangle of particles " +
                       std::to_string(c.i) + ", " + std::to_string(c.j) + ", " + std::to_string(c.k) +
                       " has no area");
    const Vec3 e1 = a / l1, e3 = n / twice_area, e2 = e3.cross(e1);
    // The stress now, as cst_forces.cpp takes it (eq. 3.37-3.38).
    const CstReference& r = c.ref;
    const double h = twice_area / l1, cc = bb.dot(e1);
    const double ex = l1 / r.l1 - 1, ey = h / r.h - 1, gamma = (cc - r.c * (1 + ex)) / r.h;
    const double sx = mb.sigma_warp + mb.dxx * ex + mb.dxy * ey;
    const double sy = mb.sigma_weft + mb.dyx * ex + mb.dyy * ey;
    const double tau = mb.G * gamma;
    const Mat3 S = (sx * e1 * e1.transpose() + sy * e2 * e2.transpose() +
                    tau * (e1 * e2.transpose() + e2 * e1.transpose())) / t;
    const int el = d.next_element++;
    const std::string id = std::to_string(el);
    if (m.blocks[b].pressure != 0) {
      std::array<ParticleId, 3> key{c.i, c.j, c.k};
      std::sort(key.begin(), key.end());
      auto it = pushes.find(key);
      if (it != pushes.end())  // P1 pushes along (j - i) x (k - i), P2 against it (checked on ccx 2.20)
        d.dloads += id + (n.dot(it->second) >= 0 ? ", P1, " : ", P2, ") + num(m.blocks[b].pressure) + "\n";
    }
    triangles += id + ", " + std::to_string(c.i + 1) + ", " + std::to_string(c.j + 1) + ", " +
                 std::to_string(c.k + 1) + "\n";
    d.sets += "*ELSET, ELSET=M" + id + "\n" + id + "\n";
    d.properties += "*ORIENTATION, NAME=O" + id + "\n" + vec(e1) + ", " + vec(e2) + "\n";
    d.properties += "*MEMBRANE SECTION, ELSET=M" + id + ", MATERIAL=MEMB" + std::to_string(b) +
                    ", ORIENTATION=O" + id + "\n" + num(t) + "\n";
    for (int ip = 1; ip <= 2; ++ip)  // the two points of the expanded wedge
      d.initial += id + ", " + std::to_string(ip) + ", " + num(S(0, 0)) + ", " + num(S(1, 1)) + ", " +
                   num(S(2, 2)) + ", " + num(S(0, 1)) + ", " + num(S(0, 2)) + ", " + num(S(1, 2)) + "\n";
  }
  if (!triangles.empty()) d.elements += "*ELEMENT, TYPE=M3D3, ELSET=MEMBRANES\n" + triangles;

  // --- nodes, supports, loads --------------------------------------------------
  std::string nodes;
  for (ParticleId p = 0; p < P.capacity(); ++p) {
    if (!P.valid(p) || P.degree[p] == 0) continue;
    nodes += std::to_string(p + 1) + ", " + vec(P.position[p]) + "\n";
    const std::string id = std::to_string(p + 1);
    std::uint8_t lock = P.lock[p];
    if (P.passive[p]) lock = kLockTranslation | kLockRotation;
    if (!on_beam[p]) lock &= kLockTranslation;
    for (int dof = 0; dof < 6; ++dof)
      if (lock >> dof & 1) d.boundary += id + ", " + std::to_string(dof + 1) + ", " + std::to_string(dof + 1) + "\n";
    const Vec3 f = P.load[p] + P.mass(p) * m.gravity + pressure_force[p];
    for (int k = 0; k < 3; ++k)
      if (f[k] != 0) d.loads += id + ", " + std::to_string(k + 1) + ", " + num(f[k]) + "\n";
    const Vec3 mo = P.moment[p];
    if (!mo.isZero(0)) {
      if (on_beam[p])
        for (int k = 0; k < 3; ++k)
          if (mo[k] != 0) d.loads += id + ", " + std::to_string(k + 4) + ", " + num(mo[k]) + "\n";
    }
  }
  for (Dart c : m.clamp_darts)
    if (m.clamp_acts(c)) {
      const ParticleId p = m.dart_particle[c];
      if ((P.lock[p] & kLockTranslation) == kLockTranslation)
        d.boundary += std::to_string(p + 1) + ", 4, 6\n";
      else
        d.notes += "** the clamp at particle " + std::to_string(p) + " of a free end is not in the deck\n";
    }
  if (!m.goals.empty()) d.notes += "** " + std::to_string(m.goals.size()) + " goals are not in the deck\n";
  if (tension_only)
    d.notes += "** " + std::to_string(tension_only) + " tension-only bars: springs with no force below their slack length\n";

  std::string out;
  out += "** tendril: the model's current state for CalculiX (ccx -i NAME); docs/calculix.md.\n";
  out += "** Node n is particle n - 1. Units: those of the model (N, m).\n";
  out += d.notes;
  out += "*HEADING\ntendril model\n";
  out += "*NODE, NSET=NALL\n" + nodes + d.nodes;
  out += d.elements + d.sets + d.properties;
  if (!d.equations.empty()) out += "*EQUATION\n" + d.equations;
  if (!d.initial.empty()) out += "*INITIAL CONDITIONS, TYPE=STRESS\n" + d.initial;
  if (!d.boundary.empty()) out += "*BOUNDARY\n" + d.boundary;
  out += "*STEP, NLGEOM, INC=10000\n*STATIC\n0.05, 1., 1e-5, 0.25\n";
  if (!d.loads.empty()) out += "*CLOAD\n" + d.loads;
  if (!d.dloads.empty()) out += "*DLOAD\n" + d.dloads;
  out += "*NODE PRINT, NSET=NALL, FREQUENCY=10000\nU\n*NODE FILE, FREQUENCY=10000\nU\n*END STEP\n";
  return out;
}

void save_ccx(const Model& m, const std::string& path) { write_file_atomically(path, ccx_string(m)); }

std::vector<CcxDisplacement> parse_ccx_displacements(const std::string& text, const std::string& name) {
  std::vector<CcxDisplacement> last;
  std::size_t pos = 0, line_no = 0;
  bool found = false;
  while (pos < text.size()) {
    const std::size_t at = text.find("displacements (vx,vy,vz)", pos);
    if (at == std::string::npos) break;
    found = true;
    line_no = std::count(text.begin(), text.begin() + at, '\n') + 1;
    std::size_t p = text.find('\n', at);
    std::vector<CcxDisplacement> block;
    while (p != std::string::npos && p < text.size()) {
      const std::size_t start = p + 1, end = std::min(text.find('\n', start), text.size());
      const std::string line = text.substr(start, end - start);
      ++line_no;
      p = end < text.size() ? end : std::string::npos;
      if (line.find_first_not_of(" \t\r") == std::string::npos) {
        if (block.empty()) continue;  // the blank line after the heading
        break;
      }
      CcxDisplacement u;
      const char* s = line.c_str();
      char* next = nullptr;
      u.node = static_cast<int>(std::strtol(s, &next, 10));
      bool ok = next != s;
      for (int k = 0; k < 3 && ok; ++k) {
        s = next;
        u.u[k] = std::strtod(s, &next);
        ok = next != s && std::isfinite(u.u[k]);
      }
      if (!ok) {
        if (block.empty()) throw InputError(name + ":" + std::to_string(line_no) + ": not a displacement line: " + line);
        break;  // the next heading
      }
      block.push_back(u);
    }
    last = std::move(block);
    pos = at + 1;
  }
  if (!found) throw InputError(name + ": no nodal displacements (ccx writes them with *NODE PRINT ... U)");
  return last;
}

std::vector<CcxDisplacement> read_ccx_displacements(const std::string& dat_path) {
  return parse_ccx_displacements(read_input_file(dat_path), dat_path);
}

}  // namespace tendril
