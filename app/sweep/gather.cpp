#include "sweep/gather.hpp"

#include <filesystem>
#include <set>

#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/input_file.hpp"

namespace tendril::sweep {

namespace {

// The figures a finished run reported, by column name.
std::map<std::string, std::string> reported(const std::string& run) {
  std::map<std::string, std::string> figures;
  std::error_code ec;
  const std::string path = run + "/summary.csv";
  if (!std::filesystem::is_regular_file(path, ec)) return figures;
  const auto rows = parse_csv(read_input_file(path));
  if (rows.size() < 2) return figures;
  for (std::size_t k = 0; k < rows[0].size() && k < rows[1].size(); ++k) figures[rows[0][k]] = rows[1][k];
  return figures;
}

}  // namespace

Gathered::Gathered(const Plan& plan, std::string dir, const std::map<int, std::string>& queue)
    : plan_(plan), dir_(std::move(dir)), runs_(plan.runs.size()) {
  for (const PlannedRun& r : plan.runs) update(r.index, queue.count(r.index) ? queue.at(r.index) : "");
}

void Gathered::update(int index, const std::string& queue_state) {
  RunState& s = runs_.at(std::size_t(index - 1));
  const std::string folder = run_dir(dir_, index);
  s.outcome = read_outcome(folder);
  s.status = kind_name(s.outcome.kind);
  const bool marked = s.outcome.finished() || s.outcome.kind == Outcome::kCancelled;
  if (!marked && !queue_state.empty()) s.status = queue_state;
  s.figures = s.outcome.finished() ? reported(folder) : std::map<std::string, std::string>{};
}

Tally Gathered::tally() const {
  Tally t;
  for (const RunState& s : runs_) {
    if (s.outcome.kind == Outcome::kOk) ++t.ok;
    else if (s.outcome.kind == Outcome::kFailed) ++t.failed;
    else if (s.status == "cancelled") ++t.cancelled;
    else if (s.status == "running") ++t.running;
    else ++t.waiting;
  }
  return t;
}

SweepTable sweep_table(const Plan& plan, const Gathered& g) {
  std::set<std::string> metrics;
  for (const RunState& s : g.runs())
    for (const auto& [name, value] : s.figures) metrics.insert(name);
  SweepTable t;
  t.header = {"run"};
  t.header.insert(t.header.end(), plan.params.begin(), plan.params.end());
  t.header.insert(t.header.end(), {"seed", "status"});
  t.metric_column = t.header.size();
  t.metrics.assign(metrics.begin(), metrics.end());
  t.header.insert(t.header.end(), t.metrics.begin(), t.metrics.end());
  t.header.push_back("error");
  for (std::size_t k = 0; k < plan.runs.size(); ++k) {
    const PlannedRun& r = plan.runs[k];
    const RunState& s = g.runs()[k];
    std::vector<std::string> row{std::to_string(r.index)};
    row.insert(row.end(), r.values.begin(), r.values.end());
    row.insert(row.end(), {std::to_string(r.seed), s.status});
    for (const std::string& m : t.metrics) row.push_back(s.figures.count(m) ? s.figures.at(m) : "");
    row.push_back(s.outcome.error);
    t.rows.push_back(std::move(row));
  }
  return t;
}

void write_sweep_csv(const Plan& plan, const Gathered& g, const std::string& dir, bool finished_only) {
  const SweepTable t = sweep_table(plan, g);
  std::string csv = csv_line(t.header) + "\n";
  std::string times = csv_line({"run", "status", "wall_time_s", "host", "exit_status"}) + "\n";
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const Outcome& o = g.runs()[k].outcome;
    if (finished_only && !o.finished()) continue;
    csv += csv_line(t.rows[k]) + "\n";
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.3f", o.seconds);
    const bool ran = o.finished() || o.kind == Outcome::kCancelled;
    times += csv_line({std::to_string(plan.runs[k].index), g.runs()[k].status, ran ? seconds : "", o.host,
                       ran ? std::to_string(o.exit_status) : ""}) +
             "\n";
  }
  write_file_atomically(dir + "/sweep.csv", csv);
  write_file_atomically(dir + "/times.csv", times);
}

}  // namespace tendril::sweep
