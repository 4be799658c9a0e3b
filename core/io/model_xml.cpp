// The model database: writing walks the live model in id order; reading first
// turns the whole document into plain records (every check with the file's
// line, element and attribute), then builds. Building happens twice, first
// into a scratch model, so that even a failure the checks did not foresee
// leaves the caller's model untouched.
#include "io/model_xml.hpp"

#include <tinyxml2.h>

#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "model/limits.hpp"
#include "physics/settings_check.hpp"
#include "query/element_results.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

namespace tendril {

namespace {

// An undirected edge by its sorted particle pair.
std::pair<unsigned, unsigned> edge_key(unsigned x, unsigned y) { return {std::min(x, y), std::max(x, y)}; }

constexpr int kVersion = 1;

// The bounds the commands check too (model/limits.hpp), in their words.
bool rest_in_range(double rest) { return rest > 0 && rest <= kMaxRestLength; }
constexpr const char* kRestRange = "must be > 0 and <= 1e+13";
constexpr const char* kLineMassRange = "must be from 0 to 1e+12";

// A name or value as an error message shows it: at most 40 characters, so
// that a 50 MB attribute does not come back as a 50 MB message.
std::string clipped(const char* v, std::size_t limit = 40) {
  const std::size_t n = std::strlen(v);
  if (n <= limit) return v;
  return std::string(v, limit - 8) + "... (" + std::to_string(n) + " characters)";
}
std::string quoted(const char* v) { return "\"" + clipped(v) + "\""; }

// 17 significant digits: every double reads back to the same bits.
std::string number(double v) {
  char buf[40];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  return std::string(buf, r.ptr);
}

// --- patches as quad grids ------------------------------------------------------

// A patch as add_quad_grid builds it: nodes row-major, one rest length per
// grid edge in edges() order (horizontal edges row by row, then vertical).
struct QuadGrid {
  struct Edge {
    std::size_t a, b, index;  // grid node indices
  };
  int rows = 0, cols = 0;
  std::vector<ParticleId> nodes;
  std::vector<double> rest;
  std::vector<double> prestress;  // per edge: its own (NaN: the section's)

  static std::vector<Edge> edges(int rows, int cols) {
    std::vector<Edge> out;
    const std::size_t R = std::size_t(rows), C = std::size_t(cols);
    for (std::size_t r = 0; r < R; ++r)
      for (std::size_t c = 0; c + 1 < C; ++c) out.push_back({r * C + c, r * C + c + 1, out.size()});
    for (std::size_t r = 0; r + 1 < R; ++r)
      for (std::size_t c = 0; c < C; ++c) out.push_back({r * C + c, (r + 1) * C + c, out.size()});
    return out;
  }
  std::vector<Edge> edges() const { return edges(rows, cols); }
};

// Reads the grid back from the map, taking `d00` as quad (0,0)'s dart at its
// first corner on its top side, the way add_quad_grid links the darts: in a
// quad, alpha1(alpha0(.)) steps from side k to side k+1, the right neighbour
// is sewn to side 1 and the one below to side 2.
bool walk_quad_grid(const Model& m, BlockId b, Dart d00, QuadGrid& g) {
  const GMap& map = m.map;
  auto a = [&](int i, Dart d) { return map.alpha(i, d); };
  auto side1 = [&](Dart q) { return a(1, a(0, q)); };
  auto side2 = [&](Dart q) { return a(1, a(0, side1(q))); };
  auto right = [&](Dart q) { Dart s = side1(q); return map.is_free(2, s) ? kNoDart : a(1, a(2, s)); };
  auto down = [&](Dart q) { Dart s = side2(q); return map.is_free(2, s) ? kNoDart : a(0, a(2, s)); };

  const std::size_t total = m.blocks[b].darts, quads = total / 8;
  if (total == 0 || total % 8 != 0) return false;
  if (!map.is_free(2, d00) || !map.is_free(2, a(1, d00))) return false;
  std::size_t qr = 1, qc = 1;
  for (Dart q = right(d00); q != kNoDart; q = right(q))
    if (++qc > quads) return false;
  for (Dart q = down(d00); q != kNoDart; q = down(q))
    if (++qr > quads) return false;
  if (qr * qc != quads) return false;

  std::vector<Dart> start(quads, kNoDart);
  std::set<Dart> seen;
  Dart row = d00;
  for (std::size_t r = 0; r < qr; ++r, row = down(row)) {
    if (row == kNoDart) return false;
    Dart q = row;
    for (std::size_t c = 0; c < qc; ++c, q = right(q)) {
      if (q == kNoDart || map.orbit_size(kFaceOrbit, q) != 8) return false;
      for (Dart x : map.orbit(kFaceOrbit, q))
        if (!seen.insert(x).second) return false;
      if (map.is_free(2, q) != (r == 0) || map.is_free(2, a(1, q)) != (c == 0)) return false;
      start[r * qc + c] = q;
    }
    if (q != kNoDart) return false;
  }
  for (std::size_t r = 0; r < qr; ++r)
    for (std::size_t c = 0; c < qc; ++c)
      if (down(start[r * qc + c]) != (r + 1 < qr ? start[(r + 1) * qc + c] : kNoDart)) return false;

  const std::size_t R = qr + 1, C = qc + 1;
  g.rows = int(R);
  g.cols = int(C);
  g.nodes.assign(R * C, kNone);
  auto put = [&](std::size_t r, std::size_t c, Dart d) {
    ParticleId p = m.dart_particle[d];
    ParticleId& slot = g.nodes[r * C + c];
    if (slot != kNone && slot != p) return false;
    slot = p;
    return true;
  };
  for (std::size_t r = 0; r < qr; ++r)
    for (std::size_t c = 0; c < qc; ++c) {
      Dart q = start[r * qc + c];
      if (!put(r, c, q) || !put(r, c + 1, a(0, q)) || !put(r + 1, c + 1, a(0, side1(q))) ||
          !put(r + 1, c, a(0, side2(q))))
        return false;
    }
  std::vector<ParticleId> sorted = g.nodes;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;

  g.rest.clear();
  g.prestress.clear();
  for (const QuadGrid::Edge& e : g.edges()) {
    const std::size_t r = e.a / C, c = e.a % C;
    Dart d;
    if (e.b == e.a + 1)  // horizontal: the top side of the quad below it, or the bottom one of the last row
      d = r < qr ? start[r * qc + c] : side2(start[(qr - 1) * qc + c]);
    else  // vertical: the left side of the quad right of it, or the right one of the last column
      d = c < qc ? a(1, start[r * qc + c]) : side1(start[r * qc + qc - 1]);
    g.rest.push_back(m.rest_length[d]);
    g.prestress.push_back(m.edge_prestress[d]);
  }
  return true;
}

bool find_quad_grid(const Model& m, BlockId b, QuadGrid& g) {
  const Dart first = m.blocks[b].dart;
  if (walk_quad_grid(m, b, first, g)) return true;
  std::vector<Dart> darts = m.map.orbit(kComponentOrbit, first);
  std::sort(darts.begin(), darts.end());
  for (Dart d : darts)
    if (d != first && walk_quad_grid(m, b, d, g)) return true;
  return false;
}

// Any other patch (paving, Catmull-Clark, projection: meshing/) as its quads
// and edges in file ids, in an order that does not depend on dart numbers:
// each quad from its smallest id towards its smaller neighbour, quads sorted;
// edges as (smaller, larger) id, sorted, with their rest lengths.
struct QuadList {
  struct Edge {
    double rest, prestress;  // prestress: the edge's own (NaN: the section's)
  };
  std::vector<std::array<unsigned, 4>> quads;
  std::vector<std::pair<std::pair<unsigned, unsigned>, Edge>> edges;
};

QuadList quad_list(const Model& m, BlockId b, const std::vector<unsigned>& dense) {
  QuadList out;
  std::vector<Dart> darts = m.map.orbit(kComponentOrbit, m.blocks[b].dart);
  std::sort(darts.begin(), darts.end());
  std::set<Dart> done;
  std::map<std::pair<unsigned, unsigned>, QuadList::Edge> rest;
  for (Dart d : darts) {
    const unsigned a = dense[m.dart_particle[d]], c = dense[m.dart_particle[m.map.alpha(0, d)]];
    rest.emplace(edge_key(a, c), QuadList::Edge{m.rest_length[d], m.edge_prestress[d]});
    if (done.count(d)) continue;
    for (Dart x : m.map.orbit(kFaceOrbit, d)) done.insert(x);
    std::array<unsigned, 4> q{};
    Dart x = d;
    for (int k = 0; k < 4; ++k, x = m.map.alpha(1, m.map.alpha(0, x))) q[k] = dense[m.dart_particle[x]];
    const int first = int(std::min_element(q.begin(), q.end()) - q.begin());
    const int step = q[(first + 1) % 4] < q[(first + 3) % 4] ? 1 : 3;
    std::array<unsigned, 4> canonical{};
    for (int k = 0; k < 4; ++k) canonical[k] = q[(first + k * step) % 4];
    out.quads.push_back(canonical);
  }
  std::sort(out.quads.begin(), out.quads.end());
  out.edges.assign(rest.begin(), rest.end());
  // What add_patch would refuse on loading (merges can make such patches).
  std::map<std::pair<unsigned, unsigned>, int> uses;
  bool valid = true;
  for (const auto& q : out.quads)
    for (int k = 0; k < 4; ++k) {
      valid = valid && q[k] != q[(k + 1) % 4] && q[k] != q[(k + 2) % 4];
      valid = valid && ++uses[{std::min(q[k], q[(k + 1) % 4]), std::max(q[k], q[(k + 1) % 4])}] <= 2;
    }
  if (!valid)
    throw ModelError("save_model_xml: patch " + std::to_string(b) +
                     " is neither a quad grid of distinct particles nor a set of quads with four distinct corners "
                     "and edges in at most two quads; the model database holds only those");
  return out;
}

// --- writing -----------------------------------------------------------------

class Writer {
 public:
  explicit Writer(tinyxml2::XMLPrinter& out) : out_(out) {}
  void open(const char* name) { out_.OpenElement(name); }
  void close() { out_.CloseElement(); }
  void attr(const char* name, double v) { out_.PushAttribute(name, number(v).c_str()); }
  void attr(const char* name, unsigned v) { out_.PushAttribute(name, std::to_string(v).c_str()); }
  void attr(const char* name, const char* v) { out_.PushAttribute(name, v); }
  // 12 significant digits: results (write_results), whose last bits may
  // depend on which way an element is walked.
  void result(const char* name, double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.12g", v);
    out_.PushAttribute(name, buf);
  }

