#include "model/materials.hpp"

namespace tendril {

const std::vector<Material>& materials() {
  static const std::vector<Material> table = {
      {"steel", 210e9, 81e9, 7850, 355e6,
       "structural steel S355: E, G from EN 1993-1-1 3.2.6, density EN 1991-1-1 annex A, yield strength EN 10025-2"},
      {"timber", 11e9, 0.69e9, 420, 24e6,
       "softwood C24, EN 338: E0,mean, Gmean, mean density, characteristic bending strength fm,k"},
      {"gfrp", 25e9, 4e9, 1900, 400e6,
       "pultruded E-glass rod, indicative: E 25 GPa as in the thesis' case studies (5.5.2, 6.2); G, density and a "
       "bending strength typical of such rods' data sheets"},
      {"cfrp", 130e9, 5e9, 1550, 1200e6,
       "pultruded standard-modulus carbon rod or strip, indicative values of data sheets"},
      {"bamboo", 12e9, 0.8e9, 700, 80e6,
       "bamboo culm (e.g. Moso), indicative: values of the range reported from ISO 22157 tests"},
  };
  return table;
}

const std::vector<Fabric>& fabrics() {
  static const std::vector<Fabric> table = {
      {"pvc_polyester", 800e3, 600e3, 0.3, 30e3, 84e3, 80e3, 1.05,
       "PVC-coated polyester, type II, indicative: strengths of the class (4200 / 4000 N per 5 cm), stiffnesses "
       "of biaxial tests; use your fabric's data"},
      {"ptfe_glass", 1400e3, 1100e3, 0.3, 50e3, 140e3, 120e3, 1.25,
       "PTFE-coated glass fibre, type III, indicative: strengths of the class (7000 / 6000 N per 5 cm), "
       "stiffnesses of biaxial tests; use your fabric's data"},
  };
  return table;
}

const Material* find_material(const std::string& name) {
  for (const Material& m : materials())
    if (m.name == name) return &m;
  return nullptr;
}

const Fabric* find_fabric(const std::string& name) {
  for (const Fabric& f : fabrics())
    if (f.name == name) return &f;
  return nullptr;
}

}  // namespace tendril
