// tendril sweep: a scene run for every combination of parameter values and
// seeds, across N processes; one CSV row per run, each run's outputs (model,
// journal, summary) in its own folder. A failing run is a row with its error.
#include <spawn.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "io/csv.hpp"
#include "scene_declarations.hpp"

extern char** environ;

namespace tendril::app {

namespace {

struct Run {
  std::vector<std::pair<std::string, std::string>> params;
  long long seed = 0;
  std::string dir;
  int status = -1;
  double seconds = 0;
  std::string error;
  std::map<std::string, std::string> summary;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, sep);) out.push_back(item);
  return out;
}

std::string last_line(const std::string& path) {
  std::ifstream in(path);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  return last;
}

void read_summary(Run& r) {
  std::ifstream in(r.dir + "/summary.csv");
  const auto rows = tendril::parse_csv(std::string(std::istreambuf_iterator<char>(in), {}));
  if (rows.size() < 2) return;
  for (std::size_t k = 0; k < rows[0].size() && k < rows[1].size(); ++k) r.summary[rows[0][k]] = rows[1][k];
}

std::int64_t whole_number(const std::string& text, const std::string& what) {
  std::int64_t v = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, v);
  if (error != std::errc() || stop != end) throw UsageError(what + ": '" + text + "' is not a whole number");
  return v;
}

struct SweepArguments {
  std::string scene, out = "sweep", seeds;
  std::vector<std::string> params;
  std::int64_t jobs = 1, steps = -1;
};

int run_sweep(const SweepArguments& a) {
  const std::string& scene = a.scene;
  const std::string& out = a.out;
  if (a.params.empty() && a.seeds.empty())
    throw UsageError("nothing to sweep: give --param NAME=V1,V2,... or --seeds A..B (or both)");
  std::vector<std::pair<std::string, std::vector<std::string>>> params;
  std::vector<std::string> names;
  for (const std::string& p : a.params) {
    auto [name, values] = split_param(p);
    if (values.empty()) throw UsageError("--param " + name + " needs values: " + name + "=V1,V2,...");
    if (std::find(names.begin(), names.end(), name) != names.end())
      throw UsageError("--param " + name + " is given twice");
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
  check_declared(scene, names);
  const std::string steps = a.steps >= 0 ? std::to_string(a.steps) : "";
  const std::int64_t jobs = a.jobs;

  // Every combination, parameters in the order given, then seeds.
  std::vector<Run> runs(1);
  for (const auto& [name, values] : params) {
    std::vector<Run> next;
    for (const Run& r : runs)
      for (const std::string& v : values) {
        Run copy = r;
        copy.params.push_back({name, v});
        next.push_back(copy);
      }
    runs = next;
  }
  std::vector<Run> all;
  for (const Run& r : runs)
    for (long long s = first; s <= last; ++s) {
      Run copy = r;
      copy.seed = s;
      copy.dir = out + "/run-" + std::to_string(all.size() + 1);
      all.push_back(copy);
    }

  std::filesystem::create_directories(out);
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::map<pid_t, std::pair<std::size_t, std::chrono::steady_clock::time_point>> running;
  std::size_t next = 0, done = 0;
  while (done < all.size()) {
    while (running.size() < std::size_t(jobs) && next < all.size()) {
      Run& r = all[next];
      std::filesystem::create_directories(r.dir);
      std::vector<std::string> args{self, "run", scene, "--out", r.dir, "--seed", std::to_string(r.seed), "--quiet"};
      for (const auto& [name, v] : r.params) args.insert(args.end(), {"--param", name + "=" + v});
      if (!steps.empty()) args.insert(args.end(), {"--steps", steps});
      std::vector<char*> cargs;
      for (std::string& a : args) cargs.push_back(a.data());
      cargs.push_back(nullptr);
      posix_spawn_file_actions_t files;
      posix_spawn_file_actions_init(&files);
      posix_spawn_file_actions_addopen(&files, 1, (r.dir + "/stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      posix_spawn_file_actions_addopen(&files, 2, (r.dir + "/stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      pid_t pid = 0;
      if (int err = posix_spawn(&pid, self.c_str(), &files, nullptr, cargs.data(), environ); err != 0) {
        r.error = std::string("could not start ") + self + ": " + std::strerror(err);
        ++done;
      } else {
        running[pid] = {next, std::chrono::steady_clock::now()};
      }
      posix_spawn_file_actions_destroy(&files);
      ++next;
    }
    if (running.empty()) continue;
    int status = 0;
    pid_t pid = waitpid(-1, &status, 0);
    auto it = running.find(pid);
    if (it == running.end()) continue;
    Run& r = all[it->second.first];
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - it->second.second).count();
    r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    if (r.status != 0) r.error = last_line(r.dir + "/stderr.txt");
    read_summary(r);
    running.erase(it);
    ++done;
    std::fprintf(stderr, "[tendril] sweep: %zu/%zu runs done\n", done, all.size());
  }

  std::set<std::string> keys;
  for (const Run& r : all)
    for (const auto& [k, v] : r.summary) keys.insert(k);
  std::ofstream csv(out + "/sweep.csv");
  csv << "run";
  std::vector<std::string> header{"run"};
  for (const auto& [name, values] : params) header.push_back(name);
  header.insert(header.end(), {"seed", "status", "wall_time_s"});
  header.insert(header.end(), keys.begin(), keys.end());
  header.push_back("error");
  csv << tendril::csv_line(header) << "\n";
  int failed = 0;
  for (std::size_t n = 0; n < all.size(); ++n) {
    const Run& r = all[n];
    std::vector<std::string> row{std::to_string(n + 1)};
    for (const auto& [name, v] : r.params) row.push_back(v);
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.3f", r.seconds);
    row.insert(row.end(), {std::to_string(r.seed), r.status == 0 ? "ok" : "failed", secs});
    for (const std::string& k : keys) row.push_back(r.summary.count(k) ? r.summary.at(k) : "");
    row.push_back(r.error);
    csv << tendril::csv_line(row) << "\n";
    failed += r.status != 0;
  }
  csv.close();
  std::ifstream back(out + "/sweep.csv");
  std::printf("%s", std::string(std::istreambuf_iterator<char>(back), {}).c_str());
  std::fprintf(stderr, "[tendril] sweep: %zu runs, %d failed -> %s/sweep.csv\n", all.size(), failed, out.c_str());
  return failed ? kSceneError : kOk;
}

}  // namespace

Command sweep_command() {
  return {"sweep", "runs a scene for every combination of parameters and seeds; one CSV row per run",
          [](CLI::App& cli) {
            auto a = std::make_shared<SweepArguments>();
            constexpr auto kMax = std::numeric_limits<std::int64_t>::max();
            add_scene(cli, a->scene);
            cli.add_option("--param", a->params, "values of tendril.param(NAME, default) to sweep (repeatable)")
                ->type_name("NAME=V1,V2,...")
                ->expected(1)
                ->take_all();
            cli.add_option("--seeds", a->seeds, "the seeds of every combination, A to B")->type_name("A..B");
            add_integer(cli, "--jobs", a->jobs, 1, 4096, "runs at once")->capture_default_str();
            cli.add_option("--out", a->out, "the sweep's folder: sweep.csv and a folder per run")
                ->type_name("DIR")
                ->capture_default_str();
            add_integer(cli, "--steps", a->steps, 0, kMax, "caps the steps of every run{} and step() of each run");
            return [a] { return run_sweep(*a); };
          }};
}

}  // namespace tendril::app
