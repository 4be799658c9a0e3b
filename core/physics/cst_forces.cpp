// Constant strain triangles (thesis 3.2.8.2): nodal forces of a uniform
// membrane stress and the greatest direct stiffnesses of eq. 3.40 for the
// fictitious masses of eq. 3.4.
//
// Frame: e1 along side 1 (i -> j, the warp, eq. 3.36), e3 the normal, e2 =
// e3 x e1 in the plane towards k, all in the deformed state. The in-plane
// stress is sigma_x e1e1 + sigma_y e2e2 + tau (e1e2 + e2e1). A uniform stress
// pulls each corner a with 1/2 sigma m_a, m_a the outward normal of the
// opposite side times its length. Written as tensions along the three sides
// this is exactly Barnes' eq. 3.36 (direct stresses) and eq. 3.39 (shear);
// the stress form stays bounded when the triangle degenerates, where the
// side tensions (cot of angles going to 0) do not.
//
// Analysis (eq. 3.37-3.38): with the reference side 1 of length l1 along x
// and k at (c, h), and now (c', h') on side l1', the strains are
// eps_x = l1'/l1 - 1, eps_y = h'/h - 1 and the shear gamma = (c' - c (1 +
// eps_x)) / h: eq. 3.37's gamma times (1 + eps_y), the same to first order,
// without dividing by the current height.
//
// In form-finding the prescribed stresses have no in-plane stiffness: the
// interior vertices of a patch would slide in the surface towards ever
// smaller triangles (the mesh drift the thesis' G-strings prevent, fig.
// 3.11). So an interior vertex takes only the component of its CST pull
// along its normal (the sum of its triangles' area vectors), and in the
// surface it follows the G-strings: the warp and weft lines of the quads
// (sides 1 and 2 of the triangles) pull it with one force density, the
// mean of sigma_warp and sigma_weft [N/m] (one for both directions, so that
// unequal stresses do not squash the quads), and it takes their component
// in its tangent plane only. They move a vertex within the surface, never
// across it, so the shape is that of the membrane; they keep the mesh as regular
// as the boundary allows while the boundary moves (a bending-active arch
// deflecting under the membrane) or the surface grows far from its start
// (a minimal surface from a flat sheet), and they carry what a load has in
// the surface, which a prescribed stress cannot. Boundary vertices take
// the whole pull: it is what their edge cables, beams or supports carry.
// Analysis has elastic in-plane stiffness and takes the whole pull
// everywhere.
//
// A triangle whose area vanishes (collinear corners, twice its area below
// 1e-10 times its longest side squared) has no plane and no normal: it
// exerts no force and adds only its elastic stiffness.
#include <algorithm>

#include "physics/solver.hpp"

