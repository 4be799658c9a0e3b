#include "physics/cst_plan.hpp"

#include <algorithm>

#include "physics/element_shares.hpp"

namespace tendril {

bool CstPlan::current(const Model& m) const {
  return model_ == &m && i.size() == m.csts.awake && m.csts.edits.clean_since(caught_up_);
}

void CstPlan::update(Model& m) {
  if (current(m)) return;
  const bool patchable = model_ == &m && m.csts.edits.lists_since(caught_up_);
  if (!(patchable && patch(m))) derive(m);
  m.csts.edits.restart(m.revision);
  caught_up_ = m.revision;
}

void CstPlan::put(const Cst& t, std::size_t e) {
  const Membrane& mb = t.membrane;
  i[e] = t.i, j[e] = t.j, k[e] = t.k;
  sigma_warp[e] = mb.sigma_warp, sigma_weft[e] = mb.sigma_weft;
  g_string[e] = 0.5 * (mb.sigma_warp + mb.sigma_weft);
  along_normal[e] = mb.mode == Membrane::FormFinding ? t.interior : 0;
  analysis[e] = mb.mode == Membrane::Analysis;
}

// Every corner of an interior form-finding triangle has a slot (its pull
// summed there only where its bit is set); a corner seen first takes the
// next one.
void CstPlan::add_slots(std::size_t e, int way) {
  if (!along_normal[e]) return;
  const ParticleId corners[3] = {i[e], j[e], k[e]};
  for (int c = 0; c < 3; ++c) {
    std::uint32_t& s = slot_of_[corners[c]];
    if (way < 0) {
      unused_ += --users_[s] == 0;
      slot[3 * e + c] = kNoSlot;
      continue;
    }
    if (s == kNoSlot) {
      s = std::uint32_t(corner.size());
      corner.push_back(corners[c]);
      users_.push_back(0);
      ++unused_;
    }
    unused_ -= users_[s]++ == 0;
    slot[3 * e + c] = along_normal[e] >> c & 1 ? s : kNoSlot;
  }
}

// The awake triangles written, woken or put to sleep since the last
// update, each in place: its old corners leave their slots, its new ones
// join theirs. False (the plan to be derived) when the border moved too far
// for the edit list or unused slots grew to more than half.
bool CstPlan::patch(const Model& m) {
  const std::size_t had = i.size(), now = m.csts.awake;
  if (!m.csts.edits.touched(had, now, touched_)) return false;
  touched_.erase(std::lower_bound(touched_.begin(), touched_.end(), std::uint32_t(std::max(had, now))),
                 touched_.end());  // dormant both before and now
  slot_of_.resize(m.particles.capacity(), kNoSlot);
  const std::size_t slots = corner.size();
  old_ends_.assign(3 * touched_.size(), kNone);
  for (std::size_t t = 0; t < touched_.size(); ++t) {
    const std::uint32_t e = touched_[t];
    if (e >= had) break;
    old_ends_[3 * t] = i[e], old_ends_[3 * t + 1] = j[e], old_ends_[3 * t + 2] = k[e];
    add_slots(e, -1);
  }
  i.resize(now), j.resize(now), k.resize(now);
  sigma_warp.resize(now), sigma_weft.resize(now), g_string.resize(now);
  along_normal.resize(now, 0), analysis.resize(now);
  slot.resize(3 * now, kNoSlot);
  const Cst* csts = m.csts.awake_begin();
  bool moved = had != now;
  for (std::size_t t = 0; t < touched_.size(); ++t) {
    const std::uint32_t e = touched_[t];
    if (e >= now) break;
    put(csts[e], e);
    add_slots(e, +1);
    moved |= old_ends_[3 * t] != i[e] || old_ends_[3 * t + 1] != j[e] || old_ends_[3 * t + 2] != k[e];
  }
  if (unused_ > 64 && 2 * unused_ > corner.size()) return false;
  moved |= corner.size() != slots;
  patched_from_ = values_;
  values_ = new_stamp();
  if (moved) generation_ = values_;
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
  users_.clear();
  unused_ = 0;
  slot_of_.assign(m.particles.capacity(), kNoSlot);
  for (std::size_t e = 0; e < n; ++e) {
    put(csts[e], e);
    add_slots(e, +1);
  }
  model_ = &m;
  generation_ = values_ = new_stamp();
  patched_from_ = ~std::uint64_t(0);
  touched_.clear();
  old_ends_.clear();
}

}  // namespace tendril
