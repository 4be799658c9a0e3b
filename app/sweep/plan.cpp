#include "sweep/plan.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>

#include "io/csv.hpp"
#include "io/input_file.hpp"

namespace tendril::sweep {

namespace {

std::int64_t whole_number(const std::string& text, const std::string& what) {
  std::int64_t v = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, v);
  if (error != std::errc() || stop != end) throw std::runtime_error(what + ": '" + text + "' is not a whole number");
  return v;
}

}  // namespace

Plan make_plan(const std::string& scene, const std::string& workdir, std::int64_t steps, const ParamValues& params,
               std::int64_t first_seed, std::int64_t last_seed) {
  Plan plan{scene, workdir, steps, {}, {}};
  std::vector<std::vector<std::string>> combinations(1);
  for (const auto& [name, values] : params) {
    plan.params.push_back(name);
    std::vector<std::vector<std::string>> next;
    for (const auto& combination : combinations)
      for (const std::string& v : values) {
        next.push_back(combination);
        next.back().push_back(v);
      }
    combinations = std::move(next);
  }
  for (const auto& combination : combinations)
    for (std::int64_t seed = first_seed; seed <= last_seed; ++seed)
      plan.runs.push_back({int(plan.runs.size()) + 1, seed, combination});
  return plan;
}

const std::vector<std::string>& plan_columns() {
  static const std::vector<std::string> columns{"run", "seed", "scene", "workdir", "steps"};
  return columns;
}

std::string plan_csv(const Plan& plan) {
  std::vector<std::string> header = plan_columns();
  header.insert(header.end(), plan.params.begin(), plan.params.end());
  std::string text = csv_line(header) + "\n";
  const std::string steps = plan.steps >= 0 ? std::to_string(plan.steps) : "";
  for (const PlannedRun& r : plan.runs) {
    std::vector<std::string> row{std::to_string(r.index), std::to_string(r.seed), plan.scene, plan.workdir, steps};
    row.insert(row.end(), r.values.begin(), r.values.end());
    text += csv_line(row) + "\n";
  }
  return text;
}

Plan parse_plan(std::string_view text, const std::string& where) {
  const auto rows = parse_csv(text);
  const auto& fixed = plan_columns();
  if (rows.empty() || rows[0].size() < fixed.size() || !std::equal(fixed.begin(), fixed.end(), rows[0].begin()))
    throw std::runtime_error(where + ": not a sweep plan (its header is not run,seed,scene,workdir,steps,...)");
  Plan plan;
  plan.params.assign(rows[0].begin() + long(fixed.size()), rows[0].end());
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const auto& row = rows[k];
    const std::string at = where + ": row " + std::to_string(k + 1);
    if (row.size() != rows[0].size())
      throw std::runtime_error(at + " has " + std::to_string(row.size()) + " fields, the header " +
                               std::to_string(rows[0].size()));
    PlannedRun r{int(whole_number(row[0], at + ": run")), whole_number(row[1], at + ": seed"),
                 {row.begin() + long(fixed.size()), row.end()}};
    if (r.index != int(k)) throw std::runtime_error(at + " is run " + row[0] + ", expected " + std::to_string(k));
    const std::int64_t steps = row[4].empty() ? -1 : whole_number(row[4], at + ": steps");
    if (k == 1) {
      plan.scene = row[2];
      plan.workdir = row[3];
      plan.steps = steps;
    } else if (row[2] != plan.scene || row[3] != plan.workdir || steps != plan.steps) {
      throw std::runtime_error(at + ": every run of a sweep has the same scene, workdir and steps");
    }
    plan.runs.push_back(std::move(r));
  }
  if (plan.runs.empty()) throw std::runtime_error(where + ": the plan has no runs");
  return plan;
}

std::string plan_path(const std::string& dir) { return dir + "/plan.csv"; }

Plan read_plan(const std::string& dir) {
  const std::string path = plan_path(dir);
  return parse_plan(read_input_file(path), path);
}

}  // namespace tendril::sweep
