// The hanging chain of benchmark_models.hpp against the elastic catenary.
#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

Outcome run_catenary(const Setting& setting) {
  HangingChain chain(setting.segments);
  Solver solver(chain.m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-6, 2'000'000);  // 1 uN against 235 N of weight
  out.error = relative_error(chain.sag(), HangingChain::exact_sag());
  return out;
}

}  // namespace

Case catenary_case() {
  Case c;
  c.name = "catenary";
  c.reference = "hanging chain, 12 m over a 10 m span: elastic catenary (Irvine), mid-span sag";
  c.resolution = "cables of the chain";
  c.formulations = {"cable"};
  c.segments = {20, 40, 80, 160};
  c.quick_segments = {20, 80};
  c.defaults.formulation = "cable";
  c.defaults.segments = 80;
  c.tolerance = 0.005;
  c.run = run_catenary;
  return c;
}

}  // namespace tendril::validate
