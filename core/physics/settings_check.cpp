#include "physics/settings_check.hpp"

#include <cmath>

namespace tendril {

std::optional<SettingError> check_settings(const SolverSettings& s) {
  auto finite = [](double x) { return std::isfinite(x); };
  if (!(s.dt > 0) || !finite(s.dt)) return SettingError{"dt", "must be a finite number > 0"};
  if (!(s.viscous >= 0 && s.viscous < 2)) return SettingError{"viscous", "must be in [0, 2)"};
  if (!(s.geometric_factor >= 0) || !finite(s.geometric_factor))
    return SettingError{"geometric_factor", "must be a finite number >= 0"};
  if (!(s.mass_factor >= 1) || !finite(s.mass_factor)) return SettingError{"mass_factor", "must be a finite number >= 1"};
  if (s.vie_iterations < 0 || s.vie_iterations > kMaxVieIterations)
    return SettingError{"vie_iterations",
                        "must be a whole number from 0 (the solver chooses) to " + std::to_string(kMaxVieIterations)};
  if (!(s.vie_dt >= 0) || !finite(s.vie_dt)) return SettingError{"vie_dt", "must be a finite number >= 0 (0: dt)"};
  if (!(s.mixed_switch > 0 && s.mixed_switch < 1)) return SettingError{"mixed_switch", "must be in (0, 1)"};
  if (s.mixed_implicit != Integrator::VariationalImplicitEuler && s.mixed_implicit != Integrator::ProjectiveDynamics)
    return SettingError{"mixed_implicit", "must be vie or projective"};
  if (s.threads < 1 || s.threads > kMaxThreads)
    return SettingError{"threads", "must be a whole number from 1 to " + std::to_string(kMaxThreads)};
  return std::nullopt;
}

std::optional<std::int64_t> whole_number_in(double x, std::int64_t lo, std::int64_t hi) {
  // Compared as doubles first: both bounds convert exactly up to 2^53.
  if (!(x >= double(lo) && x <= double(hi)) || x != std::floor(x)) return std::nullopt;
  if (!(std::abs(x) < 9223372036854775808.0)) return std::nullopt;  // 2^63: double(hi) may round up to it
  return std::int64_t(x);
}

}  // namespace tendril