 private:
  tinyxml2::XMLPrinter& out_;
};

void write_section(Writer& w, const Section& s) {
  w.attr("EA", s.EA);
  w.attr("EI", s.EI);
  w.attr("prestress", s.prestress);
  w.attr("line_mass", s.line_mass);
}

// <results> (issue 14): what the model carries at its saved state, for the
// tools that read the file (query/element_results.hpp), derived from the
// state and so ignored on load (a loaded model computes them again). Only
// quantities that do not depend on which way an element is walked are
// written, each element by its particles in ascending file id, so that a
// model saved, loaded and saved again writes the same bytes: per line
// element (bar, cable segment, beam link or 6-DOF element) the axial force
// [N], strain, slack flag, and on beams the resultant moment [N m] and the
// curvature [1/m] at the end `at` where they are larger; per 3-DOF beam
// vertex its curvature and moment; per CST triangle its stresses [N/m] in
// its own frame and the principal stresses. Signed moments, torsion,
// stresses with sections and reactions are in m:results and the VTK files.
void write_results(Writer& w, const Model& m, const std::vector<unsigned>& dense) {
  w.open("results");
  unsigned id = 0;
  for (BlockId b : m.live_blocks()) {
    const BlockResults r = element_results(m, b);
    const bool beam = m.blocks[b].kind == BlockKind::Beam;
    std::vector<const LineResult*> lines;
    for (const LineResult& l : r.lines) lines.push_back(&l);
    auto ends = [&](const LineResult* l) { return std::minmax(dense[l->a], dense[l->b]); };
    std::stable_sort(lines.begin(), lines.end(), [&](auto* x, auto* y) { return ends(x) < ends(y); });
    for (const LineResult* l : lines) {
      w.open("line");
      w.attr("block", id);
      w.attr("a", ends(l).first);
      w.attr("b", ends(l).second);
      w.result("axial", l->axial);
      w.result("strain", l->strain);
      if (l->slack) w.attr("slack", 1u);
      if (beam) {
        w.attr("at", dense[l->at]);
        w.result("moment", l->moment);
        w.result("curvature", l->curvature);
      }
      w.close();
    }
    std::vector<const VertexResult*> vertices;
    for (const VertexResult& v : r.vertices) vertices.push_back(&v);
    std::stable_sort(vertices.begin(), vertices.end(), [&](auto* x, auto* y) { return dense[x->p] < dense[y->p]; });
    for (const VertexResult* v : vertices) {
      w.open("vertex");
      w.attr("block", id);
      w.attr("p", dense[v->p]);
      w.result("curvature", v->curvature);
      w.result("moment", v->moment);
      w.close();
    }
    std::vector<const TriangleResult*> triangles;
    for (const TriangleResult& t : r.triangles) triangles.push_back(&t);
    auto corners = [&](const TriangleResult* t) { return std::array{dense[t->i], dense[t->j], dense[t->k]}; };
    std::stable_sort(triangles.begin(), triangles.end(), [&](auto* x, auto* y) { return corners(x) < corners(y); });
    for (const TriangleResult* t : triangles) {
      w.open("triangle");
      w.attr("block", id);
      for (int k = 0; k < 3; ++k) w.attr(k == 0 ? "a" : k == 1 ? "b" : "c", corners(t)[std::size_t(k)]);
      w.result("warp", t->warp);
      w.result("weft", t->weft);
      w.result("shear", t->shear);
      w.result("s1", t->s1);
      w.result("s2", t->s2);
      w.close();
    }
    ++id;
  }
  w.close();
}

// A beam's formulation and the section constants only the 6-DOF beam reads.
void write_beam_section(Writer& w, const Block& blk) {
  w.attr("dofs", unsigned(blk.dofs));
  write_section(w, blk.section);
  w.attr("GJ", blk.section.GJ);
  w.attr("EIy", blk.section.EIy);
  w.attr("EIz", blk.section.EIz);
}

void write_quat(Writer& w, const char* const names[4], const Quat& q) {
  w.attr(names[0], q.w());
  w.attr(names[1], q.x());
  w.attr(names[2], q.y());
  w.attr(names[3], q.z());
}

constexpr const char* kFrameNames[4] = {"qw", "qx", "qy", "qz"};
constexpr const char* kEndANames[4] = {"aw", "ax", "ay", "az"};
constexpr const char* kEndBNames[4] = {"bw", "bx", "by", "bz"};
constexpr const char* kQuadNames[4] = {"a", "b", "c", "d"};  // <quad>: corners in order

// A clamped beam end (Model::set_clamp): its fixed tangent, on its <node>.
void write_clamp(Writer& w, const Model& m, Dart d) {
  if (!m.map.is_free(1, d) || m.clamp[d].isZero(0)) return;
  w.attr("tx", m.clamp[d].x());
  w.attr("ty", m.clamp[d].y());
  w.attr("tz", m.clamp[d].z());
}

// A patch's formulation (attributes): nothing for bars.
void write_membrane(Writer& w, const Membrane& mem) {
  if (!mem.cst()) return;
  w.attr("membrane", membrane_mode_name(mem.mode));
  w.attr("sigma_warp", mem.sigma_warp);
  w.attr("sigma_weft", mem.sigma_weft);
  if (mem.mode != Membrane::Analysis) return;
  w.attr("dxx", mem.dxx);
  w.attr("dxy", mem.dxy);
  w.attr("dyx", mem.dyx);
  w.attr("dyy", mem.dyy);
  w.attr("G", mem.G);
}

// A patch's pressure (attributes): nothing without one.
void write_pressure(Writer& w, const Block& blk) {
  if (blk.area_load != 0) {
    w.attr("area_load", blk.area_load);
    w.attr("area_x", blk.area_load_direction.x());
    w.attr("area_y", blk.area_load_direction.y());
    w.attr("area_z", blk.area_load_direction.z());
  }
  if (blk.pressure == 0) return;
  w.attr("pressure", blk.pressure);
  if (blk.pressure_towards == Vec3::Zero()) return;
  w.attr("towards_x", blk.pressure_towards.x());
  w.attr("towards_y", blk.pressure_towards.y());
  w.attr("towards_z", blk.pressure_towards.z());
}

// A CST patch's triangles (children), sorted by their file ids.
void write_triangles(Writer& w, const Model& m, BlockId b, const std::vector<unsigned>& dense) {
  if (!m.blocks[b].membrane.cst()) return;
  std::vector<CstReference> refs;
  const std::vector<Model::Triangle> tris = m.patch_triangles(b, &refs);
  std::vector<std::pair<std::array<unsigned, 3>, CstReference>> rows;
  for (std::size_t t = 0; t < tris.size(); ++t)
    rows.push_back({{dense[tris[t][0]], dense[tris[t][1]], dense[tris[t][2]]}, refs[t]});
  std::sort(rows.begin(), rows.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
  const bool analysis = m.blocks[b].membrane.mode == Membrane::Analysis;
  for (const auto& [t, r] : rows) {
    w.open("triangle");
    for (int k = 0; k < 3; ++k) w.attr(kQuadNames[k], t[k]);
    if (analysis) {
      w.attr("l1", r.l1);
      w.attr("h", r.h);
      w.attr("x", r.c);
    }
    w.close();
  }
}

std::string write_document(const Model& m, const SolverSettings& s) {
  // Dense file ids in the order of live ids.
  std::vector<unsigned> dense(m.particles.capacity(), kNone);
  unsigned n = 0;
  for (ParticleId p = 0; p < m.particles.capacity(); ++p)
    if (m.particles.valid(p)) dense[p] = n++;

  tinyxml2::XMLPrinter out;
  out.PushHeader(false, true);
  Writer w(out);
  w.open("tendril");
  w.attr("version", unsigned(kVersion));
  w.attr("steps", std::to_string(m.steps).c_str());
  w.attr("time", m.time);

  w.open("solver");
  w.attr("dt", s.dt);
  w.attr("damping", damping_name(s.damping));
  w.attr("viscous", s.viscous);
  w.attr("geometric_factor", s.geometric_factor);
  w.attr("mass_factor", s.mass_factor);
  w.attr("integrator", integrator_name(s.integrator));
  w.attr("mass_mode", mass_mode_name(s.mass_mode));
  w.attr("vie_iterations", unsigned(s.vie_iterations));
  w.attr("vie_dt", s.vie_dt);
  w.attr("mixed_switch", s.mixed_switch);
  w.attr("mixed_implicit", integrator_name(s.mixed_implicit));
  w.close();

  w.open("gravity");
  w.attr("x", m.gravity.x());
  w.attr("y", m.gravity.y());
  w.attr("z", m.gravity.z());
  w.close();

  const Particles& ps = m.particles;
  w.open("particles");
  for (ParticleId p = 0; p < ps.capacity(); ++p) {
    if (!ps.valid(p)) continue;
    w.open("particle");
    w.attr("id", dense[p]);
    w.attr("x", ps.position[p].x());
    w.attr("y", ps.position[p].y());
    w.attr("z", ps.position[p].z());
    w.attr("vx", ps.velocity[p].x());
    w.attr("vy", ps.velocity[p].y());
    w.attr("vz", ps.velocity[p].z());
    w.attr("lock", unsigned(ps.lock[p]));
    w.attr("passive", unsigned(ps.passive[p] ? 1 : 0));
    w.attr("role", unsigned(ps.role[p]));
    w.attr("point_mass", ps.point_mass[p]);
    w.attr("fx", ps.load[p].x());
    w.attr("fy", ps.load[p].y());
    w.attr("fz", ps.load[p].z());
    // Rotation, when there is any: frame, angular velocity, external moment.
    if (ps.orientation[p].coeffs() != Quat::Identity().coeffs()) write_quat(w, kFrameNames, ps.orientation[p]);
    if (!ps.angular_velocity[p].isZero()) {
      w.attr("wx", ps.angular_velocity[p].x());
      w.attr("wy", ps.angular_velocity[p].y());
      w.attr("wz", ps.angular_velocity[p].z());
    }
    if (!ps.moment[p].isZero()) {
      w.attr("mx", ps.moment[p].x());
      w.attr("my", ps.moment[p].y());
      w.attr("mz", ps.moment[p].z());
    }
    w.close();
  }
  w.close();

  w.open("blocks");
  unsigned id = 0;
  for (BlockId b : m.live_blocks()) {
    const Block& blk = m.blocks[b];
    switch (blk.kind) {
      case BlockKind::Cable:
      case BlockKind::Bar: {
        Dart d = blk.dart;
        w.open(blk.kind == BlockKind::Bar ? "bar" : "cable");
        w.attr("id", id);
        w.attr("a", dense[m.dart_particle[d]]);
        w.attr("b", dense[m.dart_particle[m.map.alpha(0, d)]]);
        write_section(w, blk.section);
        w.attr("rest_length", m.rest_length[d]);
        w.close();
        break;
      }
      case BlockKind::Beam: {
        w.open("beam");
        w.attr("id", id);
        w.attr("closed", unsigned(blk.closed ? 1 : 0));
        write_beam_section(w, blk);
        if (blk.rest == RestShape::Current) w.attr("rest", rest_shape_name(blk.rest));
        // Path order from the block's start dart, as particles_of walks it.
        Dart d = blk.dart;
        for (std::size_t guard = 0; guard <= blk.darts; ++guard) {
          w.open("node");
          w.attr("p", dense[m.dart_particle[d]]);
          // A 3-DOF hinge's rest curvature (absent: straight at rest).
          if (blk.dofs == 3 && !m.map.is_free(1, d) && m.rest_curvature[d] != 0)
            w.attr("curvature", m.rest_curvature[d]);
          write_clamp(w, m, d);
          w.close();
          w.open("segment");
          w.attr("rest", m.rest_length[d]);
          if (blk.dofs == 6) {  // the beam ends at node k and k+1, in their node frames
            write_quat(w, kEndANames, m.beam_end[d]);
            write_quat(w, kEndBNames, m.beam_end[m.map.alpha(0, d)]);
          }
          w.close();
          Dart e = m.map.alpha(0, d), next = m.map.alpha(1, e);
          if (next == e) {
            w.open("node");
            w.attr("p", dense[m.dart_particle[e]]);
            write_clamp(w, m, e);
            w.close();
            break;
          }
          if (next == blk.dart) break;
          d = next;
        }
        w.close();
        break;
      }
      case BlockKind::Patch: {
        QuadGrid g;
        if (!find_quad_grid(m, b, g)) {
          const QuadList list = quad_list(m, b, dense);
          w.open("patch");
          w.attr("id", id);
          write_section(w, blk.section);
          write_membrane(w, blk.membrane);
          write_pressure(w, blk);
          for (const auto& q : list.quads) {
            w.open("quad");
            for (int k = 0; k < 4; ++k) w.attr(kQuadNames[k], q[k]);
            w.close();
          }
          for (const auto& [e, edge] : list.edges) {
            w.open("edge");
            w.attr("a", e.first);
            w.attr("b", e.second);
            w.attr("rest", edge.rest);
            if (!std::isnan(edge.prestress)) w.attr("prestress", edge.prestress);
            w.close();
          }
          write_triangles(w, m, b, dense);
          w.close();
          break;
        }
        w.open("patch");
        w.attr("id", id);
        w.attr("rows", unsigned(g.rows));
        w.attr("cols", unsigned(g.cols));
        write_section(w, blk.section);
        write_membrane(w, blk.membrane);
        write_pressure(w, blk);
        for (ParticleId p : g.nodes) {
          w.open("node");
          w.attr("p", dense[p]);
          w.close();
        }
        for (const QuadGrid::Edge& e : g.edges()) {
          w.open("edge");
          w.attr("a", dense[g.nodes[e.a]]);
          w.attr("b", dense[g.nodes[e.b]]);
          w.attr("rest", g.rest[e.index]);
          if (!std::isnan(g.prestress[e.index])) w.attr("prestress", g.prestress[e.index]);
          w.close();
        }
        write_triangles(w, m, b, dense);
        w.close();
        break;
      }
    }
    ++id;
  }
  w.close();
  if (!m.joints.items.empty()) {  // rotational joints (thesis 6.5.2)
    w.open("joints");
    for (const RotationalJoint& j : m.joints.items) {
      w.open("joint");
      w.attr("particle", dense[j.particle]);
      w.attr("angle", j.angle);
      w.attr("stiffness", j.stiffness);
      w.close();
    }
    w.close();
  }
  {  // rigid joints between beams (Model::set_joint), each as its two segments
    std::vector<unsigned> block_id(m.blocks.size(), kNone);
    unsigned next = 0;
    for (BlockId b : m.live_blocks()) block_id[b] = next++;
    bool open = false;
    for (const RigidJoint& j : m.rigid_joints.raw()) {
      if (!m.rigid_joined(j)) continue;
      if (!open) w.open("connections");
      open = true;
      w.open("rigid");
      w.attr("particle", dense[m.dart_particle[j.a]]);
      w.attr("a", block_id[m.dart_block[j.a]]);
      w.attr("a_to", dense[m.dart_particle[m.map.alpha(0, j.a)]]);
      w.attr("b", block_id[m.dart_block[j.b]]);
      w.attr("b_to", dense[m.dart_particle[m.map.alpha(0, j.b)]]);
      w.attr("angle", j.angle);
      w.close();
    }
    if (open) w.close();
  }
  if (!m.goals.empty()) {  // goals of the constraint-based solvers, in index order
    w.open("goals");
    for (const Goal& g : m.goals) {
      w.open("goal");
      w.attr("kind", goal_kind_name(g.kind));
      if (g.kind == Goal::Rigid) {  // its members with their rest offsets
        w.attr("weight", g.weight);
        for (std::size_t k = 0; k < g.members.size(); ++k) {
          w.open("member");
          w.attr("p", dense[g.members[k]]);
          w.attr("x", g.rest[k].x());
          w.attr("y", g.rest[k].y());
          w.attr("z", g.rest[k].z());
          w.close();
        }
        w.close();
        continue;
      }
      w.attr("i", dense[g.i]);
      if (g.kind == Goal::Planar || g.kind == Goal::Bend) {
        w.attr("j", dense[g.j]);
        w.attr("k", dense[g.k]);
        w.attr("l", dense[g.l]);
      } else if (g.kind == Goal::Length) {
        w.attr("j", dense[g.j]);
        w.attr("length", g.length);
      } else {
        w.attr("x", g.point.x());
        w.attr("y", g.point.y());
        w.attr("z", g.point.z());
      }
      if (g.kind == Goal::Bend) {  // the corners' cotangent weights and the triangles' area
        w.attr("ci", g.hinge[0]);
        w.attr("cj", g.hinge[1]);
        w.attr("ck", g.hinge[2]);
        w.attr("cl", g.hinge[3]);
        w.attr("area", g.hinge_area);
      }
      if (g.kind == Goal::Plane || g.kind == Goal::Line) {
        w.attr("dx", g.direction.x());
        w.attr("dy", g.direction.y());
        w.attr("dz", g.direction.z());
      }
      w.attr("weight", g.weight);
      w.close();
    }
    w.close();
  }
  write_results(w, m, dense);
  w.close();
  return std::string(out.CStr(), std::size_t(out.CStrSize() - 1));
}

// --- reading: records --------------------------------------------------------

struct ParticleRecord {
  unsigned id = 0;
  Vec3 x = Vec3::Zero(), v = Vec3::Zero(), load = Vec3::Zero();
  Quat frame = Quat::Identity();
  Vec3 w = Vec3::Zero(), moment = Vec3::Zero();
  unsigned lock = 0;
  bool passive = false;
  unsigned role = 0;
  double point_mass = 0;
  const tinyxml2::XMLElement* element = nullptr;
};

struct EdgeRecord {
  unsigned a, b;  // file ids
  double rest;
  Quat end_a = Quat::Identity(), end_b = Quat::Identity();  // 6-DOF beams
  double prestress = std::numeric_limits<double>::quiet_NaN();  // a patch edge's own prestress
};

struct BlockRecord {
  BlockKind kind = BlockKind::Cable;
  unsigned id = 0;
  Section section;
  bool closed = false;
  unsigned dofs = 3;
  RestShape rest = RestShape::Straight;  // beams
  std::vector<double> curvature;         // beams: per node, its hinge's rest curvature
  Vec3 clamp_first = Vec3::Zero(), clamp_last = Vec3::Zero();  // beams: clamped ends' tangents
  int rows = 0, cols = 0;  // 0: a patch of <quad>s, nodes holding their corners four by four
  std::vector<unsigned> nodes;  // file ids: cable ends, beam path, grid row-major
  std::vector<EdgeRecord> edges;
  const tinyxml2::XMLElement* element = nullptr;
  // CST patches: the formulation, triangles (file ids) and their references.
  Membrane membrane;
  double pressure = 0;  // patches: Model::set_pressure
  Vec3 towards = Vec3::Zero();
  double area_load = 0;  // patches: Model::set_area_load
  Vec3 area_direction = Vec3::Zero();
  std::vector<std::array<unsigned, 3>> triangles;
  std::vector<CstReference> references;
  std::vector<const tinyxml2::XMLElement*> triangle_elements;
};

struct JointRecord {
  unsigned particle = 0;
  double angle = 0, stiffness = 0;
  const tinyxml2::XMLElement* element = nullptr;
};

struct RigidRecord {  // file ids
  unsigned particle = 0, a = 0, a_to = 0, b = 0, b_to = 0;
  double angle = 0;
  const tinyxml2::XMLElement* element = nullptr;
};

struct GoalRecord {
  Goal goal;  // particle ids as in the file
  const tinyxml2::XMLElement* element = nullptr;
};

struct Document {
  std::uint64_t steps = 0;  // how far the model was integrated (absent before: 0)
  double time = 0;
  SolverSettings settings;
  Vec3 gravity = Vec3::Zero();
  std::vector<ParticleRecord> particles;  // ascending id
  std::vector<BlockRecord> blocks;        // ascending id
  std::vector<JointRecord> joints;        // in file order
  std::vector<GoalRecord> goals;          // in file (index) order
  std::vector<RigidRecord> rigid;         // in file order
};

class Attributes;

class Reader {
 public:
  explicit Reader(std::string name) : name_(std::move(name)) {}

  [[noreturn]] void fail(const tinyxml2::XMLElement* e, const std::string& what) const {
    throw ModelFormatError(name_ + ":" + std::to_string(e->GetLineNum()) + ": " + describe(e) + ": " + what);
  }
  [[noreturn]] void fail(const std::string& what) const { throw ModelFormatError(name_ + ": " + what); }

  static std::string tag(const tinyxml2::XMLElement* e) {
    std::string s = "<" + clipped(e->Name());
    for (const char* key : {"id", "p", "a", "b"})
      if (const char* v = e->Attribute(key)) s += std::string(" ") + key + "=" + quoted(v);
    return s + ">";
  }
  // The element, behind its block when it is a node, segment or edge.
  static std::string describe(const tinyxml2::XMLElement* e) {
    const tinyxml2::XMLNode* parent = e->Parent();
    const tinyxml2::XMLElement* pe = parent ? parent->ToElement() : nullptr;
    if (pe && (std::strcmp(pe->Name(), "beam") == 0 || std::strcmp(pe->Name(), "patch") == 0))
      return tag(pe) + ": " + tag(e);
    return tag(e);
  }

  Document read(const tinyxml2::XMLDocument& doc) const;

 private:
  std::string name_;
  void read_solver(const tinyxml2::XMLElement* e, SolverSettings& s) const;
  ParticleRecord read_particle(const tinyxml2::XMLElement* e) const;
  BlockRecord read_cable(const tinyxml2::XMLElement* e, BlockKind kind) const;  // a cable or a bar
  BlockRecord read_beam(const tinyxml2::XMLElement* e) const;
  BlockRecord read_patch(const tinyxml2::XMLElement* e) const;
  BlockRecord read_quad_patch(const tinyxml2::XMLElement* e, Attributes& a, BlockRecord& b) const;
  void check_references(const Document& d) const;
  void read_triangle(const tinyxml2::XMLElement* c, Attributes& ca, BlockRecord& b) const;
  // The children both patch forms share: <edge a b rest> and <triangle>.
  void read_edge_or_triangle(const tinyxml2::XMLElement* c, Attributes& ca, BlockRecord& b,
                             std::vector<const tinyxml2::XMLElement*>& edge_elements) const;
  void check_triangles(const tinyxml2::XMLElement* e, const BlockRecord& b) const;
  void match_edges(const tinyxml2::XMLElement* e, const BlockRecord& b,
                   const std::vector<const tinyxml2::XMLElement*>& edge_elements,
                   std::map<std::pair<unsigned, unsigned>, int>& expected, const char* where) const;
  void no_children(const tinyxml2::XMLElement* e) const {
    if (const tinyxml2::XMLElement* c = e->FirstChildElement())
      fail(c, "unknown element <" + clipped(c->Name()) + "> inside <" + e->Name() + ">");
  }
  friend class Attributes;
};

// Reads the attributes of one element; done() rejects any it did not ask for.
class Attributes {
 public:
  Attributes(const Reader& r, const tinyxml2::XMLElement* e) : r_(r), e_(e) {}

  const char* raw(const char* name) {
    used_.insert(name);
    return e_->Attribute(name);
  }
  const char* text(const char* name) {
    const char* v = raw(name);
    if (!v) missing(name);
    return v;
  }
  double real(const char* name) { return parse_real(name, text(name)); }
  double real(const char* name, double fallback) {
    const char* v = raw(name);
    return v ? parse_real(name, v) : fallback;
  }
  unsigned index(const char* name) { return parse_index(name, text(name)); }
  unsigned index(const char* name, unsigned fallback) {
    const char* v = raw(name);
    return v ? parse_index(name, v) : fallback;
  }
  bool flag(const char* name, bool fallback) {
    const char* v = raw(name);
    if (!v) return fallback;
    std::string s = v;
    if (s == "1" || s == "true") return true;
    if (s == "0" || s == "false") return false;
    r_.fail(e_, std::string("attribute '") + name + "' is not 0 or 1: " + quoted(v));
  }
  [[noreturn]] void bad(const char* name, const std::string& what) {
    r_.fail(e_, std::string("attribute '") + name + "' " + what);
  }
  void done() {
    for (const tinyxml2::XMLAttribute* a = e_->FirstAttribute(); a; a = a->Next())
      if (!used_.count(a->Name())) r_.fail(e_, "unknown attribute '" + clipped(a->Name()) + "'");
  }
  // Section attributes shared by all blocks; EI is required for beams only,
  // which may also give GJ, EIy and EIz (0 or absent: as EI).
  Section section(bool beam) {
    Section s;
    s.EA = real("EA");
    s.EI = beam ? real("EI") : real("EI", 0.0);
    s.prestress = real("prestress", 0.0);
    s.line_mass = real("line_mass", 0.0);
    if (!(s.EA > 0)) bad("EA", "must be > 0");
    if (beam ? !(s.EI > 0) : !(s.EI >= 0)) bad("EI", beam ? "must be > 0" : "must be >= 0");
    if (!(s.line_mass >= 0 && s.line_mass <= kMaxLineMass)) bad("line_mass", kLineMassRange);
    if (beam) {
      s.GJ = real("GJ", 0.0);
      s.EIy = real("EIy", 0.0);
      s.EIz = real("EIz", 0.0);
      for (auto [name, v] : {std::pair{"GJ", s.GJ}, std::pair{"EIy", s.EIy}, std::pair{"EIz", s.EIz}})
        if (!(v >= 0)) bad(name, "must be >= 0");
    }
    return s;
  }
  // A patch's formulation: absent, bars; "form" or "analysis", CST.
  Membrane membrane() {
    Membrane m;
    const char* v = raw("membrane");
    if (!v) return m;
    const std::string mode = v;
    if (mode == "form") m.mode = Membrane::FormFinding;
    else if (mode == "analysis") m.mode = Membrane::Analysis;
    else bad("membrane", "must be \"form\" or \"analysis\" (absent: bars), not " + quoted(v));
    m.sigma_warp = real("sigma_warp");
    m.sigma_weft = real("sigma_weft");
    if (m.mode == Membrane::Analysis) {
      m.dxx = real("dxx");
      m.dxy = real("dxy");
      m.dyx = real("dyx");
      m.dyy = real("dyy");
      m.G = real("G");
    }
    return m;
  }
  // A unit quaternion from four attributes (all absent: the identity). Taken
  // as written, so the file round-trips bit for bit.
  Quat rotation(const char* const names[4]) {
    Quat q(real(names[0], 1.0), real(names[1], 0.0), real(names[2], 0.0), real(names[3], 0.0));
    if (std::abs(q.norm() - 1) > 1e-9)
      bad(names[0], "and its companions must form a unit quaternion (w x y z), norm " + std::to_string(q.norm()));
    return q;
  }

 private:
  [[noreturn]] void missing(const char* name) { bad(name, "is missing"); }
  double parse_real(const char* name, const char* v) {
    const char* end = v + std::strlen(v);
    while (v < end && *v == ' ') ++v;
    while (end > v && end[-1] == ' ') --end;
    if (v < end && *v == '+') ++v;
    double x = 0;
    auto r = std::from_chars(v, end, x);
    if (r.ec == std::errc::result_out_of_range && r.ptr == end) {
      // Too large (infinite) or too small (below 4.9e-324, not 0): from_chars
      // tells not which, strtod does.
      const bool tiny = std::strtod(std::string(v, end).c_str(), nullptr) == 0;
      bad(name, std::string(tiny ? "is too small for a double (nonzero, below 4.9e-324): "
                                 : "is too large for a double (above 1.8e308): ") +
                    quoted(e_->Attribute(name)));
    }
    if (r.ec == std::errc() && r.ptr == end && v != end && !std::isfinite(x))
      bad(name, "is not a finite number: " + quoted(e_->Attribute(name)));
    if (r.ec != std::errc() || r.ptr != end || v == end) bad(name, "is not a number: " + quoted(e_->Attribute(name)));
    return x;
  }
  unsigned parse_index(const char* name, const char* v) {
    const char* end = v + std::strlen(v);
    std::uint32_t x = 0;
    auto r = std::from_chars(v, end, x);
    if (r.ec != std::errc() || r.ptr != end || v == end || x == kNone)
      bad(name, "is not a non-negative integer: " + quoted(v));
    return x;
  }
  const Reader& r_;
  const tinyxml2::XMLElement* e_;
  std::set<std::string> used_;
};

void Reader::read_solver(const tinyxml2::XMLElement* e, SolverSettings& s) const {
  Attributes a(*this, e);
  s.dt = a.real("dt", s.dt);
  if (const char* d = a.raw("damping")) {
    bool found = false;
    for (Damping k : {Damping::None, Damping::Viscous, Damping::Kinetic})
      if (std::strcmp(d, damping_name(k)) == 0) s.damping = k, found = true;
    if (!found) a.bad("damping", "is " + quoted(d) + "; expected none, viscous or kinetic");
  }
  s.viscous = a.real("viscous", s.viscous);
  s.geometric_factor = a.real("geometric_factor", s.geometric_factor);
  s.mass_factor = a.real("mass_factor", s.mass_factor);
  if (const char* name = a.raw("integrator")) {
    auto i = parse_integrator(name);
    if (!i)
      a.bad("integrator", "is " + quoted(name) +
                              "; expected leapfrog, symplectic_euler, velocity_verlet, midpoint, rk4, vie, projective, "
                              "mixed or newton");
    s.integrator = *i;
  }
  if (const char* name = a.raw("mass_mode")) {
    auto mm = parse_mass_mode(name);
    if (!mm) a.bad("mass_mode", "is " + quoted(name) + "; expected fictitious or physical");
    s.mass_mode = *mm;
  }
  if (const char* name = a.raw("mixed_implicit")) {
    auto i = parse_integrator(name);
    if (!i || (*i != Integrator::VariationalImplicitEuler && *i != Integrator::ProjectiveDynamics))
      a.bad("mixed_implicit", "is " + quoted(name) + "; expected vie or projective");
    else s.mixed_implicit = *i;
  }
  // Out of range: -1, which check_settings refuses with the message every entry point gives.
  s.vie_iterations = int(whole_number_in(a.real("vie_iterations", s.vie_iterations), 0, kMaxVieIterations).value_or(-1));
  s.vie_dt = a.real("vie_dt", s.vie_dt);
  s.mixed_switch = a.real("mixed_switch", s.mixed_switch);
  if (auto error = check_settings(s)) a.bad(error->key.c_str(), error->message);
  a.done();
  no_children(e);
}

ParticleRecord Reader::read_particle(const tinyxml2::XMLElement* e) const {
  Attributes a(*this, e);
  ParticleRecord p;
  p.element = e;
  p.id = a.index("id");
  p.x = Vec3(a.real("x"), a.real("y"), a.real("z"));
  p.v = Vec3(a.real("vx", 0.0), a.real("vy", 0.0), a.real("vz", 0.0));
  p.load = Vec3(a.real("fx", 0.0), a.real("fy", 0.0), a.real("fz", 0.0));
  p.lock = a.index("lock", 0);
  if (p.lock > (kLockTranslation | kLockRotation)) a.bad("lock", "has bits beyond 63 (x y z rx ry rz)");
  p.passive = a.flag("passive", false);
  p.role = a.index("role", 0);
  if (p.role > unsigned(Role::Volatile)) a.bad("role", "must be 0 (none), 1 (parent), 2 (child) or 3 (volatile)");
  p.point_mass = a.real("point_mass", 0.0);
  if (!(p.point_mass >= 0)) a.bad("point_mass", "must be >= 0");
  p.frame = a.rotation(kFrameNames);
  p.w = Vec3(a.real("wx", 0.0), a.real("wy", 0.0), a.real("wz", 0.0));
  p.moment = Vec3(a.real("mx", 0.0), a.real("my", 0.0), a.real("mz", 0.0));
  a.done();
  no_children(e);
  return p;
}

BlockRecord Reader::read_cable(const tinyxml2::XMLElement* e, BlockKind kind) const {
  Attributes a(*this, e);
  BlockRecord b;
  b.kind = kind;
  b.element = e;
  b.id = a.index("id");
  unsigned pa = a.index("a"), pb = a.index("b");
  if (pa == pb) a.bad("b", "is " + std::to_string(pb) + ", the same particle as 'a'");
  b.section = a.section(false);
  double rest = a.real("rest_length");
  if (!rest_in_range(rest)) a.bad("rest_length", kRestRange);
  b.nodes = {pa, pb};
  b.edges.push_back({pa, pb, rest});
  a.done();
  no_children(e);
  return b;
}

BlockRecord Reader::read_beam(const tinyxml2::XMLElement* e) const {
  Attributes a(*this, e);
  BlockRecord b;
  b.kind = BlockKind::Beam;
  b.element = e;
  b.id = a.index("id");
  b.closed = a.flag("closed", false);
  b.dofs = a.index("dofs", 3);
  if (b.dofs != 3 && b.dofs != 6) a.bad("dofs", "must be 3 or 6 (DOF per particle)");
  b.section = a.section(true);
  if (const char* rest = a.raw("rest"); rest && !parse_rest_shape(rest, b.rest))
    a.bad("rest", "must be \"straight\" or \"current\", not " + quoted(rest));
  a.done();
  std::vector<double> rests;
  std::vector<std::pair<Quat, Quat>> ends;
  std::vector<const tinyxml2::XMLElement*> node_elements;
  const tinyxml2::XMLElement* clamp_node = nullptr;  // the last clamped node after the first
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    Attributes ca(*this, c);
    if (std::strcmp(c->Name(), "node") == 0) {
      b.nodes.push_back(ca.index("p"));
      b.curvature.push_back(ca.real("curvature", 0.0));
      if (!(b.curvature.back() >= 0)) ca.bad("curvature", "must be >= 0 [1/m]");
      if (b.curvature.back() != 0 && b.dofs != 3) ca.bad("curvature", "belongs to 3-DOF beams (6 DOF: the segments' beam ends)");
      const Vec3 t(ca.real("tx", 0.0), ca.real("ty", 0.0), ca.real("tz", 0.0));
      if (!t.isZero(0)) {
        if (std::abs(t.norm() - 1) > 1e-9) ca.bad("tx", "ty, tz: a clamp's tangent must be a unit vector");
        if (b.closed) ca.bad("tx", "a ring has no ends to clamp");
        (b.nodes.size() == 1 ? b.clamp_first : b.clamp_last) = t;
        if (b.nodes.size() > 1) clamp_node = c;
      }
      node_elements.push_back(c);
    } else if (std::strcmp(c->Name(), "segment") == 0) {
      double rest = ca.real("rest");
      if (!rest_in_range(rest)) ca.bad("rest", kRestRange);
      rests.push_back(rest);
      if (b.dofs == 6) ends.emplace_back(ca.rotation(kEndANames), ca.rotation(kEndBNames));
    } else {
      fail(c, "unknown element <" + clipped(c->Name()) + "> inside <beam>");
    }
    ca.done();
    no_children(c);
  }
  const std::size_t n = b.nodes.size(), need = b.closed ? 3 : 2;
  if (n < need)
    fail(e, "a" + std::string(b.closed ? " closed" : "n open") + " beam needs at least " + std::to_string(need) +
                " <node p> children, got " + std::to_string(n));
  if (clamp_node && clamp_node != node_elements.back()) fail(clamp_node, "only the first and last <node> of a beam (its ends) are clamped");
  const std::size_t segments = b.closed ? n : n - 1;
  if (rests.size() != segments)
    fail(e, std::to_string(n) + " <node> children need " + std::to_string(segments) + " <segment rest> children, got " +
                std::to_string(rests.size()));
  // A particle may come back on the same beam (a loop): add_beam says where not.
  for (std::size_t k = 0; k < segments; ++k) {
    b.edges.push_back({b.nodes[k], b.nodes[(k + 1) % n], rests[k]});
    if (b.dofs == 6) {
      b.edges.back().end_a = ends[k].first;
      b.edges.back().end_b = ends[k].second;
    }
  }
  return b;
}

BlockRecord Reader::read_patch(const tinyxml2::XMLElement* e) const {
  Attributes a(*this, e);
  BlockRecord b;
  b.kind = BlockKind::Patch;
  b.element = e;
  b.id = a.index("id");
  b.membrane = a.membrane();
  b.pressure = a.real("pressure", 0.0);
  b.towards = Vec3(a.real("towards_x", 0.0), a.real("towards_y", 0.0), a.real("towards_z", 0.0));
  b.area_load = a.real("area_load", 0.0);
  b.area_direction = Vec3(a.real("area_x", 0.0), a.real("area_y", 0.0), a.real("area_z", 0.0));
  if (b.area_load != 0 && !(b.area_direction.norm() > 0)) a.bad("area_load", "needs a non-zero area_x, area_y, area_z");
  if (!e->Attribute("rows") && !e->Attribute("cols")) return read_quad_patch(e, a, b);
  unsigned rows = a.index("rows"), cols = a.index("cols");
  if (rows < 2 || rows > 1u << 15) a.bad("rows", "must be an integer from 2 to 32768");
  if (cols < 2 || cols > 1u << 15) a.bad("cols", "must be an integer from 2 to 32768");
  b.rows = int(rows);
  b.cols = int(cols);
  b.section = a.section(false);
  a.done();
  std::vector<const tinyxml2::XMLElement*> node_elements, edge_elements;
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    Attributes ca(*this, c);
    if (std::strcmp(c->Name(), "node") == 0) {
      b.nodes.push_back(ca.index("p"));
      node_elements.push_back(c);
    } else {
      read_edge_or_triangle(c, ca, b, edge_elements);
    }
    ca.done();
    no_children(c);
  }
  const std::size_t n = std::size_t(rows) * cols;
  if (b.nodes.size() != n)
    fail(e, "attributes 'rows' and 'cols' need " + std::to_string(n) + " <node p> children, got " +
                std::to_string(b.nodes.size()));
  std::set<unsigned> seen;
  for (std::size_t k = 0; k < n; ++k)
    if (!seen.insert(b.nodes[k]).second)
      fail(node_elements[k], "attribute 'p': particle " + std::to_string(b.nodes[k]) + " appears twice in the patch");
  // Every grid edge exactly once, either way round.
  std::map<std::pair<unsigned, unsigned>, int> expected;  // -> index of its <edge>, -1 until seen
  for (const QuadGrid::Edge& g : QuadGrid::edges(b.rows, b.cols)) expected[edge_key(b.nodes[g.a], b.nodes[g.b])] = -1;
  match_edges(e, b, edge_elements, expected, "the grid");
  check_triangles(e, b);
  return b;
}

// <patch id EA ...> <quad a b c d/> ... <edge a b rest/> ... </patch>: every
// quad edge exactly once.
BlockRecord Reader::read_quad_patch(const tinyxml2::XMLElement* e, Attributes& a, BlockRecord& b) const {
  b.section = a.section(false);
  a.done();
  std::vector<const tinyxml2::XMLElement*> edge_elements;
  std::map<std::pair<unsigned, unsigned>, int> expected;  // -> index of its <edge>, -1 until seen
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    Attributes ca(*this, c);
    if (std::strcmp(c->Name(), "quad") == 0) {
      std::array<unsigned, 4> q{};
      for (int k = 0; k < 4; ++k) q[k] = ca.index(kQuadNames[k]);
      for (int k = 0; k < 4; ++k) {
        for (int j = k + 1; j < 4; ++j)
          if (q[k] == q[j]) ca.bad(kQuadNames[j], "repeats particle " + std::to_string(q[j]) + " in the quad");
        expected.emplace(edge_key(q[k], q[(k + 1) % 4]), -1);
        b.nodes.push_back(q[k]);
      }
    } else {
      read_edge_or_triangle(c, ca, b, edge_elements);
    }
    ca.done();
    no_children(c);
  }
  if (b.nodes.empty()) fail(e, "a patch needs attributes 'rows' and 'cols' with <node>s, or <quad a b c d> children");
  match_edges(e, b, edge_elements, expected, "a quad");
  check_triangles(e, b);
  return b;
}

