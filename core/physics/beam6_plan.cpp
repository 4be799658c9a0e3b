#include "physics/beam6_plan.hpp"

#include "physics/element_forces.hpp"

namespace tendril {

void Beam6Plan::derive(const Model& m) {
  const Beam6* beams = m.beam6s.awake_begin();
  const std::size_t n = m.beam6s.awake;
  for (auto* v : {&i, &j}) v->resize(n);
  for (auto* v : {&end_i, &end_j}) v->resize(n);
  for (auto* v : {&L, &EA, &prestress, &k_static, &kr, &cz, &cy, &torsion}) v->resize(n);
  for (std::size_t e = 0; e < n; ++e) {
    const Beam6& b = beams[e];
    const double l = b.rest_length, EI = b.EIy < b.EIz ? b.EIz : b.EIy;
    i[e] = b.i, j[e] = b.j;
    end_i[e] = b.end_i, end_j[e] = b.end_j;
    L[e] = l, EA[e] = b.EA, prestress[e] = b.prestress;
    // As beam6_ends writes them (std::max(a, b) is a < b ? b : a).
    const double k_axial = b.EA / l, k_bending = kBendingMassFactor * 12 * EI / (l * l * l);
    k_static[e] = k_axial < k_bending ? k_bending : k_axial;
    const double kr_torsion = b.GJ / l, kr_bending = kBendingMassFactor * 4 * EI / l;
    kr[e] = kr_torsion < kr_bending ? kr_bending : kr_torsion;
    cz[e] = 2 * b.EIz / l, cy[e] = 2 * b.EIy / l;
    torsion[e] = b.GJ / l;
  }
  model_ = &m;
  revision_ = m.revision;
  capacity_ = m.particles.capacity();
}

}  // namespace tendril
