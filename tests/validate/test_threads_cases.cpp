// Issue 18: every validation case gives the same numbers whatever the
// thread count. Each case at its coarsest quick resolution with every
// integrator it lists, on 1 and on 3 threads (an odd
// count: partitions of unequal size): the same error, steps and force
// evaluations, to the last bit. The threads only split work in fixed chunks
// summed in a fixed order (core/physics/workers.hpp), so they must.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>

#include "registry.hpp"

using namespace tendril;
using namespace tendril::validate;

// Under the sanitizers this case alone took 310 s of the suite, to check
// again what the ordinary build checks: it is a question of numbers, not of
// memory, and the threaded force paths run under the sanitizers in
// tests/physics/test_threads.cpp.
#ifdef TENDRIL_SANITIZED
constexpr bool kSkipUnderSanitizers = true;
#else
constexpr bool kSkipUnderSanitizers = false;
#endif

TEST_CASE("validation cases: 1 and 3 threads give the same numbers bit for bit" *
          doctest::skip(kSkipUnderSanitizers)) {
  int settings = 0;
  for (const Case& c : cases()) {
    std::vector<Setting> runs;
    for (Integrator i : c.integrators) {
      Setting s = c.defaults;
      s.segments = c.quick_segments.empty() ? c.defaults.segments : c.quick_segments.front();
      s.solver.integrator = i;
      runs.push_back(s);
    }
    for (Setting s : runs) {
      CAPTURE(c.name);
      CAPTURE(std::string(integrator_name(s.solver.integrator)));
      CAPTURE(s.segments);
      s.solver.threads = 1;
      const Outcome one = c.run(s);
      s.solver.threads = 3;
      const Outcome three = c.run(s);
      CHECK(one.error == three.error);
      CHECK(one.steps == three.steps);
      CHECK(one.force_evaluations == three.force_evaluations);
      CHECK(one.converged == three.converged);
      ++settings;
    }
  }
  std::printf("validation cases on 1 and 3 threads: %d settings\n", settings);
  CHECK(settings > 140);  // 147 when written
}
