#pragma once
// A sweep's plan: every run -- its index, seed and parameter values -- and
// what all runs share (the scene, the folder they start in, the step cap).
// Written once to DIR/plan.csv, one row per run, each row whole, so that any
// machine (this one, a Slurm task) runs run K from the file alone.
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tendril::sweep {

struct PlannedRun {
  int index = 0;  // 1..N, the folder run-K
  std::int64_t seed = 1;
  std::vector<std::string> values;  // in Plan::params order
  bool operator==(const PlannedRun&) const = default;
};

struct Plan {
  std::string scene;    // absolute path
  std::string workdir;  // absolute: every run starts here
  std::int64_t steps = -1;  // --steps of every run; -1: none
  std::vector<std::string> params;  // names, in the order given
  std::vector<PlannedRun> runs;
  bool operator==(const Plan&) const = default;
};

using ParamValues = std::vector<std::pair<std::string, std::vector<std::string>>>;

// Every combination of the values (the first parameter varies slowest), each
// with every seed from first to last.
Plan make_plan(const std::string& scene, const std::string& workdir, std::int64_t steps, const ParamValues& params,
               std::int64_t first_seed, std::int64_t last_seed);

// The columns every plan row has before its parameters; a parameter may not
// take one of these names.
const std::vector<std::string>& plan_columns();

std::string plan_csv(const Plan& plan);
// Throws std::runtime_error naming `where` and the row at fault.
Plan parse_plan(std::string_view text, const std::string& where);

// DIR/plan.csv
std::string plan_path(const std::string& dir);
Plan read_plan(const std::string& dir);  // throws when DIR has no plan

}  // namespace tendril::sweep
