// The constant strain triangle (thesis 3.2.8.2, eq. 3.36-3.40) against
// references: an equal-stress membrane between two rings becomes the
// catenoid; an orthotropic prestressed flat square under a small normal load
// deflects like the linear membrane n_x w_xx + n_y w_yy = -p; a homogeneous
// strain gives the stresses of eq. 3.37-3.39 on a cut; each corner's pull
// is half the stress tensor applied to its opposite side's outward normal;
// a triangle collapsing to a line stays finite.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "cst_scenes.hpp"
#include "paving.hpp"
#include "quality.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using namespace tendril::test;

namespace {

constexpr double kPi = std::numbers::pi;

Membrane form(double warp, double weft) {
  Membrane m;
  m.mode = Membrane::FormFinding;
  m.sigma_warp = warp;
  m.sigma_weft = weft;
  return m;
}

// Linear prestressed membrane on a x b with fixed edges under uniform p:
// w = sum over odd m, n of 16 p / (pi^2 m n (n_x (m pi/a)^2 + n_y (n pi/b)^2))
//     sin(m pi x/a) sin(n pi y/b).
double membrane_deflection(double p, double nx, double ny, double a, double b, double x, double y) {
  double w = 0;
  for (int m = 1; m < 2000; m += 2)
    for (int n = 1; n < 2000; n += 2)
      w += 16 * p / (kPi * kPi * m * n * (nx * std::pow(m * kPi / a, 2) + ny * std::pow(n * kPi / b, 2))) *
           std::sin(m * kPi * x / a) * std::sin(n * kPi * y / b);
  return w;
}

}  // namespace

TEST_CASE("cst: an equal-stress membrane between two rings is the catenoid") {
  const double exact = catenoid_waist();
  CHECK(exact == doctest::Approx(0.84834).epsilon(1e-5));
  Tube tube(48, 16);
  tube.m.set_patch_formulation(tube.patch, form(1, 1), triangles_of(tube.m, tube.patch, Vec3(0, 0, 1)));
  REQUIRE(tube.m.check() == "");
  REQUIRE(tube.m.csts.size() == 2u * 48 * 16);
  Solver solver(tube.m);
  const RunResult r = solver.run(1e-7, 200000);
  const double waist = tube.radius(8);
  MESSAGE("catenoid 48 x 16: waist " << waist << " (exact " << exact << ", error "
                                     << 100 * std::abs(waist / exact - 1) << " %) after " << r.steps << " steps");
  CHECK(r.converged);
  CHECK(std::abs(waist / exact - 1) < 0.01);
  // Every ring is a circle about the axis at the catenoid's height.
  for (int ring = 1; ring < 16; ++ring) {
    const double z = -0.5 + ring / 16.0;
    CHECK(std::abs(tube.radius(ring) / (exact * std::cosh(z / exact)) - 1) < 0.01);
  }
}

TEST_CASE("cst: form-finding on a paved patch keeps its mesh (no drift in the surface)") {
  // A paved disc (irregular: valence 3 and 5 vertices, hence seams) in a
  // wavy ring. Prescribed stresses have no in-plane stiffness; without the
  // normal projection of interior vertices the triangles collapsed
  // (minimum quad angle 1e-7 degrees, folded quads, no convergence).
  for (double warp : {1.0, 3.0}) {
    CAPTURE(warp);
    Model m;
    std::vector<ParticleId> ring;
    for (int i = 0; i < 32; ++i) {
      const double a = 2 * kPi * i / 32;
      ring.push_back(m.add_particle(Vec3(5 * std::cos(a), 5 * std::sin(a), (i % 2) * 0.8)));
      m.set_lock(ring.back(), kLockTranslation);
    }
    const BlockId disc = meshing::patch_by_paving(m, ring, Section{1e3, 0, 0, 0}).patch;
    meshing::ClassifyOptions o;
    o.allow_seams = true;
    std::vector<Model::Triangle> tris;
    for (const auto& t : meshing::cst_triangulation(m, disc, o).triangles) tris.push_back({t[0], t[1], t[2]});
    const double angle_before = meshing::quality(m, disc).angle_min;
    m.set_patch_formulation(disc, form(warp, 1), tris);
    Solver solver(m);
    const RunResult r = solver.run(1e-6, 20000);
    const meshing::Quality q = meshing::quality(m, disc);
    MESSAGE("paved disc, stresses " << warp << " / 1: " << r.steps << " steps, quad angles >= " << q.angle_min
                                    << " deg (paved: " << angle_before << "), scaled Jacobian >= " << q.jacobian_min);
    CHECK(r.converged);
    CHECK(q.angle_min > 30);
    CHECK(q.jacobian_min > 0.4);
    CHECK(m.check() == "");
  }
}

