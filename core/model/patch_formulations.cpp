// Switching a tensile patch between elastic bars and constant strain
// triangles (thesis 5.5.2.2). The quads of the map stay; what changes is the
// element buffers of the one patch, so the cost is proportional to it. The
// triangulation is model state on the map (cst_first, cst_reference), the
// Cst elements a cache derived from it like bars from edges.
#include <algorithm>
#include <cmath>
#include <map>

#include "model/model.hpp"

namespace tendril {

namespace {

std::string bid(BlockId b) { return std::to_string(b); }

std::string triangle_name(const Model::Triangle& t) {
  return "(" + std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

bool finite(double x) { return std::isfinite(x); }

void check_membrane(const Membrane& m) {
  const std::string what = "formulation: ";
  if (!finite(m.sigma_warp) || !finite(m.sigma_weft) || m.sigma_warp < 0 || m.sigma_weft < 0)
    throw ModelError(what + "the warp and weft stresses must be finite numbers >= 0 [N/m]");
  const bool stiff = m.dxx != 0 || m.dxy != 0 || m.dyx != 0 || m.dyy != 0 || m.G != 0;
  switch (m.mode) {
    case Membrane::Bars:
      if (stiff || m.sigma_warp != 0 || m.sigma_weft != 0)
        throw ModelError(what + "a patch of bars takes no membrane stresses or stiffnesses");
      break;
    case Membrane::FormFinding:
      if (stiff) throw ModelError(what + "the stiffnesses dxx, dxy, dyx, dyy, G belong to analysis, not form-finding");
      if (!(m.sigma_warp + m.sigma_weft > 0))
        throw ModelError(what + "form-finding needs a warp or weft stress > 0 (a membrane without stress has no shape)");
      break;
    case Membrane::Analysis:
      for (double d : {m.dxx, m.dxy, m.dyx, m.dyy, m.G})
        if (!finite(d)) throw ModelError(what + "the stiffnesses dxx, dxy, dyx, dyy, G must be finite");
      if (!(m.dxx > 0) || !(m.dyy > 0) || m.G < 0)
        throw ModelError(what + "analysis needs dxx > 0, dyy > 0 and G >= 0 [N/m]");
      if (!(m.dxx * m.dyy > m.dxy * m.dyx))
        throw ModelError(what + "dxx dyy must exceed dxy dyx (a stable orthotropic membrane)");
      break;
    default: throw ModelError(what + "unknown membrane mode");
  }
}

}  // namespace

const char* membrane_mode_name(Membrane::Mode m) {
  switch (m) {
    case Membrane::Bars: return "bars";
    case Membrane::FormFinding: return "form";
    case Membrane::Analysis: return "analysis";
  }
  return "?";
}

const Membrane& Model::patch_formulation(BlockId b) const {
  require_block(b, "formulation");
  if (blocks[b].kind != BlockKind::Patch) throw ModelError("formulation: block " + bid(b) + " is not a patch");
  return blocks[b].membrane;
}

void Model::set_patch_formulation(BlockId b, const Membrane& mem, const std::vector<Triangle>& triangles,
                                  const std::vector<CstReference>* reference) {
  require_block(b, "formulation");
  if (blocks[b].kind != BlockKind::Patch)
    throw ModelError("formulation: block " + bid(b) + " is a " + block_kind_name(blocks[b].kind) +
                     "; only patches switch between bars and CST");
  check_membrane(mem);
  const std::size_t quads = blocks[b].darts / 8;
  if (!mem.cst() && !triangles.empty())
    throw ModelError("formulation: a patch of bars takes no triangles");
  if (mem.cst() && triangles.size() != 2 * quads)
    throw ModelError("formulation: patch " + bid(b) + " has " + std::to_string(quads) + " quads and needs " +
                     std::to_string(2 * quads) + " triangles, got " + std::to_string(triangles.size()));
  if (reference && reference->size() != triangles.size())
    throw ModelError("formulation: " + std::to_string(reference->size()) + " reference geometries for " +
                     std::to_string(triangles.size()) + " triangles");

  // Validate everything before touching the model: every triangle is half
  // of a quad of the patch, paired with the other half across its diagonal.
  auto next = [&](Dart x) { return map.alpha(1, map.alpha(0, x)); };
  std::vector<Dart> starts;
  std::vector<CstReference> refs;
  std::map<Dart, std::size_t> taken;  // start dart -> triangle
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Triangle& tri = triangles[t];
    for (ParticleId p : tri) require_particle(p, "formulation");
    Dart found = kNoDart;
    for (Dart d : darts_of(tri[0])) {
      if (dart_block[d] != b) continue;
      const Dart x = map.alpha(0, d);
      if (dart_particle[x] == tri[1] && dart_particle[map.alpha(0, next(d))] == tri[2]) {
        found = d;
        break;
      }
    }
    if (found == kNoDart)
      throw ModelError("formulation: triangle " + std::to_string(t) + " " + triangle_name(tri) +
                       " is not half of a quad of patch " + bid(b) +
                       " (sides a-b and b-c must be consecutive sides of one quad)");
    if (!taken.emplace(found, t).second)
      throw ModelError("formulation: triangles " + std::to_string(taken[found]) + " and " + std::to_string(t) +
                       " are the same triangle " + triangle_name(tri));
    starts.push_back(found);
    CstReference r;
    if (reference) {
      r = (*reference)[t];
      if (!finite(r.l1) || !finite(r.h) || !finite(r.c) || !(r.l1 > 0) || !(r.h > 0))
        throw ModelError("formulation: the reference geometry of triangle " + triangle_name(tri) +
                         " needs finite l1 > 0 and h > 0");
    } else if (mem.mode == Membrane::Analysis) {
      const Vec3 a = particles.position[tri[1]] - particles.position[tri[0]];
      const Vec3 c = particles.position[tri[2]] - particles.position[tri[0]];
      r.l1 = a.norm();
      const double twice_area = a.cross(c).norm();
      const double longest = std::max({a.squaredNorm(), c.squaredNorm(), (c - a).squaredNorm()});
      if (!(r.l1 > 0) || !(twice_area > 1e-10 * longest))
        throw ModelError("formulation: triangle " + triangle_name(tri) +
                         " has no area (its particles are collinear); analysis needs a reference shape");
      r.h = twice_area / r.l1;
      r.c = c.dot(a) / r.l1;
    }
    refs.push_back(r);
  }
  for (const auto& [d, t] : taken)
    if (!taken.count(next(next(d))))
      throw ModelError("formulation: triangle " + std::to_string(t) + " " + triangle_name(triangles[t]) +
                       " has no partner (c, d, a) across its quad's diagonal");

