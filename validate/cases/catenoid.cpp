// The catenoid between rings of radius 1 at a distance of 1 (catenoid_run.hpp).
#include "cases/catenoid_run.hpp"

namespace tendril::validate {

Case catenoid_case() {
  Case c;
  c.name = "catenoid";
  c.reference = "equal-stress CST membrane between rings of radius 1 at distance 1: catenoid waist 0.84834";
  c.resolution = "particles round a ring (rows: a third)";
  c.formulations = {"cst"};
  c.segments = {12, 24, 48, 96};
  c.quick_segments = {12, 24};
  c.defaults.formulation = "cst";
  c.defaults.segments = 24;
  c.tolerance = 0.005;
  c.run = [](const Setting& s) { return run_catenoid(s, 1.0); };
  return c;
}

}  // namespace tendril::validate