TEST_CASE("cst: an orthotropic prestressed flat square under a small normal load") {
  // 1 m x 1 m, warp along x with n_x = 2 kN/m, weft n_y = 1 kN/m of
  // prestress, fixed edges, p = 1 N/m^2 lumped on the particles. The
  // deflection (w / a ~ 1e-4) stretches the membrane by ~1e-8, so the elastic
  // stiffnesses change the stresses by ~1e-5 of the prestress: linear.
  const int n = 16;
  const double side = 1, p = 1, nx = 2000, ny = 1000;
  FlatSquare sq(n, side);
  Membrane mem;
  mem.mode = Membrane::Analysis;
  mem.sigma_warp = nx;
  mem.sigma_weft = ny;
  mem.dxx = 5e5;
  mem.dyy = 3e5;
  mem.dxy = mem.dyx = 6e4;
  mem.G = 1e4;
  sq.m.set_patch_formulation(sq.patch, mem, triangles_of(sq.m, sq.patch, Vec3(1, 0, 0)));
  REQUIRE(sq.m.check() == "");
  const double h = side / n;
  for (int r = 1; r < n; ++r)
    for (int c = 1; c < n; ++c) sq.m.set_load(sq.at(r, c), Vec3(0, 0, -p * h * h));
  Solver solver(sq.m);
  const RunResult run = solver.run(1e-9, 400000);
  const double w = -sq.m.particles.position[sq.at(n / 2, n / 2)].z();
  const double exact = membrane_deflection(p, nx, ny, side, side, 0.5, 0.5);
  MESSAGE("orthotropic square 16 x 16: centre deflection " << w << " m, linear membrane " << exact << " m, error "
                                                           << 100 * std::abs(w / exact - 1) << " % after " << run.steps
                                                           << " steps");
  CHECK(run.converged);
  CHECK(std::abs(w / exact - 1) < 0.01);
  // Orthotropy shows in the shape: the warp (x) carries more prestress, so
  // across it the membrane spans like strings along x: a quarter in from the
  // edge, the sag is less on the x axis through the centre than on the y axis.
  const double wx = -sq.m.particles.position[sq.at(n / 2, n / 4)].z();  // x = 1/4, y = 1/2
  const double wy = -sq.m.particles.position[sq.at(n / 4, n / 2)].z();  // x = 1/2, y = 1/4
  const double ex = membrane_deflection(p, nx, ny, side, side, 0.25, 0.5);
  const double ey = membrane_deflection(p, nx, ny, side, side, 0.5, 0.25);
  MESSAGE("  at (1/4, 1/2): " << wx << " m against " << ex << " m (" << 100 * std::abs(wx / ex - 1)
                              << " %); at (1/2, 1/4): " << wy << " m against " << ey << " m ("
                              << 100 * std::abs(wy / ey - 1) << " %)");
  CHECK(ex < ey * 0.95);  // the reference tells the directions apart ...
  CHECK(std::abs(wx / ex - 1) < 0.01);  // ... and so does the CST
  CHECK(std::abs(wy / ey - 1) < 0.01);
}

