// `tendril sweep`: a scene run for every combination of parameter values and
// seeds. The plan (DIR/plan.csv) is written once; each run gets its folder
// and a `done` marker last, so a sweep resumes where it stopped; the runs go
// to local processes or to one Slurm job array, and both end in the same
// DIR/sweep.csv and DIR/summary.md (docs/agents.md).
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>

#include "command.hpp"
#include "io/atomic_file.hpp"
#include "scene_declarations.hpp"
#include "sweep/local.hpp"
#include "sweep/slurm.hpp"
#include "sweep/supervisor.hpp"

namespace tendril::app {

namespace {

namespace fs = std::filesystem;
using namespace tendril::sweep;

struct SweepArguments {
  std::string scene, out = "sweep", plan_dir, gather_dir, seeds;
  std::vector<std::string> params;
  std::int64_t jobs = 1, steps = -1, task = 0, array_max = 0;
  bool resume = false, slurm = false, no_wait = false;
  SlurmOptions slurm_options;
};

std::string self() { return fs::read_symlink("/proc/self/exe").string(); }

std::int64_t whole_number(const std::string& text, const std::string& what) {
  std::int64_t v = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, v);
  if (error != std::errc() || stop != end) throw UsageError(what + ": '" + text + "' is not a whole number");
  return v;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t k; (k = s.find(sep, start)) != std::string::npos; start = k + 1) out.push_back(s.substr(start, k - start));
  out.push_back(s.substr(start));
  return out;
}

// The plan the command line describes; its parameters checked against the
// scene's declarations.
Plan plan_of(const SweepArguments& a) {
  if (a.params.empty() && a.seeds.empty())
    throw UsageError("nothing to sweep: give --param NAME=V1,V2,... or --seeds A..B (or both)");
  ParamValues params;
  std::vector<std::string> names;
  for (const std::string& p : a.params) {
    auto [name, values] = split_param(p);
    if (values.empty()) throw UsageError("--param " + name + " needs values: " + name + "=V1,V2,...");
    if (std::find(names.begin(), names.end(), name) != names.end())
      throw UsageError("--param " + name + " is given twice");
    const auto& reserved = plan_columns();
    if (std::find(reserved.begin(), reserved.end(), name) != reserved.end() || name == "status" || name == "error")
      throw UsageError("--param " + name + ": a sweep's own column has that name; rename the parameter");
    names.push_back(name);
    params.push_back({name, split(values, ',')});
  }
  std::int64_t first = 1, last = 1;
  if (!a.seeds.empty()) {
    const auto dots = a.seeds.find("..");
    first = whole_number(a.seeds.substr(0, dots), "--seeds");
    last = dots == std::string::npos ? first : whole_number(a.seeds.substr(dots + 2), "--seeds");
    if (last < first) throw UsageError("--seeds " + a.seeds + ": the first seed is after the last");
  }
  check_declared(a.scene, names);
  return make_plan(fs::absolute(a.scene).lexically_normal().string(), fs::current_path().string(), a.steps, params,
                   first, last);
}

// What differs between the plan in DIR and this command's.
std::string difference(const Plan& there, const Plan& here) {
  if (there.scene != here.scene) return "its scene is " + there.scene + ", this command's " + here.scene;
  if (there.workdir != here.workdir) return "it runs in " + there.workdir + ", this command in " + here.workdir;
  if (there.steps != here.steps) return "its --steps differ";
  if (there.params != here.params) return "its parameters differ";
  if (there.runs.size() != here.runs.size())
    return "it has " + std::to_string(there.runs.size()) + " runs, this command " + std::to_string(here.runs.size());
  return "its values or seeds differ";
}

bool has_plan(const std::string& dir) {
  std::error_code ec;
  return fs::exists(plan_path(dir), ec);
}

// The plan of DIR: the one the command line describes (written there if DIR
// has none), or DIR's own when no scene is given.
Plan settle_plan(const SweepArguments& a, const std::string& dir) {
  if (a.scene.empty()) {
    if (!has_plan(dir)) throw UsageError(dir + " holds no sweep plan: give the scene, --param and --seeds");
    return read_plan(dir);
  }
  Plan plan = plan_of(a);
  if (has_plan(dir)) {
    const Plan there = read_plan(dir);
    if (!(there == plan))
      throw UsageError(plan_path(dir) + " is the plan of another sweep (" + difference(there, plan) +
                       "): give another --out, or remove it");
  } else {
    fs::create_directories(dir);
    write_file_atomically(plan_path(dir), plan_csv(plan));
  }
  return plan;
}

int plan_only(const SweepArguments& a) {
  const Plan plan = settle_plan(a, a.plan_dir);
  std::printf("%zu runs planned in %s; `tendril sweep --out %s` (with --jobs N or --slurm) runs them\n",
              plan.runs.size(), plan_path(a.plan_dir).c_str(), a.plan_dir.c_str());
  return kOk;
}

int one_task(const SweepArguments& a) {
  if (!a.scene.empty() || !a.params.empty() || !a.seeds.empty())
    throw UsageError("--task runs a run of a planned sweep: give only --out DIR, whose plan.csv says the rest");
  if (!has_plan(a.out)) throw UsageError(a.out + " holds no sweep plan (plan.csv)");
  const Plan plan = read_plan(a.out);
  if (a.task < 1 || a.task > std::int64_t(plan.runs.size()))
    throw UsageError("--task " + std::to_string(a.task) + ": the plan has runs 1 to " + std::to_string(plan.runs.size()));
  Supervisor supervisor(self(), plan, a.out);
  Outcome outcome;
  supervisor.run({int(a.task)}, 1, [&](const PlannedRun&, const Outcome& o) { outcome = o; }, {});
  if (supervisor.stop_signal()) die_of(supervisor.stop_signal());
  if (!outcome.error.empty()) std::fprintf(stderr, "tendril sweep: run %lld: %s\n", static_cast<long long>(a.task),
                                           outcome.error.c_str());
  return outcome.kind == Outcome::kOk ? kOk : kSceneError;
}

