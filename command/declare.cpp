#include "command/declare.hpp"

namespace tendril::command {

std::vector<Param> section_params() {
  return {{"EA", Type::Number, "axial stiffness [N]", {0, kInf}},
          {"EI", Type::Number, "bending stiffness [N m^2] (beams; 0 for cables and patches)", {0, kInf}},
          {"prestress", Type::Number, "geometric tension T [N]"},
          {"line_mass", Type::Number, "physical mass per length [kg/m]", {0, kMaxLineMass}}};
}

std::vector<Param> with_section(std::vector<Param> before, std::vector<Param> after) {
  for (Param& p : section_params()) before.push_back(std::move(p));
  for (Param& p : after) before.push_back(std::move(p));
  return before;
}

Section section_at(const Args& a, std::size_t first) {
  Section s;
  s.EA = a[first].number;
  s.EI = a[first + 1].number;
  s.prestress = a[first + 2].number;
  s.line_mass = a[first + 3].number;
  return s;
}

Result nothing() { return {}; }

Result particle_result(ParticleId p) {
  Result r;
  r.kind = Returns::Particle;
  r.ids = {p};
  return r;
}

Result block_result(BlockId b) {
  Result r;
  r.kind = Returns::Block;
  r.ids = {b};
  return r;
}

Result number_result(double x) {
  Result r;
  r.kind = Returns::Number;
  r.number = x;
  return r;
}

Result vector_result(const Vec3& x) {
  Result r;
  r.kind = Returns::Vector;
  r.vector = x;
  return r;
}

}  // namespace tendril::command