TEST_CASE("cst: a homogeneous strain gives the stresses of eq. 3.37-3.39 on a cut") {
  // One unit quad (two triangles), analysis from the flat square, then the
  // affine map x' = (1 + ex) x + g y, y' = (1 + ey) y. The membrane pulls the
  // corners of the right edge with -sigma n' L' (its current normal times length).
  FlatSquare sq(1, 1.0);
  Membrane mem;
  mem.mode = Membrane::Analysis;
  mem.sigma_warp = 10;
  mem.sigma_weft = 4;
  mem.dxx = 1000;
  mem.dxy = 150;
  mem.dyx = 120;
  mem.dyy = 600;
  mem.G = 80;
  sq.m.set_patch_formulation(sq.patch, mem, triangles_of(sq.m, sq.patch, Vec3(1, 0, 0)));
  const double ex = 2e-3, ey = -1e-3, g = 1.5e-3;
  for (ParticleId q : sq.ps) {
    Vec3& x = sq.m.particles.position[q];
    x = Vec3((1 + ex) * x.x() + g * x.y(), (1 + ey) * x.y(), 0);
  }
  Solver solver(sq.m);
  solver.compute_forces();
  // Subtract what the boundary bars pull (they stay in CST mode).
  Vec3 bars = Vec3::Zero();
  Model& m = sq.m;
  for (const Bar& b : m.bars.items) {
    const Vec3 d = m.particles.position[b.j] - m.particles.position[b.i];
    const double T = b.prestress + b.EA / b.rest_length * (d.norm() - b.rest_length);
    for (ParticleId q : {sq.at(0, 1), sq.at(1, 1)}) {
      if (b.i == q) bars += T * d / d.norm();
      if (b.j == q) bars -= T * d / d.norm();
    }
  }
  const Vec3 membrane = m.particles.force[sq.at(0, 1)] + m.particles.force[sq.at(1, 1)] - bars;
  const double sx = 10 + 1000 * ex + 150 * ey, sy = 4 + 120 * ex + 600 * ey, tau = 80 * g;
  const Vec3 expected(-(sx * (1 + ey) - tau * g), -(tau * (1 + ey) - sy * g), 0);
  MESSAGE("cut of the right edge: " << membrane.transpose() << " expected " << expected.transpose());
  CHECK(membrane.x() == doctest::Approx(expected.x()).epsilon(1e-12));
  CHECK(membrane.y() == doctest::Approx(expected.y()).epsilon(1e-12));
  CHECK(std::abs(membrane.z()) < 1e-12);
}

TEST_CASE("cst: each corner's pull is half the stress tensor applied to its opposite side's outward normal") {
  // One quad, skewed out of its plane, every corner on the boundary (so
  // each takes its whole pull). The reference is eq. 3.36's uniform stress
  // written with the frame's tensor, S = sigma_x e1 e1 + sigma_y e2 e2, and
  // the corner's 1/2 S m, m = (opposite side) x e3 (Eigen's cross
  // products); the step computes it from the sides' coordinates in the
  // frame instead (stop 43), equal to rounding: within 1e-13 of the pull's
  // scale.
  FlatSquare sq(1, 1.0);
  Model& m = sq.m;
  const auto tris = triangles_of(m, sq.patch, Vec3(1, 0, 0));
  const double sx = 3, sy = 2;
  m.set_patch_formulation(sq.patch, form(sx, sy), tris);
  const Vec3 moved[4] = {Vec3(0, 0, 0.1), Vec3(1.2, 0.1, -0.2), Vec3(-0.1, 0.9, 0.3), Vec3(1.1, 1.3, 0.05)};
  for (int q = 0; q < 4; ++q) m.particles.position[sq.ps[q]] = moved[q];
  Solver solver(m);
  solver.compute_forces();
  std::vector<Vec3> expected(m.particles.capacity(), Vec3::Zero());
  const auto& x = m.particles.position;
  for (const Bar& b : m.bars.items) {
    const Vec3 d = x[b.j] - x[b.i];
    const double T = b.prestress + b.EA / b.rest_length * (d.norm() - b.rest_length);
    expected[b.i] += T * d / d.norm();
    expected[b.j] -= T * d / d.norm();
  }
  for (const auto& t : tris) {
    const Vec3 a = x[t[1]] - x[t[0]], b = x[t[2]] - x[t[0]], c = x[t[2]] - x[t[1]];
    const Vec3 e1 = a.normalized(), e3 = a.cross(b).normalized(), e2 = e3.cross(e1);
    const Eigen::Matrix3d S = sx * e1 * e1.transpose() + sy * e2 * e2.transpose();
    expected[t[0]] += 0.5 * S * c.cross(e3);
    expected[t[1]] += 0.5 * S * (-b).cross(e3);
    expected[t[2]] += 0.5 * S * a.cross(e3);
  }
  for (ParticleId q : sq.ps) {
    CAPTURE(q);
    CHECK((m.particles.force[q] - expected[q]).norm() < 1e-13 * (sx + sy));
  }
}

