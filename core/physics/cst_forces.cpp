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
#include <vector>

#include "physics/cst_plan.hpp"
#include "physics/element_sinks.hpp"
#include "physics/simd_clones.hpp"
#include "physics/solver.hpp"

namespace tendril {

namespace {
constexpr double kDegenerate = 1e-10;

// Triangles are evaluated in blocks, as bars and hinges are (forces.cpp):
// their sides gathered, one vectorised loop without branches for the
// frame, the stresses, the three corner pulls and the stiffnesses, then the
// scatter in the model's order (the G-strings, the pulls and their normals,
// the stiffnesses), so every sum is added in the model's order of its
// triangles, whatever the block size or the thread count. 32 a block: its
// 40 columns take 10 KB of the 32 KB L1 beside the chunk's sums (64: 1.04x
// slower at 100K, the same at 10K; 16 and 32 alike; stop 44).
constexpr std::uint32_t kCstBlock = 32;

struct CstBlock {
  // in: sides i -> j (a), i -> k (b), j -> k (side3); the membrane
  alignas(64) double ax[kCstBlock], ay[kCstBlock], az[kCstBlock];
  alignas(64) double bx[kCstBlock], by[kCstBlock], bz[kCstBlock];
  alignas(64) double cx[kCstBlock], cy[kCstBlock], cz[kCstBlock];
  alignas(64) double sigma_warp[kCstBlock], sigma_weft[kCstBlock];
  alignas(64) double dxx[kCstBlock], dxy[kCstBlock], dyx[kCstBlock], dyy[kCstBlock], G[kCstBlock];
  alignas(64) double l1[kCstBlock], h[kCstBlock], c[kCstBlock];
  alignas(64) double analysis[kCstBlock];  // 1 or 0 (flags as doubles: bytes would keep SSE2 scalar)
  // out: the pulls on i, j, k, the normal a x b, the stiffnesses with and
  // without a plane (elastic), whether the triangle has a plane
  alignas(64) double fix[kCstBlock], fiy[kCstBlock], fiz[kCstBlock];
  alignas(64) double fjx[kCstBlock], fjy[kCstBlock], fjz[kCstBlock];
  alignas(64) double fkx[kCstBlock], fky[kCstBlock], fkz[kCstBlock];
  alignas(64) double nx[kCstBlock], ny[kCstBlock], nz[kCstBlock];
  alignas(64) double si[kCstBlock], sj[kCstBlock], sk[kCstBlock];
  alignas(64) double ei[kCstBlock], ej[kCstBlock], ek[kCstBlock];
  alignas(64) double flat[kCstBlock];
};

// kAnalysis false: every triangle of the block is in form-finding, and the
// analysis fields are neither gathered nor read.
template <bool kAnalysis>
TENDRIL_SIMD_CLONES void cst_block(CstBlock& t, std::uint32_t n, double gf) {
#pragma omp simd
  for (std::uint32_t m = 0; m < n; ++m) {
    const bool analysis = kAnalysis && t.analysis[m] != 0;
    // Elastic stiffness (analysis): the diagonal of A B^T D B bounded over
    // directions, on the reference shape, eq. 3.35's EA / L for a membrane.
    const double dxx = kAnalysis ? t.dxx[m] : 0.0, dxy = kAnalysis ? t.dxy[m] : 0.0, dyx = kAnalysis ? t.dyx[m] : 0.0;
    const double dyy = kAnalysis ? t.dyy[m] : 0.0, G = kAnalysis ? t.G[m] : 0.0;
    const double r_l1 = kAnalysis ? t.l1[m] : 1.0, r_h = kAnalysis ? t.h[m] : 1.0, r_c = kAnalysis ? t.c[m] : 0.0;
    const double adxy = std::abs(dxy), adyx = std::abs(dyx);
    const double d = (dxx < dyy ? dyy : dxx) + (adxy < adyx ? adyx : adxy) + G;
    const double ref_twice_area = r_l1 * r_h;
    const double e0 = analysis ? d * ((r_c - r_l1) * (r_c - r_l1) + r_h * r_h) / ref_twice_area : 0.0;
    const double e1 = analysis ? d * (r_c * r_c + r_h * r_h) / ref_twice_area : 0.0;
    const double e2 = analysis ? d * r_l1 * r_l1 / ref_twice_area : 0.0;
    t.ei[m] = e0, t.ej[m] = e1, t.ek[m] = e2;
    const double ax = t.ax[m], ay = t.ay[m], az = t.az[m], bx = t.bx[m], by = t.by[m], bz = t.bz[m];
    const double cx = t.cx[m], cy = t.cy[m], cz = t.cz[m];
    const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;  // a x b
    t.nx[m] = nx, t.ny[m] = ny, t.nz[m] = nz;
    const double twice_area = std::sqrt(nx * nx + ny * ny + nz * nz);
    const double aa = ax * ax + ay * ay + az * az, bb = bx * bx + by * by + bz * bz, cc = cx * cx + cy * cy + cz * cz;
    double longest = aa;  // std::max({aa, bb, cc}): the first of the largest
    longest = longest < bb ? bb : longest;
    longest = longest < cc ? cc : longest;
    t.flat[m] = !(twice_area > kDegenerate * longest) ? 1.0 : 0.0;
    // The frame with two divisions: e1 = a / l1, e2 = e3 x e1 = (n x a) /
    // (|n| l1). In it the corners' opposite sides (c, -b, a) have the
    // coordinates (l1 - b1, h), (b1, -h) and (-l1, 0), b1 = b . e1 and h
    // = |n| / l1 the height of k over side 1, and side x e3 turns (s1, s2)
    // into (s2, -s1): the pulls of 1/2 sigma m need no cross products.
    const double l1 = std::sqrt(aa), inv_l1 = 1.0 / l1, inv_e2 = inv_l1 / twice_area;
    const double e1x = ax * inv_l1, e1y = ay * inv_l1, e1z = az * inv_l1;
    const double e2x = (ny * az - nz * ay) * inv_e2, e2y = (nz * ax - nx * az) * inv_e2,
                 e2z = (nx * ay - ny * ax) * inv_e2;
    const double h = twice_area * inv_l1, b1 = (bx * ax + by * ay + bz * az) * inv_l1;
    double sx = t.sigma_warp[m], sy = t.sigma_weft[m], tau = 0;
    {  // analysis: eq. 3.37-3.38
      const double ex = l1 / r_l1 - 1, ey = h / r_h - 1;
      const double gamma = (b1 - r_c * (1 + ex)) / r_h;
      const double ax_sx = sx + (dxx * ex + dxy * ey), ax_sy = sy + (dyx * ex + dyy * ey);
      sx = analysis ? ax_sx : sx;
      sy = analysis ? ax_sy : sy;
      tau = analysis ? G * gamma : 0.0;
    }
    // Corner i (u = h, v = l1 - b1) and k (u = 0, v = -l1): A = sx u + tau
    // v along e1, B = tau u + sy v along e2, halved; j takes what keeps the
    // three in equilibrium. Without analysis tau is 0 and its terms go.
    const double hx = 0.5 * sx, hy = 0.5 * sy, ht = 0.5 * tau, vi = l1 - b1;
    const double Ai = kAnalysis ? hx * h + ht * vi : hx * h, Bi = kAnalysis ? ht * h + hy * vi : hy * vi;
    const double Ak = kAnalysis ? -(ht * l1) : 0.0, Bk = -(hy * l1);
    const double fix = Ai * e1x + Bi * e2x, fiy = Ai * e1y + Bi * e2y, fiz = Ai * e1z + Bi * e2z;
    const double fkx = kAnalysis ? Ak * e1x + Bk * e2x : Bk * e2x, fky = kAnalysis ? Ak * e1y + Bk * e2y : Bk * e2y,
                 fkz = kAnalysis ? Ak * e1z + Bk * e2z : Bk * e2z;
    t.fix[m] = fix, t.fiy[m] = fiy, t.fiz[m] = fiz;
    t.fkx[m] = fkx, t.fky[m] = fky, t.fkz[m] = fkz;
    t.fjx[m] = -(fix + fkx), t.fjy[m] = -(fiy + fky), t.fjz[m] = -(fiz + fkz);
    // Eq. 3.40: the geometric stiffness of a corner under tension grows with
    // (opposite side)^2 / (twice the area), i.e. base over height; both
    // stresses count, so neither direction is left without mass.
    const double g = gf * ((sx < 0.0 ? 0.0 : sx) + (sy < 0.0 ? 0.0 : sy)) / twice_area;
    t.si[m] = e0 + g * cc;
    t.sj[m] = e1 + g * bb;
    t.sk[m] = e2 + g * aa;
  }
}

// a += b and a -= b, component by component as Eigen adds: Eigen's
// operators, inlined many times in the loop below, stop being inlined.
TENDRIL_INLINE inline void add_into(Vec3& a, const Vec3& b) { a.x() += b.x(), a.y() += b.y(), a.z() += b.z(); }
TENDRIL_INLINE inline void subtract_from(Vec3& a, const Vec3& b) { a.x() -= b.x(), a.y() -= b.y(), a.z() -= b.z(); }

// Where a projected corner's sums are: the model's slot of triangle e's
// corner c (one thread's triangles), or the chunk's own row of particle p
// (a chunk's: rows indexed like its force sums, in a scratch that stays in
// the cache, read without the slots' indirection).
struct CornerSlots {
  const std::uint32_t* slot;
  CstCornerSums* sums;
  TENDRIL_INLINE CstCornerSums& operator()(std::uint32_t e, int c, ParticleId) const { return sums[slot[3 * e + c]]; }
  TENDRIL_INLINE CstCornerSums& of_slot(std::uint32_t s, ParticleId) const { return sums[s]; }
};
struct CornerRows {
  CstCornerSums* rows;
  ParticleId base;
  TENDRIL_INLINE CstCornerSums& operator()(std::uint32_t, int, ParticleId p) const { return rows[p - base]; }
  TENDRIL_INLINE CstCornerSums& of_slot(std::uint32_t, ParticleId p) const { return rows[p - base]; }
};

// One thread's (or chunk's) triangles: items[0 .. count) (kShared) or
// 0 .. count, in the model's order, their forces and G-strings added into
// the particles it owns, the pulls of its projected corners into their
// sums.
template <bool kShared, class Sink, class Corners>
TENDRIL_SIMD_CLONES void cst_forces(const CstPlan& plan, const Cst* csts, const std::uint32_t* items,
                                    std::uint32_t count, Owned<kShared> own, const Vec3* x, double gf, Sink out,
                                    Corners corner) {
  const ParticleId *ti = plan.i.data(), *tj = plan.j.data(), *tk = plan.k.data();
  CstBlock tb;
  for (std::uint32_t e0 = 0; e0 < count; e0 += kCstBlock) {
    const std::uint32_t n = std::min(kCstBlock, count - e0);
    bool analysis = false;
    for (std::uint32_t m = 0; m < n; ++m) {
      const std::uint32_t e = kShared ? items[e0 + m] : e0 + m;
      // Read as doubles: copies of the Vec3s went through the stack, and
      // their z back from it, a third of this loop's time (perf).
      const double *xi = x[ti[e]].data(), *xj = x[tj[e]].data(), *xk = x[tk[e]].data();
      tb.ax[m] = xj[0] - xi[0], tb.ay[m] = xj[1] - xi[1], tb.az[m] = xj[2] - xi[2];
      tb.bx[m] = xk[0] - xi[0], tb.by[m] = xk[1] - xi[1], tb.bz[m] = xk[2] - xi[2];
      tb.cx[m] = xk[0] - xj[0], tb.cy[m] = xk[1] - xj[1], tb.cz[m] = xk[2] - xj[2];
      tb.sigma_warp[m] = plan.sigma_warp[e], tb.sigma_weft[m] = plan.sigma_weft[e];
      analysis |= plan.analysis[e] != 0;
    }
    if (analysis) {
      for (std::uint32_t m = 0; m < n; ++m) {
        const Cst& t = csts[kShared ? items[e0 + m] : e0 + m];
        const Membrane& mb = t.membrane;
        tb.dxx[m] = mb.dxx, tb.dxy[m] = mb.dxy, tb.dyx[m] = mb.dyx, tb.dyy[m] = mb.dyy, tb.G[m] = mb.G;
        tb.l1[m] = t.ref.l1, tb.h[m] = t.ref.h, tb.c[m] = t.ref.c;
        tb.analysis[m] = mb.mode == Membrane::Analysis ? 1.0 : 0.0;
      }
      cst_block<true>(tb, n, gf);
    } else {
      cst_block<false>(tb, n, gf);
    }
    for (std::uint32_t m = 0; m < n; ++m) {
      const std::uint32_t e = kShared ? items[e0 + m] : e0 + m;
      const ParticleId i = ti[e], j = tj[e], k = tk[e];
      const Vec3 nrm(tb.nx[m], tb.ny[m], tb.nz[m]);
      // A projected corner: its pull, and the normal oriented to its sum so
      // far (projected in project_corners, once all its triangles are in).
      auto pull_into = [&](CstCornerSums& c, const Vec3& f) TENDRIL_INLINE {
        add_into(c.pull, f);
        add_into(c.normal, c.normal.dot(nrm) < 0 ? Vec3(-nrm.x(), -nrm.y(), -nrm.z()) : nrm);
      };
      if (plan.along_normal[e] == CstPlan::kAllCorners && tb.flat[m] == 0 && own(i) && own(j) && own(k)) [[likely]] {
        // The common triangle (every corner owned and projected, a plane):
        // the general path's additions below, each sum's in its order, but
        // grouped by sum: j's G-strings (it ends side 1 and starts side 2)
        // and a corner's stiffnesses (its strings', then its pull's) take
        // one load and one store each, not a store and a load of the same
        // sum back to back.
        const double q = plan.g_string[e];
        const Vec3 qa(q * tb.ax[m], q * tb.ay[m], q * tb.az[m]), qc(q * tb.cx[m], q * tb.cy[m], q * tb.cz[m]);
        CstCornerSums &ci = corner(e, 0, i), &cj = corner(e, 1, j), &ck = corner(e, 2, k);
        add_into(ci.smooth, qa);
        cj.smooth = Vec3((cj.smooth.x() - qa.x()) + qc.x(), (cj.smooth.y() - qa.y()) + qc.y(),
                         (cj.smooth.z() - qa.z()) + qc.z());
        subtract_from(ck.smooth, qc);
        pull_into(ci, Vec3(tb.fix[m], tb.fiy[m], tb.fiz[m]));
        out.stiffness(i, q, tb.si[m]);
        pull_into(cj, Vec3(tb.fjx[m], tb.fjy[m], tb.fjz[m]));
        out.stiffness(j, q, q, tb.sj[m]);
        pull_into(ck, Vec3(tb.fkx[m], tb.fky[m], tb.fkz[m]));
        out.stiffness(k, q, tb.sk[m]);
        continue;
      }
      const bool own_i = own(i), own_j = own(j), own_k = own(k);
      const std::uint8_t along_normal = plan.along_normal[e];
      if (along_normal) {  // the G-strings: side 1 (i -> j) warp, side 2 (j -> k) weft
        auto g_string = [&](ParticleId u, int cu, bool own_u, ParticleId v, int cv, bool own_v, const Vec3& uv,
                            double q) TENDRIL_INLINE {
          if ((along_normal >> cu & 1) && own_u) {
            add_into(corner(e, cu, u).smooth, Vec3(q * uv.x(), q * uv.y(), q * uv.z()));
            out.stiffness(u, q);
          }
          if ((along_normal >> cv & 1) && own_v) {
            subtract_from(corner(e, cv, v).smooth, Vec3(q * uv.x(), q * uv.y(), q * uv.z()));
            out.stiffness(v, q);
          }
        };
        const double q = plan.g_string[e];
        g_string(i, 0, own_i, j, 1, own_j, Vec3(tb.ax[m], tb.ay[m], tb.az[m]), q);
        g_string(j, 1, own_j, k, 2, own_k, Vec3(tb.cx[m], tb.cy[m], tb.cz[m]), q);
      }
      if (tb.flat[m] != 0) {  // no plane: no force, the elastic stiffness only
        if (own_i) out.stiffness(i, tb.ei[m]);
        if (own_j) out.stiffness(j, tb.ej[m]);
        if (own_k) out.stiffness(k, tb.ek[m]);
        continue;
      }
      // A corner's force and stiffness go to different lanes of a sum, so
      // adding them at once (one 4-lane addition in a chunk's sums) adds to
      // each lane what the force's and then the stiffness's addition add.
      auto add = [&](ParticleId p, int c, const Vec3& f, double stiffness) TENDRIL_INLINE {
        if (!(along_normal >> c & 1)) {
          out.force_stiffness(p, f, stiffness);
          return;
        }
        pull_into(corner(e, c, p), f);
        out.stiffness(p, stiffness);
      };
      if (own_i) add(i, 0, Vec3(tb.fix[m], tb.fiy[m], tb.fiz[m]), tb.si[m]);
      if (own_j) add(j, 1, Vec3(tb.fjx[m], tb.fjy[m], tb.fjz[m]), tb.sj[m]);
      if (own_k) add(k, 2, Vec3(tb.fkx[m], tb.fky[m], tb.fkz[m]), tb.sk[m]);
    }
  }
}

// The corners of every projected triangle, once each: its G-strings, and
// the part of its pull along its normal, added as one force (one addition
// into the particle's sum, not two in a row on the same sum). Each slot is
// cleared for the next call. The slots slots[0 .. count) (a chunk's) or
// all of them (slots null), those of particles it owns.
// One copy, not three: GCC's AVX copies of it move a register with a form of
// vmovq that valgrind 3.19 cannot decode (SIGILL), and callgrind is how the
// step's instructions are counted (docs/performance.md).
template <bool kShared, class Sink, class Corners>
void project_corners(const CstPlan& plan, const std::uint32_t* slots, std::uint32_t count, Owned<kShared> own,
                     Sink out, Corners corners) {
  if (!slots) count = std::uint32_t(plan.corner.size());
  for (std::uint32_t n = 0; n < count; ++n) {
    const std::uint32_t s = slots ? slots[n] : n;
    const ParticleId p = plan.corner[s];
    if (!own(p)) continue;
    CstCornerSums& c = corners.of_slot(s, p);
    const Vec3 normal = c.normal, smooth = c.smooth;
    const double nn = normal.squaredNorm();
    const double along = nn > 0 ? (c.pull - smooth).dot(normal) / nn : 0.0;
    out.force(p, Vec3(smooth.x() + along * normal.x(), smooth.y() + along * normal.y(),
                      smooth.z() + along * normal.z()));
    c = CstCornerSums{};
  }
}

}  // namespace

void Solver::accumulate_cst_forces(const Vec3* x, Vec3* F, double* S) const {
  const double gf = settings.geometric_factor;
  cst_plan_.update(model_);
  const CstPlan& plan = cst_plan_;
  // The projected corners' sums, one per slot: zero between calls (every
  // slot is cleared after its projection).
  if (cst_corner_sums_.size() != plan.corner.size()) cst_corner_sums_.assign(plan.corner.size(), CstCornerSums{});
  const CornerSlots sums{plan.slot.data(), cst_corner_sums_.data()};
  const Cst* csts = model_.csts.awake_begin();  // awake only
  const std::uint32_t n_csts = std::uint32_t(model_.csts.awake_end() - csts);
  if (!elements_on_threads()) {
    cst_forces<false>(plan, csts, nullptr, n_csts, {}, x, gf, ModelSink{F, S}, sums);
    project_corners<false>(plan, nullptr, 0, {}, ModelSink{F, S}, sums);
    return;
  }
  // On threads: each adds into the particles it owns (ElementShares).
  const std::vector<ParticleId>& bound = element_bounds();
  if (!cst_shares_.current(plan.generation(), bound))
    cst_shares_.derive(plan.generation(), bound, n_csts, [&](std::uint32_t e, ParticleId* at) {
      at[0] = plan.i[e], at[1] = plan.j[e], at[2] = plan.k[e];
      return 3;
    });
  const ElementShares& sh = cst_shares_;
  workers_->run(unsigned(bound.size()) - 1, [&](unsigned t) {
    const Owned<true> own{bound[t], bound[t + 1]};
    cst_forces<true>(plan, csts, sh.items.data() + sh.begin[t], sh.begin[t + 1] - sh.begin[t], own, x, gf,
                     ModelSink{F, S}, sums);
    project_corners<true>(plan, nullptr, 0, own, ModelSink{F, S}, sums);
  });
}

// The fused step's triangles: the plan, and each chunk's share of the
// triangles and of the projected corners (those of its particles), brought
// up to date before the pass, since the pass runs on threads.
void Solver::prepare_cst_chunks() const {
  cst_plan_.update(model_);
  const BarChunks& B = bar_chunks();
  cst_chunks_.update(cst_plan_, B.shift, B.chunks.size());
}

namespace {
// Each thread's projected corners' sums of the chunk it is evaluating, a
// row per particle of the chunk, zero between chunks (each row is cleared
// once projected). A chunk's rows stay in the cache; the model's slots
// streamed from memory at 100K particles.
thread_local std::vector<CstCornerSums> chunk_corner_scratch;
}  // namespace

// A chunk's triangles into its sums, as the element pass adds them into F
// and S (per particle the model's order of its triangles, then its
// projected corner), each lane on its own.
void Solver::chunk_cst_sums(std::uint32_t chunk, const Vec3* x, ForceSum* sums) const {
  const std::uint32_t shift = bar_chunks_.shift;
  const ParticleId base = ParticleId(chunk) << shift;
  const Owned<true> own{base, base + (ParticleId(1) << shift)};
  const ChunkSink out{sums, base};
  const CstChunks& C = cst_chunks_;
  if (chunk_corner_scratch.size() < (std::size_t(1) << shift)) chunk_corner_scratch.resize(std::size_t(1) << shift);
  const CornerRows corner_sums{chunk_corner_scratch.data(), base};
  cst_forces<true>(cst_plan_, model_.csts.awake_begin(), C.triangles.data() + C.begin[chunk],
                   C.end[chunk] - C.begin[chunk], own, x, settings.geometric_factor, out, corner_sums);
  project_corners<true>(cst_plan_, C.corners.data() + C.corner_begin[chunk],
                        C.corner_end[chunk] - C.corner_begin[chunk], own, out, corner_sums);
}

}  // namespace tendril
