#include "physics/cst_plan.hpp"

#include "physics/element_shares.hpp"

namespace tendril {

bool CstPlan::current(const Model& m) const {
  return model_ == &m && awake_ == m.csts.awake && m.csts.edits.clean_since(caught_up_);
}

void CstPlan::update(Model& m) {
  if (current(m)) return;
  const bool patchable = model_ == &m && awake_ == m.csts.awake && m.csts.edits.lists_since(caught_up_);
  if (!(patchable && patch(m))) derive(m);
  m.csts.edits.restart(m.revision);
  caught_up_ = m.revision;
}

bool CstPlan::put(const Cst& t, std::size_t e, bool check) {
  const Membrane& mb = t.membrane;
  const std::uint8_t along = mb.mode == Membrane::FormFinding ? t.interior : 0;
  if (check && (i[e] != t.i || j[e] != t.j || k[e] != t.k || along_normal[e] != along)) return false;
  i[e] = t.i, j[e] = t.j, k[e] = t.k;
  sigma_warp[e] = mb.sigma_warp, sigma_weft[e] = mb.sigma_weft;
  g_string[e] = 0.5 * (mb.sigma_warp + mb.sigma_weft);
  along_normal[e] = along;
  analysis[e] = mb.mode == Membrane::Analysis;
  return true;
}

// The awake triangles written since the last update, each in place when
// its slots stay; false (some entries written, the plan to be derived)
// otherwise.
bool CstPlan::patch(const Model& m) {
  if (!m.csts.edits.touched(awake_, awake_, touched_)) return false;
  const Cst* csts = m.csts.awake_begin();
  for (std::uint32_t e : touched_)
    if (e < awake_ && !put(csts[e], e, true)) return false;
  return true;
}

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
    put(t, e, false);
    if (!along_normal[e]) continue;
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
  awake_ = n;
  generation_ = new_stamp();
}

}  // namespace tendril