TEST_CASE("cst: a membrane triangle collapsing to a line stays finite") {
  // One quad: triangles (i, j, k) and (k, l, i). Corner k walks through the
  // line of side i-j and back; every other corner is locked.
  FlatSquare sq(1, 1.0);
  Model& m = sq.m;
  const auto tris = triangles_of(m, sq.patch, Vec3(1, 0, 0));
  m.set_patch_formulation(sq.patch, form(3, 2), tris);
  const ParticleId i = tris[0][0], j = tris[0][1], k = tris[0][2];
  m.set_lock(k, 0);
  Solver solver(m);
  const Vec3 xi = m.particles.position[i], xj = m.particles.position[j], mid = 0.5 * (xi + xj);
  const Vec3 across = Vec3(0, 0, 1).cross(xj - xi).normalized();
  // The boundary bars' pull on a particle, by hand (no prestress in the section).
  auto bar_pull = [&](ParticleId q) {
    Vec3 f = Vec3::Zero();
    for (const Bar& b : m.bars.items) {
      const Vec3 d = m.particles.position[b.j] - m.particles.position[b.i];
      const Vec3 t = b.EA / b.rest_length * (d.norm() - b.rest_length) * d / d.norm();
      if (b.i == q) f += t;
      if (b.j == q) f -= t;
    }
    return f;
  };
  for (double s : {0.5, 1e-3, 1e-6, 1e-12, 0.0, -1e-12, -1e-6, -1e-3}) {
    CAPTURE(s);
    m.particles.position[k] = mid + s * across + Vec3(0, 0, 0.3 * s);
    solver.compute_forces();
    for (ParticleId q : {i, j, k}) {
      REQUIRE(m.particles.force[q].allFinite());
      REQUIRE(std::isfinite(m.particles.stiffness[q]));
      REQUIRE(m.particles.stiffness[q] > 0);
    }
    // j belongs to the first triangle only: its membrane pull is at most
    // 1/2 (sigma_warp + sigma_weft) times the opposite side, however thin
    // the triangle (the side tensions of eq. 3.36 would blow up).
    const Vec3 membrane = m.particles.force[j] - bar_pull(j);
    CHECK(membrane.norm() <= 0.5 * 5 * (m.particles.position[k] - xi).norm() + 1e-12);
    if (std::abs(s) <= 1e-12) CHECK(membrane.norm() == 0.0);  // no plane: no force
  }
  // Relaxing from near the line: k goes back to where the bars and the other
  // triangle hold it, without NaN, and the model stays valid.
  m.particles.position[k] = mid + 1e-6 * across;
  const RunResult r = solver.run(1e-8, 50000);
  CHECK(m.particles.position[k].allFinite());
  CHECK((m.particles.position[k] - mid).norm() > 0.1);
  CHECK(m.check() == "");
  MESSAGE("collapsed triangle released in " << r.steps << " steps, converged " << r.converged);
  // Analysis needs a reference shape: switching with k on the line is
  // refused, naming the triangle, and the model is unchanged.
  m.particles.position[k] = mid;
  Membrane an;
  an.mode = Membrane::Analysis;
  an.dxx = an.dyy = 100;
  CHECK_THROWS_WITH_AS(m.set_patch_formulation(sq.patch, an, tris), doctest::Contains("collinear"), ModelError);
  CHECK(m.csts.size() == 2u);
  CHECK(m.patch_formulation(sq.patch).mode == Membrane::FormFinding);
  CHECK(m.check() == "");
}