// <triangle a b c [l1 h x]/>: a CST triangle, side a-b along the warp; in
// analysis its reference shape (side a-b of length l1, c at (x, h)).
void Reader::read_edge_or_triangle(const tinyxml2::XMLElement* c, Attributes& ca, BlockRecord& b,
                                   std::vector<const tinyxml2::XMLElement*>& edge_elements) const {
  if (std::strcmp(c->Name(), "edge") == 0) {
    EdgeRecord r{ca.index("a"), ca.index("b"), ca.real("rest")};
    if (!rest_in_range(r.rest)) ca.bad("rest", kRestRange);
    if (ca.raw("prestress")) {  // the edge's own (set_patch_prestress)
      r.prestress = ca.real("prestress");
      if (!(r.prestress >= 0)) ca.bad("prestress", "must be >= 0 [N]");
    }
    b.edges.push_back(r);
    edge_elements.push_back(c);
  } else if (std::strcmp(c->Name(), "triangle") == 0) {
    read_triangle(c, ca, b);
  } else {
    fail(c, "unknown element <" + clipped(c->Name()) + "> inside <patch>");
  }
}

void Reader::read_triangle(const tinyxml2::XMLElement* c, Attributes& ca, BlockRecord& b) const {
  if (!b.membrane.cst()) fail(c, "a <triangle> needs the patch's attribute membrane=\"form\" or \"analysis\"");
  std::array<unsigned, 3> t{};
  for (int k = 0; k < 3; ++k) t[k] = ca.index(kQuadNames[k]);
  CstReference r;
  if (b.membrane.mode == Membrane::Analysis) {
    r.l1 = ca.real("l1");
    r.h = ca.real("h");
    r.c = ca.real("x");
    if (!(r.l1 > 0)) ca.bad("l1", "must be > 0");
    if (!(r.h > 0)) ca.bad("h", "must be > 0");
  }
  b.triangles.push_back(t);
  b.references.push_back(r);
  b.triangle_elements.push_back(c);
}