int gather_only(const SweepArguments& a) {
  if (!a.scene.empty() || !a.params.empty() || !a.seeds.empty())
    throw UsageError("--gather collects a planned sweep: give only its folder, whose plan.csv says the rest");
  const std::string& dir = a.gather_dir;
  if (!has_plan(dir)) throw UsageError(dir + " holds no sweep plan (plan.csv)");
  const Plan plan = read_plan(dir);
  const std::string job = submitted_job(dir);
  Gathered g(plan, dir, job.empty() ? std::map<int, std::string>{} : queue_states(job));
  return finish_sweep(plan, g, dir);
}

int sweep(const SweepArguments& a) {
  if (!a.plan_dir.empty()) return plan_only(a);
  if (!a.gather_dir.empty()) return gather_only(a);
  if (a.task) return one_task(a);
  const std::string& dir = a.out;
  const Plan plan = settle_plan(a, dir);
  Gathered g(plan, dir);
  std::vector<int> todo;
  int finished = 0;
  for (const PlannedRun& r : plan.runs) {
    if (g.runs()[std::size_t(r.index - 1)].outcome.finished()) ++finished;
    else todo.push_back(r.index);
  }
  if (finished && !a.resume)
    throw UsageError(dir + " holds " + std::to_string(finished) + " finished runs of this sweep: --resume continues it, "
                     "or give another --out");
  if (a.resume && !todo.empty())
    std::fprintf(stderr, "[tendril] sweep: resuming %s: %d of %zu runs finished, %zu to run\n", dir.c_str(), finished,
                 plan.runs.size(), todo.size());
  if (a.slurm && !todo.empty()) {
    const std::string job = submit(self(), plan, dir, todo, a.slurm_options);
    std::fprintf(stderr, "[tendril] sweep: submitted Slurm job %s: %zu tasks (%s/slurm/array.sh)\n", job.c_str(),
                 todo.size(), dir.c_str());
    if (a.no_wait) {
      std::printf("%s\n", job.c_str());
      std::fprintf(stderr, "[tendril] sweep: `tendril sweep --gather %s` collects the runs once the job is done\n",
                   dir.c_str());
      return kOk;
    }
    wait_for(job, plan, dir, g);
  } else if (!todo.empty()) {
    run_local(self(), plan, dir, todo, int(a.jobs), g);
  }
  return finish_sweep(plan, g, dir);
}

}  // namespace

Command sweep_command() {
  return {"sweep", "runs a scene for every combination of parameters and seeds, here or on a Slurm cluster",
          [](CLI::App& cli) {
            auto a = std::make_shared<SweepArguments>();
            constexpr auto kMax = std::numeric_limits<std::int64_t>::max();
            cli.add_option("scene", a->scene, "the Lua scene (docs/lua-api.md); not needed when DIR has a plan")
                ->check(CLI::ExistingPath)
                ->type_name("SCENE.lua");
            cli.add_option("--param", a->params, "values of tendril.param(NAME, default) to sweep (repeatable)")
                ->type_name("NAME=V1,V2,...")
                ->expected(1)
                ->take_all();
            cli.add_option("--seeds", a->seeds, "the seeds of every combination, A to B")->type_name("A..B");
            add_integer(cli, "--steps", a->steps, 0, kMax, "caps the steps of every run{} and step() of each run");
            cli.add_option("--out", a->out, "the sweep's folder: plan.csv, run-K/, sweep.csv, summary.md")
                ->type_name("DIR")
                ->capture_default_str();
            auto* plan = cli.add_option("--plan", a->plan_dir, "only writes the plan, DIR/plan.csv")->type_name("DIR");
            auto* resume = cli.add_flag("--resume", a->resume, "continues the sweep in --out: finished runs are kept");
            add_integer(cli, "--jobs", a->jobs, 1, 4096, "runs at once on this machine")->type_name("N")->capture_default_str();
            auto* slurm = cli.add_flag("--slurm", a->slurm, "submits the runs as one Slurm job array (sbatch)");
            cli.add_option("--partition", a->slurm_options.partition, "sbatch --partition")->type_name("NAME")->needs(slurm);
            cli.add_option("--time", a->slurm_options.time, "sbatch --time, per run (e.g. 30:00)")
                ->type_name("TIME")
                ->needs(slurm);
            add_integer(cli, "--array-max", a->array_max, 1, 1'000'000, "at most N tasks at once (--array=...%N)")
                ->type_name("N")
                ->needs(slurm);
            cli.add_flag("--no-wait", a->no_wait, "returns once submitted; --gather collects")->needs(slurm);
            auto* task = add_integer(cli, "--task", a->task, 1, kMax,
                                     "runs run K of --out's plan (what a Slurm array task calls)")
                           ->type_name("K");
            auto* gather = cli.add_option("--gather", a->gather_dir, "collects DIR's runs into sweep.csv and summary.md")
                               ->type_name("DIR");
            for (CLI::Option* mode : {plan, task, gather})
              for (CLI::Option* other : {resume, slurm}) mode->excludes(other);
            plan->excludes(task)->excludes(gather);
            task->excludes(gather);
            return [a] {
              a->slurm_options.array_max = int(a->array_max);
              return sweep(*a);
            };
          }};
}

}  // namespace tendril::app
