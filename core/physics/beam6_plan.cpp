#include "physics/beam6_plan.hpp"

#include <algorithm>
#include <cstring>

#include "physics/element_forces.hpp"
#include "physics/element_shares.hpp"

namespace tendril {

template <class Each>
void Beam6Plan::columns(Beam6Plan& out, const Beam6Plan& in, Each each) {
  each(out.i, in.i), each(out.j, in.j);
  for (int c = 0; c < 4; ++c) each(out.end_i[c], in.end_i[c]), each(out.end_j[c], in.end_j[c]);
  each(out.L, in.L), each(out.EA, in.EA), each(out.prestress, in.prestress), each(out.k_static, in.k_static);
  each(out.kr, in.kr), each(out.cz, in.cz), each(out.cy, in.cy), each(out.torsion, in.torsion);
}

bool Beam6Plan::current(const Model& m) const {
  return model_ == &m && awake_ == m.beam6s.awake && m.beam6s.edits.clean_since(caught_up_);
}

void Beam6Plan::update(Model& m) {
  if (current(m)) return;
  const bool patchable = model_ == &m && m.beam6s.edits.lists_since(caught_up_);
  if (!(patchable && patch(m))) derive(m);
  m.beam6s.edits.restart(m.revision);
  caught_up_ = m.revision;
}

void Beam6Plan::put(const Beam6& b, std::uint32_t e) {
  const double l = b.rest_length, EI = b.EIy < b.EIz ? b.EIz : b.EIy;
  i[e] = b.i, j[e] = b.j;
  for (int c = 0; c < 4; ++c) end_i[c][e] = b.end_i.coeffs()[c], end_j[c][e] = b.end_j.coeffs()[c];
  L[e] = l, EA[e] = b.EA, prestress[e] = b.prestress;
  // As beam6_ends writes them (std::max(a, b) is a < b ? b : a).
  const double k_axial = b.EA / l, k_bending = kBendingMassFactor * 12 * EI / (l * l * l);
  k_static[e] = k_axial < k_bending ? k_bending : k_axial;
  const double kr_torsion = b.GJ / l, kr_bending = kBendingMassFactor * 4 * EI / l;
  kr[e] = kr_torsion < kr_bending ? kr_bending : kr_torsion;
  cz[e] = 2 * b.EIz / l, cy[e] = 2 * b.EIy / l;
  torsion[e] = b.GJ / l;
}

// The awake elements written, woken or put to sleep since the last
// update, in place (from the last, so that each entry's runs are marked
// after those of the entries behind it); the generation moves when an
// element's ends or the number of elements did.
bool Beam6Plan::patch(const Model& m) {
  const Beam6* beams = m.beam6s.awake_begin();
  const std::size_t now = m.beam6s.awake;
  if (!m.beam6s.edits.touched(awake_, now, patched_)) return false;
  bool moved = now != awake_;
  for (std::uint32_t e : patched_)
    if (e < now && e < awake_) moved |= beams[e].i != i[e] || beams[e].j != j[e];
  if (now != awake_) {
    columns(*this, *this, [now](auto& column, const auto&) { column.resize(now); });
    same_constants_to.resize(now), same_ends_to.resize(now);
    for (std::size_t e = awake_; e < now; ++e) same_constants_to[e] = same_ends_to[e] = std::uint32_t(e + 1);
  }
  // The last entry marks its runs afresh when the plan shrank (they ended past it).
  std::vector<std::uint32_t>& marked = marked_;
  marked.clear();
  for (std::uint32_t e : patched_)
    if (e < now) marked.push_back(e);
  if (now < awake_ && now > 0 && (marked.empty() || marked.back() != now - 1)) marked.push_back(std::uint32_t(now - 1));
  for (std::size_t n = marked.size(); n-- > 0;) {
    if (marked[n] < now) put(beams[marked[n]], marked[n]);
    mark_runs_at(marked[n]);
  }
  awake_ = now;
  if (moved) generation_ = new_stamp();
  patched_from_ = values_;
  values_ = new_stamp();
  return true;
}

void Beam6Plan::derive(const Model& m) {
  const Beam6* beams = m.beam6s.awake_begin();
  const std::size_t n = m.beam6s.awake;
  elements.clear();
  columns(*this, *this, [n](auto& column, const auto&) { column.resize(n); });
  for (std::size_t e = 0; e < n; ++e) put(beams[e], std::uint32_t(e));
  find_runs();
  model_ = &m;
  awake_ = n;
  generation_ = values_ = new_stamp();
  patched_from_ = ~std::uint64_t(0);
}

void Beam6Plan::derive(const Beam6Plan& from, const std::vector<std::uint32_t>& items) {
  elements.resize(items.size());
  for (std::size_t e = 0; e < items.size(); ++e) elements[e] = from.element(items[e]);
  columns(*this, from, [&](auto& out, const auto& in) {
    out.resize(items.size());
    for (std::size_t e = 0; e < items.size(); ++e) out[e] = in[items[e]];
  });
  find_runs();
  places_.assign(2 * from.i.size(), kNone);
  for (std::size_t e = 0; e < items.size(); ++e)
    places_[2 * items[e] + (places_[2 * items[e]] == kNone ? 0 : 1)] = std::uint32_t(e);
  model_ = from.model_;
  from_generation_ = from.generation_;
  from_values_ = from.values_;
}

bool Beam6Plan::follow(const Beam6Plan& from) {
  if (from_generation_ != from.generation_) return false;
  if (from_values_ == from.values_) return true;
  if (from_values_ != from.patched_from_) return false;
  std::vector<std::uint32_t>& at = patched_;  // the places of the elements `from` wrote
  at.clear();
  for (std::uint32_t e : from.patched_)
    for (int c = 0; c < 2; ++c)
      if (places_[2 * e + c] != kNone) at.push_back(places_[2 * e + c]);
  std::sort(at.begin(), at.end());
  for (std::size_t n = at.size(); n-- > 0;) {  // from the last, as patch
    const std::uint32_t place = at[n];
    columns(*this, from, [&](auto& out, const auto& in) { out[place] = in[elements[place]]; });
    mark_runs_at(place);
  }
  from_values_ = from.values_;
  return true;
}

namespace {

// Whether entries a and a + 1 hold the same bits in every column (memcmp:
// a -0 is not a +0, and a NaN equals its own bits).
bool same_as_next(const std::array<const double*, 8>& columns, std::size_t a) {
  for (const double* column : columns)
    if (std::memcmp(column + a, column + a + 1, sizeof(double)) != 0) return false;
  return true;
}

// Entry e's run end again after its columns changed, the entries after it
// marked already. Before e - 1 whether an entry is like the next did not
// change: those in a run (to[x] != x + 1) take their successor's end, up
// to the first that keeps its own.
void mark_run_at(const std::array<const double*, 8>& columns, std::vector<std::uint32_t>& to, std::uint32_t e) {
  const std::size_t n = to.size();
  to[e] = e + 1 < n && same_as_next(columns, e) ? to[e + 1] : e + 1;
  if (e == 0) return;
  std::uint32_t x = e - 1;
  const std::uint32_t before = same_as_next(columns, x) ? to[e] : e;
  if (to[x] == before) return;
  to[x] = before;
  while (x-- > 0 && to[x] != x + 1 && to[x] != to[x + 1]) to[x] = to[x + 1];
}

}  // namespace

void Beam6Plan::find_runs() {
  same_constants_to.resize(i.size());
  same_ends_to.resize(i.size());
  find_runs(0, std::uint32_t(i.size()));
}

void Beam6Plan::find_runs(std::uint32_t first, std::uint32_t last) {
  const std::array<const double*, 8> constants = constant_columns(), ends = end_columns();
  for (std::uint32_t e = last; e-- > first;) {
    const bool at_last = e + 1 == last;
    same_constants_to[e] = !at_last && same_as_next(constants, e) ? same_constants_to[e + 1] : e + 1;
    same_ends_to[e] = !at_last && same_as_next(ends, e) ? same_ends_to[e + 1] : e + 1;
  }
}

void Beam6Plan::resize(std::size_t n) {
  const std::size_t before = i.size();
  columns(*this, *this, [n](auto& column, const auto&) { column.resize(n); });
  elements.resize(n, kNone);
  same_constants_to.resize(n), same_ends_to.resize(n);
  for (std::size_t e = before; e < n; ++e) same_constants_to[e] = same_ends_to[e] = std::uint32_t(e + 1);
}

void Beam6Plan::copy_entry(const Beam6Plan& from, std::uint32_t e, std::uint32_t at) {
  columns(*this, from, [&](auto& out, const auto& in) { out[at] = in[e]; });
  elements[at] = from.element(e);
}

void Beam6Plan::mark_runs_at(std::uint32_t e) {
  mark_run_at(constant_columns(), same_constants_to, e);
  mark_run_at(end_columns(), same_ends_to, e);
}

double Beam6Plan::step_bytes(std::uint32_t first, std::uint32_t count) const {
  double bytes = 0;
  for (std::uint32_t e0 = first; e0 < first + count; e0 += kBeam6Block) {
    const std::uint32_t n = std::min(kBeam6Block, first + count - e0);
    bytes += n * (4 + 4) + (same_ends(e0, n) ? 1 : n) * 64 + (same_constants(e0, n) ? 1 : n) * 64;
  }
  return bytes;
}

}  // namespace tendril