void Reader::check_triangles(const tinyxml2::XMLElement* e, const BlockRecord& b) const {
  if (b.membrane.cst() && b.triangles.empty())
    fail(e, "attribute 'membrane': a CST patch needs its <triangle a b c> children");
}

// Every expected edge (keyed by its sorted particle pair, value -1) must be
// given exactly once among the patch's <edge> elements.
void Reader::match_edges(const tinyxml2::XMLElement* e, const BlockRecord& b,
                         const std::vector<const tinyxml2::XMLElement*>& edge_elements,
                         std::map<std::pair<unsigned, unsigned>, int>& expected, const char* where) const {
  for (std::size_t k = 0; k < b.edges.size(); ++k) {
    auto it = expected.find(edge_key(b.edges[k].a, b.edges[k].b));
    if (it == expected.end())
      fail(edge_elements[k], "attributes 'a' and 'b': particles " + std::to_string(b.edges[k].a) + " and " +
                                 std::to_string(b.edges[k].b) + " are not neighbours in " + where);
    if (it->second >= 0)
      fail(edge_elements[k], "attributes 'a' and 'b': this edge is already given on line " +
                                 std::to_string(edge_elements[it->second]->GetLineNum()));
    it->second = int(k);
  }
  for (const auto& [pair, k] : expected)
    if (k < 0)
      fail(e, "no <edge a b rest> between particles " + std::to_string(pair.first) + " and " +
                  std::to_string(pair.second));
}

