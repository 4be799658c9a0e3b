#include "physics/cst_plan.hpp"

namespace tendril {

void CstPlan::derive(const Model& m) {
  const Cst* csts = m.csts.awake_begin();
  const std::size_t n = m.csts.awake;
  i.resize(n), j.resize(n), k.resize(n);
  sigma_warp.resize(n), sigma_weft.resize(n), g_string.resize(n);
  along_normal.resize(n);
  slot.assign(3 * n, kNoSlot);
  analysis.resize(n);
  corner.clear();
  std::vector<std::uint32_t> slot_of(m.particles.capacity(), kNoSlot);
  for (std::size_t e = 0; e < n; ++e) {
    const Cst& t = csts[e];
    const Membrane& mb = t.membrane;
    i[e] = t.i, j[e] = t.j, k[e] = t.k;
    sigma_warp[e] = mb.sigma_warp, sigma_weft[e] = mb.sigma_weft;
    g_string[e] = 0.5 * (mb.sigma_warp + mb.sigma_weft);
    along_normal[e] = mb.mode == Membrane::FormFinding ? t.interior : 0;
    analysis[e] = mb.mode == Membrane::Analysis;
    if (mb.mode != Membrane::FormFinding || !t.interior) continue;
    // Every corner of an interior form-finding triangle is projected (with
    // its pull summed in its slot only where its bit is set).
    const ParticleId corners[3] = {t.i, t.j, t.k};
    for (int c = 0; c < 3; ++c) {
      std::uint32_t& s = slot_of[corners[c]];
      if (s == kNoSlot) {
        s = std::uint32_t(corner.size());
        corner.push_back(corners[c]);
      }
      if (along_normal[e] >> c & 1) slot[3 * e + c] = s;
    }
  }
  model_ = &m;
  revision_ = m.revision;
  capacity_ = m.particles.capacity();
}

}  // namespace tendril
