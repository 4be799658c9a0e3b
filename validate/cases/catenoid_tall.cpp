// The catenoid between rings of radius 1 at a distance of 1.2 (catenoid_run.hpp).
#include "cases/catenoid_run.hpp"

namespace tendril::validate {

Case catenoid_tall_case() {
  Case c;
  c.name = "catenoid_tall";
  c.reference = "equal-stress CST membrane between rings of radius 1 at distance 1.2: catenoid waist (larger root of a cosh(h / 2a) = 1)";
  c.resolution = "particles round a ring (rows: about h / 3 of them)";
  c.formulations = {"cst"};
  c.segments = {12, 24, 48, 96};
  c.quick_segments = {12, 48};
  c.defaults.formulation = "cst";
  c.defaults.segments = 48;
  c.tolerance = 0.005;
  c.run = [](const Setting& s) { return run_catenoid(s, 1.2); };
  return c;
}

}  // namespace tendril::validate