void Reader::check_references(const Document& d) const {
  std::map<unsigned, const ParticleRecord*> by_id;
  for (const ParticleRecord& p : d.particles) by_id[p.id] = &p;
  for (const BlockRecord& b : d.blocks) {
    const tinyxml2::XMLElement* e = b.element;
    // Walk node children (beams, patches) or the a/b attributes (cables).
    std::vector<std::pair<const tinyxml2::XMLElement*, const char*>> refs;
    if (b.kind == BlockKind::Cable || b.kind == BlockKind::Bar) {
      refs = {{e, "a"}, {e, "b"}};
    } else {
      for (const tinyxml2::XMLElement* c = e->FirstChildElement("node"); c; c = c->NextSiblingElement("node"))
        refs.push_back({c, "p"});
      for (const tinyxml2::XMLElement* c = e->FirstChildElement("quad"); c; c = c->NextSiblingElement("quad"))
        for (const char* corner : kQuadNames) refs.push_back({c, corner});
    }
    for (std::size_t k = 0; k < refs.size(); ++k)
      if (!by_id.count(b.nodes[k]))
        fail(refs[k].first, std::string("attribute '") + refs[k].second + "': no particle with id " +
                                std::to_string(b.nodes[k]));
    for (std::size_t t = 0; t < b.triangles.size(); ++t)
      for (int k = 0; k < 3; ++k)
        if (!by_id.count(b.triangles[t][k]))
          fail(b.triangle_elements[t], std::string("attribute '") + kQuadNames[k] + "': no particle with id " +
                                           std::to_string(b.triangles[t][k]));
    if (b.kind == BlockKind::Beam) {  // add_beam refuses consecutive particles that coincide
      const std::size_t n = b.nodes.size(), segments = b.closed ? n : n - 1;
      for (std::size_t k = 0; k < segments; ++k) {
        unsigned p = b.nodes[k], q = b.nodes[(k + 1) % n];
        if (by_id[p]->x == by_id[q]->x)
          fail(refs[(k + 1) % n].first, "attribute 'p': particle " + std::to_string(q) + " sits on particle " +
                                            std::to_string(p) + ", its neighbour on the beam");
      }
    }
  }
}

