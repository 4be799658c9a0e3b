// A model that runs away: dynamic relaxation past its stability limit does
// not always overflow to NaN; it may drift to finite, absurd coordinates
// (1e62 ... 1e176 were seen) where every later length or rule is meaningless.
// The solver stops it with an error that names the particle, the size it
// reached and the size it had, once the model's extent grew by kGrowth since
// its last topology change (the model's own size is the yardstick), or a
// coordinate passed kMaxCoordinate (a model that drifts away whole).
#include <cmath>
#include <cstdio>
#include <limits>

#include "model/limits.hpp"
#include "physics/numerical_errors.hpp"
#include "physics/solver.hpp"

namespace tendril {

namespace {
constexpr double kGrowth = 1e6;
constexpr double kSmallestExtent = 1e-3;  // [m]: a model of one particle, or of coincident ones
}  // namespace

void Solver::check_runaway() {
  const Particles& P = model_.particles;
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 lo = Vec3::Constant(inf), hi = Vec3::Constant(-inf);
  double farthest = 0;
  for (ParticleId p = 0; p < P.capacity(); ++p) {
    if (!P.alive[p]) continue;
    lo = lo.cwiseMin(P.position[p]);
    hi = hi.cwiseMax(P.position[p]);
    farthest = std::max(farthest, P.position[p].cwiseAbs().maxCoeff());
  }
  if (!(lo.x() <= hi.x())) return;  // no particle
  const double extent = (hi - lo).maxCoeff();
  if (model_.revision != runaway_.revision) {  // a new model to measure against
    runaway_ = {model_.revision, steps_, extent, 0.5 * (lo + hi)};
    if (farthest <= kMaxCoordinate) return;
  }
  const double allowed = kGrowth * std::max(runaway_.extent, kSmallestExtent);
  if (extent <= allowed && farthest <= kMaxCoordinate) return;
  // The particle farthest from where the model was.
  ParticleId worst = kNone;
  double worst_distance = -1;
  for (ParticleId p = 0; p < P.capacity(); ++p) {
    if (!P.alive[p]) continue;
    const double d = (P.position[p] - runaway_.centre).cwiseAbs().maxCoeff();
    if (d > worst_distance) worst = p, worst_distance = d;
  }
  const Vec3& x = P.position[worst];
  char buf[400];
  if (farthest > kMaxCoordinate)
    std::snprintf(buf, sizeof buf, "step %llu: the model ran away: %s is at (%g, %g, %g), beyond %g m from the origin",
                  static_cast<unsigned long long>(steps_), describe_particle(model_, worst).c_str(), x.x(), x.y(),
                  x.z(), kMaxCoordinate);
  else
    std::snprintf(buf, sizeof buf,
                  "step %llu: the model ran away: %s is at (%g, %g, %g); the model's extent grew from %g m at step "
                  "%llu to %g m",
                  static_cast<unsigned long long>(steps_), describe_particle(model_, worst).c_str(), x.x(), x.y(),
                  x.z(), runaway_.extent, static_cast<unsigned long long>(runaway_.step), extent);
  throw NumericalError(std::string(buf) + " (a time step beyond the integrator's limit, or a load without support?)");
}

}  // namespace tendril
