#include "fields.hpp"

#include <cmath>
#include <limits>

namespace tendril::studio {

namespace {

double length(const Model& m, const Topology& t, std::size_t e) {
  const Vec3* x = m.particles.position.data();
  return (x[t.ids[t.edges[2 * e + 1]]] - x[t.ids[t.edges[2 * e]]]).norm();
}

const Section& section(const Model& m, const Topology& t, std::size_t e) {
  return m.blocks[t.blocks[t.edge_block[e]]].section;
}

// Engineering strain of every edge; a slack cable reads 0 (it carries nothing).
std::vector<float> strain(const Model& m, const Topology& t) {
  std::vector<float> out(t.edge_kind.size());
  for (std::size_t e = 0; e < out.size(); ++e) {
    const double l0 = t.rest_length[e];
    double eps = l0 > 0 ? length(m, t, e) / l0 - 1 : 0;
    if (t.edge_kind[e] == std::uint8_t(EdgeKind::Cable) && eps < 0) eps = 0;
    out[e] = float(eps);
  }
  return out;
}

// N = EA strain + the geometric prestress of eq. 3.32.
std::vector<float> axial_force(const Model& m, const Topology& t) {
  std::vector<float> out = strain(m, t);
  for (std::size_t e = 0; e < out.size(); ++e) {
    const Section& s = section(m, t, e);
    const bool slack = t.edge_kind[e] == std::uint8_t(EdgeKind::Cable) && out[e] <= 0;
    out[e] = slack ? 0.f : float(s.EA * out[e] + t.prestress[e]);
  }
  return out;
}

// |M| = EI kappa at the beam's vertices (kappa = 2 tan(theta/2) over the mean
// of the two segments, the curvature of the spline beam's hinge, eq. 3.41),
// averaged onto each segment from its two ends.
std::vector<float> bending_moment(const Model& m, const Topology& t) {
  const std::size_t n = t.edge_kind.size();
  std::vector<float> out(n, std::numeric_limits<float>::quiet_NaN());
  const Vec3* x = m.particles.position.data();
  std::size_t e = 0;
  while (e < n) {  // a block's beam edges are consecutive, in path order
    std::size_t end = e;
    while (end < n && t.edge_block[end] == t.edge_block[e]) ++end;
    if (t.edge_kind[e] == std::uint8_t(EdgeKind::Beam)) {
      const double EI = section(m, t, e).EI;
      const bool ring = end - e > 2 && t.edges[2 * e] == t.edges[2 * (end - 1) + 1];
      auto moment = [&](std::size_t a, std::size_t b) {  // at the vertex shared by edges a then b
        const Vec3 u = x[t.ids[t.edges[2 * a + 1]]] - x[t.ids[t.edges[2 * a]]];
        const Vec3 v = x[t.ids[t.edges[2 * b + 1]]] - x[t.ids[t.edges[2 * b]]];
        const double lu = u.norm(), lv = v.norm(), denom = lu * lv + u.dot(v);
        if (lu == 0 || lv == 0 || denom <= 0) return 0.0;
        return EI * 2 * u.cross(v).norm() / denom / (0.5 * (lu + lv));
      };
      for (std::size_t k = e; k < end; ++k) {
        double sum = 0;
        if (k > e) sum += moment(k - 1, k);
        else if (ring) sum += moment(end - 1, k);
        if (k + 1 < end) sum += moment(k, k + 1);
        else if (ring) sum += moment(k, e);
        out[k] = float(sum / 2);
      }
    }
    e = end;
  }
  return out;
}

}  // namespace

const std::vector<Field>& fields() {
  static const std::vector<Field> all = {
      {"axial force", "N", axial_force},
      {"strain", "-", strain},
      {"bending moment", "N m", bending_moment},
  };
  return all;
}

const Field* find_field(const std::string& name) {
  for (const Field& f : fields())
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace tendril::studio
