#include "physics/cst_chunks.hpp"

#include <algorithm>

#include "physics/bar_chunks.hpp"
#include "physics/chunk_items.hpp"

namespace tendril {

namespace {

// The distinct chunks of a triangle's corners, ascending.
int chunks_of(ParticleId a, ParticleId b, ParticleId c, std::uint32_t shift, std::uint32_t (&out)[3]) {
  std::uint32_t x = a >> shift, y = b >> shift, z = c >> shift;
  if (x > y) std::swap(x, y);
  if (y > z) std::swap(y, z);
  if (x > y) std::swap(x, y);
  int n = 0;
  out[n++] = x;
  if (y != x) out[n++] = y;
  if (z != y) out[n++] = z;
  return n;
}

// Lays out per chunk `count[c]` entries and their room, starting each
// chunk's list empty (`end` = `begin`).
void lay_out(const std::vector<std::uint32_t>& count, std::vector<std::uint32_t>& begin,
             std::vector<std::uint32_t>& end, std::vector<std::uint32_t>& limit, std::vector<std::uint32_t>& items) {
  begin.resize(count.size()), end.resize(count.size()), limit.resize(count.size());
  std::uint32_t at = 0;
  for (std::size_t c = 0; c < count.size(); ++c) {
    begin[c] = end[c] = at;
    at += count[c] + BarChunks::room(count[c]);
    limit[c] = at;
  }
  items.assign(at, kNone);
}

}  // namespace

void CstChunks::update(const CstPlan& plan, std::uint32_t shift, std::size_t n_chunks) {
  if (derivations > 0 && shift == shift_ && begin.size() <= n_chunks) {
    if (from_values_ == plan.values()) {
      while (begin.size() < n_chunks) append_empty_chunk();
      return;
    }
    if (from_values_ == plan.patched_from() && patch(plan, n_chunks)) return;
  }
  derive(plan, shift, n_chunks);
}

void CstChunks::derive(const CstPlan& plan, std::uint32_t shift, std::size_t n_chunks) {
  shift_ = shift;
  const std::uint32_t n = std::uint32_t(plan.i.size());
  std::uint32_t at[3];
  std::vector<std::uint32_t> count(n_chunks, 0);
  for (std::uint32_t e = 0; e < n; ++e)
    for (int k = chunks_of(plan.i[e], plan.j[e], plan.k[e], shift, at); k-- > 0;) ++count[at[k]];
  lay_out(count, begin, end, limit, triangles);
  for (std::uint32_t e = 0; e < n; ++e)
    for (int k = chunks_of(plan.i[e], plan.j[e], plan.k[e], shift, at); k-- > 0;) triangles[end[at[k]]++] = e;
  std::fill(count.begin(), count.end(), 0);
  for (ParticleId p : plan.corner) ++count[p >> shift];
  lay_out(count, corner_begin, corner_end, corner_limit, corners);
  for (std::uint32_t s = 0; s < plan.corner.size(); ++s) corners[corner_end[plan.corner[s] >> shift]++] = s;
  slots_ = std::uint32_t(plan.corner.size());
  from_values_ = plan.values();
  ++derivations;
}

bool CstChunks::patch(const CstPlan& plan, std::size_t n_chunks) {
  while (begin.size() < n_chunks) append_empty_chunk();
  const std::vector<std::uint32_t>& touched = plan.patched();
  const std::vector<ParticleId>& old_ends = plan.patched_ends();
  const std::size_t now = plan.i.size();
  affected_.clear();
  std::uint32_t at[3];
  for (std::size_t t = 0; t < touched.size(); ++t) {
    const std::uint32_t e = touched[t];
    if (old_ends[3 * t] != kNone) {
      const int k = chunks_of(old_ends[3 * t], old_ends[3 * t + 1], old_ends[3 * t + 2], shift_, at);
      affected_.insert(affected_.end(), at, at + k);
    }
    if (e < now) {
      const int k = chunks_of(plan.i[e], plan.j[e], plan.k[e], shift_, at);
      affected_.insert(affected_.end(), at, at + k);
    }
  }
  std::sort(affected_.begin(), affected_.end());
  affected_.erase(std::unique(affected_.begin(), affected_.end()), affected_.end());
  for (std::uint32_t c : affected_) {
    chunk_items(begin[c], end[c], [&](std::uint32_t place) { return triangles[place]; }, touched, now,
                [&](std::uint32_t e) {
                  return (plan.i[e] >> shift_) == c || (plan.j[e] >> shift_) == c || (plan.k[e] >> shift_) == c;
                },
                items_);
    if (items_.size() > limit[c] - begin[c]) return false;
    std::copy(items_.begin(), items_.end(), triangles.begin() + begin[c]);
    end[c] = begin[c] + std::uint32_t(items_.size());
    std::fill(triangles.begin() + end[c], triangles.begin() + limit[c], kNone);
  }
  for (; slots_ < plan.corner.size(); ++slots_) {  // new slots, after their chunk's
    const std::uint32_t c = plan.corner[slots_] >> shift_;
    if (corner_end[c] == corner_limit[c]) return false;
    corners[corner_end[c]++] = slots_;
  }
  from_values_ = plan.values();
  ++patches;
  return true;
}

void CstChunks::append_empty_chunk() {
  const std::uint32_t room = BarChunks::room(0);
  for (auto* list : {&triangles, &corners}) list->resize(list->size() + room, kNone);
  begin.push_back(std::uint32_t(triangles.size() - room)), end.push_back(begin.back()), limit.push_back(begin.back() + room);
  corner_begin.push_back(std::uint32_t(corners.size() - room)), corner_end.push_back(corner_begin.back());
  corner_limit.push_back(corner_begin.back() + room);
}

std::size_t CstChunks::triangle_count() const {
  std::size_t n = 0;
  for (std::size_t c = 0; c < begin.size(); ++c) n += end[c] - begin[c];
  return n;
}

std::size_t CstChunks::corner_count() const {
  std::size_t n = 0;
  for (std::size_t c = 0; c < corner_begin.size(); ++c) n += corner_end[c] - corner_begin[c];
  return n;
}

}  // namespace tendril
