// tendril sweep: a scene run for every combination of parameter values and
// seeds, across N processes; one CSV row per run, each run's outputs (model,
// journal, summary) in its own folder. A failing run is a row with its error.
#include <spawn.h>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

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

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return out + "\"";
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
  std::string header, values;
  if (!std::getline(in, header) || !std::getline(in, values)) return;
  auto keys = split(header, ','), vals = split(values, ',');
  for (std::size_t k = 0; k < keys.size() && k < vals.size(); ++k) r.summary[keys[k]] = vals[k];
}

int usage(const char* why) {
  std::fprintf(stderr,
               "tendril: sweep: %s\n\nusage: tendril sweep SCENE.lua --param NAME=V1,V2,... [--param ...] "
               "--seeds A..B [--jobs N] [--out DIR] [--steps N]\n",
               why);
  return 2;
}

}  // namespace

int run_sweep(int argc, char** argv) {
  std::string scene, out = "sweep", steps;
  std::vector<std::pair<std::string, std::vector<std::string>>> params;
  long long first = 1, last = 1;
  int jobs = 1;
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (arg == "--param") {
      const std::string kv = value();
      const auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == kv.size()) return usage("--param needs NAME=V1,V2,...");
      params.push_back({kv.substr(0, eq), split(kv.substr(eq + 1), ',')});
    } else if (arg == "--seeds") {
      const std::string range = value();
      const auto dots = range.find("..");
      try {
        first = std::stoll(range.substr(0, dots));
        last = dots == std::string::npos ? first : std::stoll(range.substr(dots + 2));
      } catch (...) {
        return usage("--seeds needs A..B");
      }
      if (last < first) return usage("--seeds needs A <= B");
    } else if (arg == "--jobs") {
      jobs = std::atoi(value().c_str());
      if (jobs < 1) return usage("--jobs needs a positive number");
    } else if (arg == "--out") {
      out = value();
    } else if (arg == "--steps") {
      steps = value();
    } else if (scene.empty() && arg[0] != '-') {
      scene = arg;
    } else {
      return usage(("unexpected argument '" + arg + "'").c_str());
    }
  }
  if (scene.empty()) return usage("needs a scene");

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
  for (const auto& [name, values] : params) csv << "," << csv_field(name);
  csv << ",seed,status,wall_time_s";
  for (const std::string& k : keys) csv << "," << csv_field(k);
  csv << ",error\n";
  int failed = 0;
  for (std::size_t n = 0; n < all.size(); ++n) {
    const Run& r = all[n];
    csv << n + 1;
    for (const auto& [name, v] : r.params) csv << "," << csv_field(v);
    char secs[32];
    std::snprintf(secs, sizeof secs, "%.3f", r.seconds);
    csv << "," << r.seed << "," << (r.status == 0 ? "ok" : "failed") << "," << secs;
    for (const std::string& k : keys) csv << "," << (r.summary.count(k) ? csv_field(r.summary.at(k)) : "");
    csv << "," << csv_field(r.error) << "\n";
    failed += r.status != 0;
  }
  csv.close();
  std::ifstream back(out + "/sweep.csv");
  std::printf("%s", std::string(std::istreambuf_iterator<char>(back), {}).c_str());
  std::fprintf(stderr, "[tendril] sweep: %zu runs, %d failed -> %s/sweep.csv\n", all.size(), failed, out.c_str());
  return 0;
}