Document Reader::read(const tinyxml2::XMLDocument& doc) const {
  const tinyxml2::XMLElement* root = doc.RootElement();
  if (!root) fail("no root element; expected <tendril version=\"1\">");
  if (std::strcmp(root->Name(), "tendril") != 0)
    fail(root, "the root element must be <tendril version=\"1\">");
  Document d;
  {
    Attributes a(*this, root);
    unsigned version = a.index("version");
    if (version != kVersion)
      a.bad("version", "is " + std::to_string(version) + "; this build reads version " + std::to_string(kVersion));
    if (const char* steps = a.raw("steps")) {
      const std::string_view v(steps);
      const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), d.steps);
      if (ec != std::errc() || end != v.data() + v.size()) a.bad("steps", "is not a whole number >= 0: " + quoted(steps));
    }
    d.time = a.real("time", 0);
    if (!(d.time >= 0)) a.bad("time", "must be >= 0");
    a.done();
  }
  std::map<std::string, const tinyxml2::XMLElement*> sections;
  std::map<unsigned, const tinyxml2::XMLElement*> particle_ids, block_ids;
  for (const tinyxml2::XMLElement* e = root->FirstChildElement(); e; e = e->NextSiblingElement()) {
    const std::string name = e->Name();
    if (name != "solver" && name != "gravity" && name != "particles" && name != "blocks" && name != "joints" &&
        name != "goals" && name != "connections" && name != "results")
      fail(e, "unknown element <" + clipped(name.c_str()) + "> inside <tendril>");
    if (auto it = sections.find(name); it != sections.end())
      fail(e, "<" + name + "> is already given on line " + std::to_string(it->second->GetLineNum()));
    sections[name] = e;
    if (name == "solver") {
      read_solver(e, d.settings);
    } else if (name == "gravity") {
      Attributes a(*this, e);
      d.gravity = Vec3(a.real("x"), a.real("y"), a.real("z"));
      a.done();
      no_children(e);
    } else if (name == "goals") {
      Attributes(*this, e).done();
      for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (std::strcmp(c->Name(), "goal") != 0)
          fail(c, "unknown element <" + clipped(c->Name()) + "> inside <goals>");
        Attributes a(*this, c);
        GoalRecord r;
        r.element = c;
        Goal& g = r.goal;
        const char* kind = a.raw("kind");
        if (!kind || !parse_goal_kind(kind, g.kind)) a.bad("kind", "must be anchor, plane, line, length, planar, rigid or bend");
        if (g.kind == Goal::Rigid) {  // <member p x y z/>: a particle and its rest offset
          g.weight = a.real("weight");
          a.done();
          for (const tinyxml2::XMLElement* e2 = c->FirstChildElement(); e2; e2 = e2->NextSiblingElement()) {
            if (std::strcmp(e2->Name(), "member") != 0)
              fail(e2, "unknown element <" + clipped(e2->Name()) + "> inside a rigid <goal>");
            Attributes ma(*this, e2);
            g.members.push_back(ma.index("p"));
            g.rest.push_back(Vec3(ma.real("x"), ma.real("y"), ma.real("z")));
            ma.done();
            no_children(e2);
          }
          d.goals.push_back(r);
          continue;
        }
        g.i = a.index("i");
        if (g.kind == Goal::Planar || g.kind == Goal::Bend) {
          g.j = a.index("j");
          g.k = a.index("k");
          g.l = a.index("l");
        } else if (g.kind == Goal::Length) {
          g.j = a.index("j");
          g.length = a.real("length");
        } else {
          g.point = Vec3(a.real("x"), a.real("y"), a.real("z"));
        }
        if (g.kind == Goal::Bend) {
          g.hinge = {a.real("ci"), a.real("cj"), a.real("ck"), a.real("cl")};
          g.hinge_area = a.real("area");
        }
        if (g.kind == Goal::Plane || g.kind == Goal::Line) g.direction = Vec3(a.real("dx"), a.real("dy"), a.real("dz"));
        g.weight = a.real("weight");
        a.done();
        no_children(c);
        d.goals.push_back(r);
      }
    } else if (name == "connections") {
      Attributes(*this, e).done();
      for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (std::strcmp(c->Name(), "rigid") != 0)
          fail(c, "unknown element <" + clipped(c->Name()) + "> inside <connections>");
        Attributes a(*this, c);
        RigidRecord r;
        r.element = c;
        r.particle = a.index("particle");
        r.a = a.index("a");
        r.a_to = a.index("a_to");
        r.b = a.index("b");
        r.b_to = a.index("b_to");
        r.angle = a.real("angle");
        if (!(r.angle >= 0 && r.angle <= std::numbers::pi)) a.bad("angle", "must be within 0 .. pi");
        a.done();
        no_children(c);
        d.rigid.push_back(r);
      }
    } else if (name == "joints") {
      Attributes(*this, e).done();
      for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (std::strcmp(c->Name(), "joint") != 0)
          fail(c, "unknown element <" + clipped(c->Name()) + "> inside <joints>");
        Attributes a(*this, c);
        JointRecord j;
        j.element = c;
        j.particle = a.index("particle");
        j.angle = a.real("angle");
        j.stiffness = a.real("stiffness");
        if (!(j.stiffness > 0)) a.bad("stiffness", "must be > 0");
        a.done();
        no_children(c);
        d.joints.push_back(j);
      }
    } else if (name == "results") {
      // Derived from the state (write_results): a loaded model computes
      // them again. Only their element names are checked.
      Attributes(*this, e).done();
      for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement())
        if (std::strcmp(c->Name(), "line") != 0 && std::strcmp(c->Name(), "vertex") != 0 &&
            std::strcmp(c->Name(), "triangle") != 0)
          fail(c, "unknown element <" + clipped(c->Name()) + "> inside <results>");
    } else if (name == "particles") {
      Attributes(*this, e).done();
      for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        if (std::strcmp(c->Name(), "particle") != 0)
          fail(c, "unknown element <" + clipped(c->Name()) + "> inside <particles>");
        ParticleRecord p = read_particle(c);
        if (auto [it, fresh] = particle_ids.emplace(p.id, c); !fresh)
          fail(c, "attribute 'id': particle " + std::to_string(p.id) + " is already defined on line " +
                      std::to_string(it->second->GetLineNum()));
        d.particles.push_back(p);
      }
    } else {
      Attributes(*this, e).done();
      for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
        const std::string kind = c->Name();
        BlockRecord b;
        if (kind == "cable") b = read_cable(c, BlockKind::Cable);
        else if (kind == "bar") b = read_cable(c, BlockKind::Bar);
        else if (kind == "beam") b = read_beam(c);
        else if (kind == "patch") b = read_patch(c);
        else fail(c, "unknown element <" + clipped(kind.c_str()) + "> inside <blocks>");
        if (auto [it, fresh] = block_ids.emplace(b.id, c); !fresh)
          fail(c, "attribute 'id': block " + std::to_string(b.id) + " is already defined on line " +
                      std::to_string(it->second->GetLineNum()));
        d.blocks.push_back(std::move(b));
      }
    }
  }
  std::stable_sort(d.particles.begin(), d.particles.end(), [](auto& x, auto& y) { return x.id < y.id; });
  std::stable_sort(d.blocks.begin(), d.blocks.end(), [](auto& x, auto& y) { return x.id < y.id; });
  check_references(d);
  return d;
}

