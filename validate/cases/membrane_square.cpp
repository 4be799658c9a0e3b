// Orthotropic CST analysis (thesis 3.2.8.2, eq. 3.37-3.39) of a flat 1 m
// square membrane, prestressed by n_x = 2 kN/m along the warp (x) and
// n_y = 1 kN/m along the weft, edges fixed, under p = 1 N/m^2 normal to it,
// against the linear membrane n_x w_xx + n_y w_yy = -p:
//   w(x, y) = sum over odd m, n of 16 p / (pi^2 m n (n_x (m pi)^2 + n_y (n pi)^2))
//             sin(m pi x) sin(n pi y),
// at the centre. The deflection (w ~ 5e-5 m) stretches the membrane by
// ~1e-8, so its stiffnesses (d ~ 1e5 N/m) change the stresses by ~1e-6 of
// the prestress: the reference is linear to that order.
#include <cmath>
#include <numbers>

#include "case.hpp"
#include "model/model.hpp"

namespace tendril::validate {

namespace {

constexpr double kNx = 2000, kNy = 1000, kP = 1;

double exact_centre() {
  const double pi = std::numbers::pi;
  double w = 0;
  for (int m = 1; m < 4000; m += 2)
    for (int n = 1; n < 4000; n += 2) {
      const double sign = (((m - 1) / 2 + (n - 1) / 2) % 2) ? -1.0 : 1.0;
      w += sign * 16 * kP / (pi * pi * m * n * (kNx * m * m * pi * pi + kNy * n * n * pi * pi));
    }
  return w;
}

Outcome run_square(const Setting& setting) {
  const int n = setting.segments;  // quads along a side, even: a particle at the centre
  const double h = 1.0 / n;
  Model m;
  std::vector<ParticleId> ps;
  for (int r = 0; r <= n; ++r)
    for (int c = 0; c <= n; ++c) {
      ps.push_back(m.add_particle(Vec3(c * h, r * h, 0)));
      if (r == 0 || c == 0 || r == n || c == n) m.set_lock(ps.back(), kLockTranslation);
      else m.set_load(ps.back(), Vec3(0, 0, -kP * h * h));
    }
  auto at = [&](int r, int c) { return ps[std::size_t(r) * (n + 1) + c]; };
  const BlockId patch = m.add_quad_grid(ps, n + 1, n + 1, Section{1e3, 0, 0, 0});
  std::vector<Model::Triangle> triangles;  // first side along x, the warp
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      triangles.push_back({at(r, c), at(r, c + 1), at(r + 1, c + 1)});
      triangles.push_back({at(r + 1, c + 1), at(r + 1, c), at(r, c)});
    }
  Membrane fabric;
  fabric.mode = Membrane::Analysis;
  fabric.sigma_warp = kNx;
  fabric.sigma_weft = kNy;
  fabric.dxx = 5e5;
  fabric.dyy = 3e5;
  fabric.dxy = fabric.dyx = 6e4;
  fabric.G = 1e4;
  m.set_patch_formulation(patch, fabric, triangles);

  Solver solver(m);
  solver.settings = setting.solver;
  // 1e-8 N against 4e-3 N of load per particle at n = 16 and ~1e4 N/m of
  // stiffness: a displacement error of ~1e-12 m against 5e-5 m.
  Outcome out = relax(solver, 1e-8, 200'000);
  out.error = relative_error(-m.particles.position[at(n / 2, n / 2)].z(), exact_centre());
  return out;
}

}  // namespace

Case membrane_square_case() {
  Case c;
  c.name = "membrane_square";
  c.reference = "orthotropic CST, prestressed 1 m square under 1 N/m^2: linear membrane (double Fourier series), centre";
  c.resolution = "quads along a side";
  c.formulations = {"cst"};
  c.segments = {8, 16, 32};
  c.quick_segments = {8, 16};
  c.defaults.formulation = "cst";
  c.defaults.segments = 16;
  c.tolerance = 0.005;
  c.run = run_square;
  return c;
}

}  // namespace tendril::validate