namespace tendril {

namespace {
constexpr double kDegenerate = 1e-10;
}

void Solver::accumulate_cst_forces(const Vec3* x, Vec3* F, double* S) const {
  const double gf = settings.geometric_factor;
  const std::size_t capacity = model_.particles.capacity();
  if (cst_pull_.size() != capacity) {  // grows with the particles, never per step
    cst_pull_.assign(capacity, Vec3::Zero());
    cst_normal_.assign(capacity, Vec3::Zero());
    cst_smooth_.assign(capacity, Vec3::Zero());
  }
  bool gathered = false;
  for (const Cst* tp = model_.csts.awake_begin(); tp != model_.csts.awake_end(); ++tp) {  // awake only
    const Cst& t = *tp;
    const Membrane& m = t.membrane;
    const bool analysis = m.mode == Membrane::Analysis;
    // Elastic stiffness (analysis): the diagonal of A B^T D B bounded over
    // directions, on the reference shape, eq. 3.35's EA / L for a membrane.
    double elastic[3] = {0, 0, 0};
    if (analysis) {
      const double d = std::max(m.dxx, m.dyy) + std::max(std::abs(m.dxy), std::abs(m.dyx)) + m.G;
      const CstReference& r = t.ref;
      const double twice_area = r.l1 * r.h;
      elastic[0] = d * ((r.c - r.l1) * (r.c - r.l1) + r.h * r.h) / twice_area;
      elastic[1] = d * (r.c * r.c + r.h * r.h) / twice_area;
      elastic[2] = d * r.l1 * r.l1 / twice_area;
    }
    const Vec3 a = x[t.j] - x[t.i], b = x[t.k] - x[t.i], side3 = x[t.k] - x[t.j];
    const std::uint8_t along_normal = analysis ? 0 : t.interior;
    if (along_normal) {  // the G-strings: side 1 (i -> j) warp, side 2 (j -> k) weft
      auto g_string = [&](ParticleId u, int cu, ParticleId v, int cv, const Vec3& uv, double q) {
        if (along_normal >> cu & 1) {
          cst_smooth_[u] += q * uv;
          S[u] += q;
        }
        if (along_normal >> cv & 1) {
          cst_smooth_[v] -= q * uv;
          S[v] += q;
        }
      };
      const double q = 0.5 * (m.sigma_warp + m.sigma_weft);
      g_string(t.i, 0, t.j, 1, a, q);
      g_string(t.j, 1, t.k, 2, side3, q);
      gathered = true;
    }
    const Vec3 n = a.cross(b);
    const double twice_area = n.norm();
    const double longest = std::max({a.squaredNorm(), b.squaredNorm(), side3.squaredNorm()});
    if (!(twice_area > kDegenerate * longest)) {
      S[t.i] += elastic[0];
      S[t.j] += elastic[1];
      S[t.k] += elastic[2];
      continue;
    }
    const double l1 = a.norm();
    const Vec3 e1 = a / l1, e3 = n / twice_area, e2 = e3.cross(e1);
    double sx = m.sigma_warp, sy = m.sigma_weft, tau = 0;
    if (analysis) {
      const CstReference& r = t.ref;
      const double h = twice_area / l1, c = b.dot(e1);
      const double ex = l1 / r.l1 - 1, ey = h / r.h - 1;
      const double gamma = (c - r.c * (1 + ex)) / r.h;
      sx += m.dxx * ex + m.dxy * ey;  // eq. 3.38
      sy += m.dyx * ex + m.dyy * ey;
      tau = m.G * gamma;
    }
    auto pull = [&](const Vec3& side) {  // 1/2 sigma m for the side opposite a corner
      const Vec3 out = side.cross(e3);
      const double u = out.dot(e1), v = out.dot(e2);
      return 0.5 * ((sx * u + tau * v) * e1 + (tau * u + sy * v) * e2);
    };
    const Vec3 fi = pull(side3), fj = pull(-b), fk = pull(a);
    auto add = [&](ParticleId p, int corner, const Vec3& f) {
      if (!(along_normal >> corner & 1)) {
        F[p] += f;
        return;
      }
      cst_pull_[p] += f;  // projected below, once all its triangles are in
      cst_normal_[p] += cst_normal_[p].dot(n) < 0 ? Vec3(-n) : n;
      gathered = true;
    };
    add(t.i, 0, fi);
    add(t.j, 1, fj);
    add(t.k, 2, fk);
    // Eq. 3.40: the geometric stiffness of a corner under tension grows with
    // (opposite side)^2 / (twice the area), i.e. base over height; both
    // stresses count, so neither direction is left without mass.
    const double g = gf * (std::max(sx, 0.0) + std::max(sy, 0.0)) / twice_area;
    S[t.i] += elastic[0] + g * side3.squaredNorm();
    S[t.j] += elastic[1] + g * b.squaredNorm();
    S[t.k] += elastic[2] + g * a.squaredNorm();
  }
  if (!gathered) return;
  for (const Cst* tp = model_.csts.awake_begin(); tp != model_.csts.awake_end(); ++tp) {
    const Cst& t = *tp;
    if (t.membrane.mode != Membrane::FormFinding || !t.interior) continue;
    for (const ParticleId p : {t.i, t.j, t.k}) {
      const Vec3 normal = cst_normal_[p], smooth = cst_smooth_[p];
      const double nn = normal.squaredNorm();
      F[p] += smooth;
      if (nn > 0) F[p] += ((cst_pull_[p] - smooth).dot(normal) / nn) * normal;
      cst_pull_[p].setZero();
      cst_normal_[p].setZero();
      cst_smooth_[p].setZero();
    }
  }
}

}  // namespace tendril