  // Apply: old triangles go, interior bars follow the new mode, new triangles come.
  const std::vector<Dart> darts = map.orbit(kComponentOrbit, blocks[b].dart);
  const bool was_cst = blocks[b].membrane.cst();
  for (Dart d : darts) {
    remove_cst(d);
    if (cst_first[d]) {
      cst_first[d] = 0;
      cst_reference[d] = CstReference{};
    }
  }
  blocks[b].membrane = mem;
  for (Dart d : darts) {
    if (map.is_free(2, d)) continue;  // boundary edges keep their bars
    if (mem.cst()) remove_bar(d);
    else if (was_cst && dart_bar[d] == kNone) add_bar(d);
  }
  for (std::size_t t = 0; t < starts.size(); ++t) {
    cst_first[starts[t]] = 1;
    cst_reference[starts[t]] = refs[t];
    add_cst(starts[t]);
  }
}

std::vector<Model::Triangle> Model::patch_triangles(BlockId b, std::vector<CstReference>* reference) const {
  patch_formulation(b);  // a live patch
  std::vector<Triangle> out;
  if (reference) reference->clear();
  std::vector<Dart> darts = map.orbit(kComponentOrbit, blocks[b].dart);
  std::sort(darts.begin(), darts.end());
  for (Dart d : darts) {
    if (!cst_first[d]) continue;
    const Dart x = map.alpha(0, d);
    out.push_back({dart_particle[d], dart_particle[x], dart_particle[map.alpha(0, map.alpha(1, x))]});
    if (reference) reference->push_back(cst_reference[d]);
  }
  return out;
}

// --- elements ------------------------------------------------------------------

bool Model::edge_has_bar(Dart d) const { return !(is_cst_patch(dart_block[d]) && !map.is_free(2, d)); }

void Model::add_cst(Dart d) {
  ++revision;
  const ElementIndex e = static_cast<ElementIndex>(csts.size());
  Cst c{};
  c.membrane = blocks[dart_block[d]].membrane;
  c.ref = cst_reference[d];
  c.dart = d;
  csts.items.push_back(c);
  dart_cst[d] = e;
  bind_cst(e);
}

namespace {
// A vertex of a patch is interior when no edge at it is on the boundary.
bool interior_vertex(const GMap& map, Dart v) {
  bool interior = true;
  map.for_orbit(kVertexOrbit, v, [&](Dart x) {
    interior = !map.is_free(2, x);
    return interior;
  });
  return interior;
}

std::uint8_t interior_corners(const GMap& map, Dart d) {
  const Dart x = map.alpha(0, d), y = map.alpha(0, map.alpha(1, x));
  return std::uint8_t(interior_vertex(map, d) | interior_vertex(map, x) << 1 | interior_vertex(map, y) << 2);
}
}  // namespace

void Model::bind_cst(ElementIndex e) {
  ++revision;
  Cst& c = csts[e];
  const Dart x = map.alpha(0, c.dart);
  c.i = dart_particle[c.dart];
  c.j = dart_particle[x];
  c.k = dart_particle[map.alpha(0, map.alpha(1, x))];
  c.interior = interior_corners(map, c.dart);
  place_cst(e);
}

// Awake when none of its corners is passive (ElementBuffer, thesis 5.5.2.3).
void Model::place_cst(ElementIndex e) {
  const Cst& c = std::as_const(csts)[e];
  const bool wake = !particles.passive[c.i] && !particles.passive[c.j] && !particles.passive[c.k];
  csts.place(e, wake, [this](ElementIndex k) { dart_cst[std::as_const(csts)[k].dart] = k; });
}

void Model::remove_cst(Dart d) {
  ++revision;
  const ElementIndex e = dart_cst[d];
  if (e == kNone) return;
  csts.erase(e, [this](ElementIndex k) { dart_cst[std::as_const(csts)[k].dart] = k; });
  dart_cst[d] = kNone;
}

void Model::refresh_csts(Dart d) {
  if (!is_cst_patch(dart_block[d])) return;
  map.for_orbit(kFaceOrbit, d, [&](Dart x) {
    if (dart_cst[x] != kNone) bind_cst(dart_cst[x]);
    return true;
  });
}

// The triangles of the face of d, as a CST patch needs them: exactly two
// marked darts, the second two sides after the first, each with its element.
std::string Model::check_cst_face(Dart d) const {
  const std::string where = "dart " + std::to_string(d) + " of CST patch " + bid(dart_block[d]);
  int marked = 0;
  std::string err;
  map.for_orbit(kFaceOrbit, d, [&](Dart x) {
    if (cst_first[x]) ++marked;
    return true;
  });
  if (marked != 2) return where + ": its quad has " + std::to_string(marked) + " triangle starts, not 2";
  if (!cst_first[d]) {
    if (dart_cst[d] != kNone) return where + " has a stray CST element";
    return {};
  }
  auto next = [&](Dart x) { return map.alpha(1, map.alpha(0, x)); };
  if (!cst_first[next(next(d))]) return where + ": the two triangles of its quad do not share the diagonal";
  const ElementIndex e = dart_cst[d];
  if (e == kNone || e >= csts.size()) return where + " starts a triangle without a CST element";
  const Cst& c = csts[e];
  const std::string name = "CST element " + std::to_string(e);
  if (c.dart != d) return name + " does not point back to its dart";
  const Dart x = map.alpha(0, d);
  if (c.i != dart_particle[d] || c.j != dart_particle[x] || c.k != dart_particle[map.alpha(0, map.alpha(1, x))] ||
      c.interior != interior_corners(map, d))
    return name + " has stale particles";
  if ((e < csts.awake) != (!particles.passive[c.i] && !particles.passive[c.j] && !particles.passive[c.k]))
    return name + " is on the wrong side of the awake/dormant partition";
  if (!(c.membrane == blocks[dart_block[d]].membrane) || !(c.ref == cst_reference[d]))
    return name + " parameters differ from its patch and dart";
  return {};
}

}  // namespace tendril
