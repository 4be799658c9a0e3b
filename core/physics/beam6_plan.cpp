#include "physics/beam6_plan.hpp"

#include <algorithm>
#include <cstring>

#include "physics/element_forces.hpp"

namespace tendril {

template <class Each>
void Beam6Plan::columns(Beam6Plan& out, const Beam6Plan& in, Each each) {
  each(out.i, in.i), each(out.j, in.j);
  for (int c = 0; c < 4; ++c) each(out.end_i[c], in.end_i[c]), each(out.end_j[c], in.end_j[c]);
  each(out.L, in.L), each(out.EA, in.EA), each(out.prestress, in.prestress), each(out.k_static, in.k_static);
  each(out.kr, in.kr), each(out.cz, in.cz), each(out.cy, in.cy), each(out.torsion, in.torsion);
}

void Beam6Plan::derive(const Model& m) {
  const Beam6* beams = m.beam6s.awake_begin();
  const std::size_t n = m.beam6s.awake;
  elements.clear();
  columns(*this, *this, [n](auto& column, const auto&) { column.resize(n); });
  for (std::size_t e = 0; e < n; ++e) {
    const Beam6& b = beams[e];
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
  find_runs();
  model_ = &m;
  revision_ = m.revision;
  capacity_ = m.particles.capacity();
}

void Beam6Plan::derive(const Beam6Plan& from, const std::vector<std::uint32_t>& items) {
  elements.resize(items.size());
  for (std::size_t e = 0; e < items.size(); ++e) elements[e] = from.element(items[e]);
  columns(*this, from, [&](auto& out, const auto& in) {
    out.resize(items.size());
    for (std::size_t e = 0; e < items.size(); ++e) out[e] = in[items[e]];
  });
  find_runs();
  model_ = from.model_;
  revision_ = from.revision_;
  capacity_ = from.capacity_;
}

void Beam6Plan::find_runs() {
  const std::size_t n = i.size();
  same_constants_to.resize(n);
  same_ends_to.resize(n);
  // Bit for bit (memcmp): a -0 is not a +0, and a NaN equals its own bits.
  const auto same = [](const std::array<const double*, 8>& columns, std::size_t a) {
    for (const double* column : columns)
      if (std::memcmp(column + a, column + a + 1, sizeof(double)) != 0) return false;
    return true;
  };
  const std::array<const double*, 8> constants = constant_columns(), ends = end_columns();
  for (std::size_t e = n; e-- > 0;) {
    const bool last = e + 1 == n;
    same_constants_to[e] = !last && same(constants, e) ? same_constants_to[e + 1] : std::uint32_t(e + 1);
    same_ends_to[e] = !last && same(ends, e) ? same_ends_to[e + 1] : std::uint32_t(e + 1);
  }
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
