#pragma once
// A small table of materials for conceptual design (docs/lua-api.md lists
// them with their sources): indicative values of a class, not design
// values of a product. Members: moduli [Pa], density [kg/m^3] and a
// characteristic strength [Pa] for utilisation. Fabrics: per unit width,
// as tendril's membranes are (thesis 3.2.8.2): stiffnesses and strengths
// [N/m], surface mass [kg/m^2].
#include <string>
#include <vector>

namespace tendril {

struct Material {
  std::string name;
  double E = 0, G = 0, density = 0, strength = 0;
  std::string source;
};

struct Fabric {
  std::string name;
  double Et_warp = 0, Et_weft = 0, nu = 0, G = 0;  // [N/m], nu: warp-weft Poisson's ratio
  double strength_warp = 0, strength_weft = 0;     // [N/m]
  double weight = 0;                               // [kg/m^2]
  std::string source;
};

const std::vector<Material>& materials();
const std::vector<Fabric>& fabrics();
// nullptr when there is no such name.
const Material* find_material(const std::string& name);
const Fabric* find_fabric(const std::string& name);

}  // namespace tendril