// --- reading: building -----------------------------------------------------------

void build(const Reader& reader, const Document& d, Model& m) {
  std::map<unsigned, ParticleId> id_of;
  for (const ParticleRecord& r : d.particles) {
    try {
      ParticleId p = m.add_particle(r.x);
      m.particles.velocity[p] = r.v;
      m.set_load(p, r.load);
      m.set_lock(p, std::uint8_t(r.lock));
      m.set_passive(p, r.passive);
      m.set_role(p, Role(r.role));
      m.set_point_mass(p, r.point_mass);
      m.particles.orientation[p] = r.frame;
      m.particles.angular_velocity[p] = r.w;
      id_of[r.id] = p;
    } catch (const ModelError& e) {
      reader.fail(r.element, e.what());
    }
  }
  std::map<unsigned, BlockId> block_of;  // file id -> block
  for (const BlockRecord& r : d.blocks) {
    try {
      std::vector<ParticleId> ps;
      for (unsigned n : r.nodes) ps.push_back(id_of.at(n));
      BlockId b = 0;
      switch (r.kind) {
        case BlockKind::Cable: b = m.add_cable(ps[0], ps[1], r.section, r.edges[0].rest); break;
        case BlockKind::Bar: b = m.add_elastic_bar(ps[0], ps[1], r.section, r.edges[0].rest); break;
        case BlockKind::Beam: b = m.add_beam(ps, r.section, r.closed); break;
        case BlockKind::Patch:
          if (r.rows == 0) {
            std::vector<Model::Quad> quads;
            for (std::size_t k = 0; k < ps.size(); k += 4) quads.push_back({ps[k], ps[k + 1], ps[k + 2], ps[k + 3]});
            b = m.add_patch(quads, r.section);
          } else {
            b = m.add_quad_grid(ps, r.rows, r.cols, r.section);
          }
          break;
      }
      // Blocks take rest lengths from the current distances; the stored
      // ones win. Bars and lumped masses follow in rebuild_elements below.
      if (r.kind == BlockKind::Beam) {
        // Segment by segment along the path (a loop may pass the same pair
        // of particles twice), with the stored ends of a 6-DOF beam; the
        // Beam6 elements follow in rebuild_elements below.
        if (r.dofs == 6) m.blocks[b].dofs = 6;
        m.blocks[b].rest = r.rest;
        Dart d = m.blocks[b].dart;
        for (std::size_t k = 0; k < r.curvature.size() && k < r.edges.size(); ++k, d = m.map.alpha(1, m.map.alpha(0, d)))
          if (!m.map.is_free(1, d)) m.rest_curvature[d] = m.rest_curvature[m.map.alpha(1, d)] = r.curvature[k];
        d = m.blocks[b].dart;
        for (const EdgeRecord& e : r.edges) {
          m.rest_length[d] = m.rest_length[m.map.alpha(0, d)] = e.rest;
          if (r.dofs == 6) {
            m.beam_end[d] = e.end_a;
            m.beam_end[m.map.alpha(0, d)] = e.end_b;
          }
          d = m.map.alpha(1, m.map.alpha(0, d));
        }
        // Clamped ends: d is the last end dart now (an open beam).
        for (auto [end, t] : {std::pair{m.blocks[b].dart, r.clamp_first}, std::pair{d, r.clamp_last}})
          if (!t.isZero(0)) {
            m.clamp[end] = t;
            m.clamp_darts.push_back(end);
          }
      } else {
        std::map<std::pair<ParticleId, ParticleId>, const EdgeRecord*> edge;
        for (const EdgeRecord& e : r.edges) {
          ParticleId a = id_of.at(e.a), c = id_of.at(e.b);
          edge[{std::min(a, c), std::max(a, c)}] = &e;
        }
        for (Dart x : m.map.orbit(kComponentOrbit, m.blocks[b].dart)) {
          ParticleId a = m.dart_particle[x], c = m.dart_particle[m.map.alpha(0, x)];
          const EdgeRecord& e = *edge.at({std::min(a, c), std::max(a, c)});
          m.rest_length[x] = e.rest;
          m.edge_prestress[x] = e.prestress;
        }
      }
      block_of[r.id] = b;
      if (r.membrane.cst()) {  // the stored triangles and reference shapes
        std::vector<Model::Triangle> tris;
        for (const auto& t : r.triangles) tris.push_back({id_of.at(t[0]), id_of.at(t[1]), id_of.at(t[2])});
        m.set_patch_formulation(b, r.membrane, tris,
                                r.membrane.mode == Membrane::Analysis ? &r.references : nullptr);
      }
      if (r.pressure != 0) m.set_pressure(b, r.pressure, r.towards);
      if (r.area_load != 0) m.set_area_load(b, r.area_load, r.area_direction);
    } catch (const ModelError& e) {
      reader.fail(r.element, e.what());
    }
  }
  m.rebuild_elements();
  for (const ParticleRecord& r : d.particles) {  // once the beams it acts on exist
    try {
      m.set_moment(id_of.at(r.id), r.moment);
    } catch (const ModelError& e) {
      reader.fail(r.element, e.what());
    }
  }
  m.gravity = d.gravity;
  m.steps = d.steps;
  m.time = d.time;
  for (const JointRecord& j : d.joints) {
    auto it = id_of.find(j.particle);
    if (it == id_of.end()) reader.fail(j.element, "attribute 'particle': no particle " + std::to_string(j.particle));
    try {
      m.add_joint(it->second, j.angle, j.stiffness);
    } catch (const ModelError& e) {
      reader.fail(j.element, e.what());
    }
  }
  for (const RigidRecord& r : d.rigid) {
    auto id = [&](const char* what, unsigned file_id, bool block) {
      if (block) {
        auto it = block_of.find(file_id);
        if (it == block_of.end()) reader.fail(r.element, std::string("attribute '") + what + "': no block " + std::to_string(file_id));
        return unsigned(it->second);
      }
      auto it = id_of.find(file_id);
      if (it == id_of.end()) reader.fail(r.element, std::string("attribute '") + what + "': no particle " + std::to_string(file_id));
      return unsigned(it->second);
    };
    const unsigned p = id("particle", r.particle, false), a = id("a", r.a, true), at = id("a_to", r.a_to, false);
    const unsigned b = id("b", r.b, true), bt = id("b_to", r.b_to, false);
    try {
      m.set_rigid_joint(p, a, at, b, bt, r.angle);
    } catch (const ModelError& e) {
      reader.fail(r.element, e.what());
    }
  }
  for (const GoalRecord& r : d.goals) {
    Goal g = r.goal;
    for (ParticleId& p : g.members) {  // a rigid body: i is its first member
      auto it = id_of.find(p);
      if (it == id_of.end()) reader.fail(r.element, "<member p>: no particle " + std::to_string(p));
      p = it->second;
    }
    if (g.kind == Goal::Rigid) {
      try {
        m.add_goal(g);
      } catch (const ModelError& e) {
        reader.fail(r.element, e.what());
      }
      continue;
    }
    auto i = id_of.find(g.i);
    if (i == id_of.end()) reader.fail(r.element, "attribute 'i': no particle " + std::to_string(g.i));
    g.i = i->second;
    if (g.kind == Goal::Length || g.kind == Goal::Planar || g.kind == Goal::Bend) {
      auto j = id_of.find(g.j);
      if (j == id_of.end()) reader.fail(r.element, "attribute 'j': no particle " + std::to_string(g.j));
      g.j = j->second;
    }
    if (g.kind == Goal::Planar || g.kind == Goal::Bend) {
      for (auto [name, q] : {std::pair<const char*, ParticleId*>{"k", &g.k}, {"l", &g.l}}) {
        auto it = id_of.find(*q);
        if (it == id_of.end()) reader.fail(r.element, std::string("attribute '") + name + "': no particle " + std::to_string(*q));
        *q = it->second;
      }
    }
    try {
      m.add_goal(g);
    } catch (const ModelError& e) {
      reader.fail(r.element, e.what());
    }
  }
}

