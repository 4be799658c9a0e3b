#include "physics/numerical_errors.hpp"

#include <cmath>

namespace tendril {

namespace {

std::string block_name(const Model& m, BlockId b) {
  return std::string(block_kind_name(m.blocks[b].kind)) + " " + std::to_string(b);
}

bool finite(const Vec3* a, ParticleId p) { return !a || a[p].allFinite(); }

}  // namespace

std::string describe_particle(const Model& m, ParticleId p) {
  std::string s = "particle " + std::to_string(p);
  const std::vector<BlockId> blocks = m.blocks_of(p);
  for (std::size_t k = 0; k < blocks.size(); ++k) s += (k ? ", " : " (on ") + block_name(m, blocks[k]);
  return blocks.empty() ? s : s + ")";
}

void throw_degenerate_hinge(const Model& m, const Hinge& h, const Vec3* x, const char* done) {
  std::string why;
  for (ParticleId p : {h.i, h.j, h.k})
    if (!x[p].allFinite()) why = "the position of particle " + std::to_string(p) + " is not finite";
  if (why.empty()) {
    const bool a = (x[h.j] - x[h.i]).norm() <= (x[h.k] - x[h.j]).norm();  // the shorter link
    why = "particles " + std::to_string(a ? h.i : h.j) + " and " + std::to_string(a ? h.j : h.k) +
          " coincide (or nearly): a zero-length link has no bending plane and an infinite stiffness 4 EI / L^3 (eq. 3.43)";
  }
  throw NumericalError("solver: the hinge of " + block_name(m, m.dart_block[h.dart]) + " at " +
                       describe_particle(m, h.j) + " between particles " + std::to_string(h.i) + " and " +
                       std::to_string(h.k) + ": " + why + "; " + done);
}

NumericalError non_finite_motion(const Model& m, const Vec3* x, const Vec3* v, const Vec3* w, const SolverSettings& s,
                             std::uint64_t step, const char* done) {
  // The first particle whose state is not finite; else (the kinetic energy
  // overflowed) the fastest.
  const Particles& P = m.particles;
  ParticleId bad = kNone, fastest = kNone;
  double top = -1;
  for (std::size_t p = 0; p < P.capacity() && bad == kNone; ++p) {
    if (!P.active[p]) continue;
    if (!finite(x, p) || !finite(v, p)) bad = ParticleId(p);
    if (v && v[p].squaredNorm() > top) top = v[p].squaredNorm(), fastest = ParticleId(p);
  }
  if (w)
    for (ParticleId p : P.rotational.raw())
      if (bad == kNone && P.active[p] && !w[p].allFinite()) bad = p;
  if (bad == kNone) bad = fastest;
  const std::string who = bad == kNone ? std::string("a particle") : describe_particle(m, bad);
  return NumericalError("solver: the motion of " + who + " is not finite at step " + std::to_string(step) + " of " +
                       integrator_name(s.integrator) + " with dt = " + std::to_string(s.dt) +
                       ": the time step is beyond the integrator's stability limit (physical masses) or a mass "
                       "vanishes; " + done);
}

}  // namespace tendril
