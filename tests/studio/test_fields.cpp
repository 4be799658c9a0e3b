// The studio's colour maps against hand calculations, and its frames.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "fields.hpp"
#include "frames.hpp"

using namespace tendril;
using namespace tendril::studio;

namespace {
std::vector<float> field(const Model& m, const char* name) { return find_field(name)->values(m, topology_of(m)); }
}  // namespace

TEST_CASE("axial force of a stretched and of a slack cable: N = EA (L - L0) / L0, slack 0") {
  Model m;
  const ParticleId a = m.add_particle({0, 0, 0}), b = m.add_particle({1.1, 0, 0}), c = m.add_particle({1.1, 0.5, 0});
  Section s;
  s.EA = 1000;
  m.add_cable(a, b, s, 1.0);  // 10 % longer than at rest: 100 N
  m.add_cable(b, c, s, 0.8);  // 0.5 m of 0.8: slack
  const std::vector<float> n = field(m, "axial force");
  REQUIRE(n.size() == 2);
  CHECK(n[0] == doctest::Approx(100.0).epsilon(1e-6));
  CHECK(n[1] == 0.f);
  CHECK(field(m, "strain")[0] == doctest::Approx(0.1).epsilon(1e-6));
  CHECK(std::isnan(field(m, "bending moment")[0]));  // a cable has none
}

TEST_CASE("bending moment of a ring of radius R: EI / R within 0.2 % at 64 segments") {
  Model m;
  const int n = 64;
  const double R = 2.5, EI = 300;
  std::vector<ParticleId> ps;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * k / n;
    ps.push_back(m.add_particle({R * std::cos(t), R * std::sin(t), 0}));
  }
  Section s;
  s.EA = 1e6;
  s.EI = EI;
  m.add_beam(ps, s, true);
  const std::vector<float> M = field(m, "bending moment");
  REQUIRE(M.size() == std::size_t(n));
  // The discrete curvature 2 tan(theta/2) / l of a regular 64-gon is
  // 1 / (R cos(pi / n)): 0.12 % above 1 / R.
  for (float v : M) CHECK(v == doctest::Approx(EI / R).epsilon(2e-3));
}

TEST_CASE("a frame carries the positions in the topology's particle order as float32") {
  Model m;
  Solver solver(m);
  const ParticleId a = m.add_particle({1, 2, 3}), b = m.add_particle({4, 5, 6});
  m.delete_particle(m.add_particle({9, 9, 9}));
  Section s;
  s.EA = 10;
  m.add_cable(a, b, s);
  const Topology t = topology_of(m);
  CHECK(t.ids == std::vector<ParticleId>{a, b});
  const std::string f = encode_frame(m, solver, t, {});
  REQUIRE(f.size() == 40 + 6 * 4);
  std::uint32_t magic = 0;
  float xyz[6];
  std::memcpy(&magic, f.data(), 4);
  std::memcpy(xyz, f.data() + 40, sizeof xyz);
  CHECK(magic == kFrame);
  for (int k = 0; k < 6; ++k) CHECK(xyz[k] == float(k + 1));
}