// tinyxml2 checks each new attribute against all before it: an element with
// 40 000 attributes took 17 s to parse. No element of the format has more
// than 24, so a tag with more than kMaxAttributes is refused before parsing,
// by a linear scan that counts the '=' of each tag outside quoted values
// (comments, CDATA, declarations and processing instructions skipped).
constexpr std::size_t kMaxAttributes = 64;

void refuse_crowded_tags(const std::string& xml, const std::string& name) {
  const std::size_t n = xml.size();
  std::size_t line = 1;
  auto skip_to = [&](std::size_t from, const char* end) {
    const std::size_t at = xml.find(end, from);
    const std::size_t stop = at == std::string::npos ? n : at + std::strlen(end);
    line += std::size_t(std::count(xml.begin() + std::ptrdiff_t(from), xml.begin() + std::ptrdiff_t(stop), '\n'));
    return stop;
  };
  for (std::size_t k = 0; k < n;) {
    if (xml[k] == '\n') ++line;
    if (xml[k] != '<') {
      ++k;
      continue;
    }
    if (xml.compare(k, 4, "<!--") == 0) k = skip_to(k, "-->");
    else if (xml.compare(k, 9, "<![CDATA[") == 0) k = skip_to(k, "]]>");
    else if (xml.compare(k, 2, "<?") == 0) k = skip_to(k, "?>");
    else if (xml.compare(k, 2, "<!") == 0) k = skip_to(k, ">");
    else {
      const std::size_t tag_line = line;
      std::size_t equals = 0;
      char quote = 0;
      for (++k; k < n && (quote || xml[k] != '>'); ++k) {
        if (xml[k] == '\n') ++line;
        if (quote) {
          if (xml[k] == quote) quote = 0;
        } else if (xml[k] == '"' || xml[k] == '\'') {
          quote = xml[k];
        } else if (xml[k] == '=' && ++equals > kMaxAttributes) {
          throw ModelFormatError(name + ":" + std::to_string(tag_line) + ": an element with more than " +
                                 std::to_string(kMaxAttributes) +
                                 " attributes; no element of a model database has more than 24");
        }
      }
    }
  }
}

void load(const std::string& xml, const std::string& name, Model& m, SolverSettings& s) {
  if (m.particles.capacity() != 0 || !m.blocks.empty() || m.map.capacity() != 0)
    throw ModelError("load_model_xml: the target model must be a fresh Model");
  refuse_crowded_tags(xml, name);
  tinyxml2::XMLDocument doc;
  doc.Parse(xml.data(), xml.size());
  if (doc.ErrorID() == tinyxml2::XML_ERROR_EMPTY_DOCUMENT)
    throw ModelFormatError(name + ": no root element; expected <tendril version=\"1\">");
  if (doc.Error())
    throw ModelFormatError(name + ":" + std::to_string(doc.ErrorLineNum()) + ": malformed XML: " +
                           clipped(doc.ErrorStr(), 200));
  Reader reader(name);
  Document d = reader.read(doc);
  {
    Model scratch;
    build(reader, d, scratch);
    if (std::string c = scratch.check(); !c.empty())
      reader.fail(doc.RootElement(), "the loaded model is invalid: " + c);
  }
  build(reader, d, m);
  s = d.settings;
}

}  // namespace

std::string model_xml_string(const Model& m, const SolverSettings& s) { return write_document(m, s); }

void save_model_xml(const Model& m, const SolverSettings& s, const std::string& path) {
  write_file_atomically(path, write_document(m, s));
}

void load_model_xml_string(const std::string& xml, Model& m, SolverSettings& s, const std::string& name) {
  load(xml, name, m, s);
}

void load_model_xml(const std::string& path, Model& m, SolverSettings& s) {
  load(read_input_file(path), path, m, s);
}

}  // namespace tendril
