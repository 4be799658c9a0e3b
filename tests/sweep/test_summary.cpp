// What a sweep gathers from its run folders and summarises: rows in plan
// order whatever order runs ended in; per combination the mean, the sample
// standard deviation and the lowest and highest run, against hand values.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "io/csv.hpp"
#include "sweep/gather.hpp"
#include "sweep/summary.hpp"

using namespace tendril;
using namespace tendril::sweep;

namespace {

namespace fs = std::filesystem;

void write(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

// Run k of the sweep in dir finished with status ok (figures: sag, converged, label) or failed.
void finished(const fs::path& dir, int k, const std::string& sag, const std::string& converged) {
  const fs::path run = dir / ("run-" + std::to_string(k));
  write(run / "summary.csv", "converged,label,sag\n" + converged + ",\"chain, 12\"," + sag + "\n");
  write(run / "done", "status,exit_status,wall_time_s,host,error\nok,0,0.5,node1,\n");
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

TEST_CASE("sweep summary: statistics per combination over its seeds, failed and unfinished runs left out") {
  const fs::path dir = fs::temp_directory_path() / "tendril-test-sweep-summary";
  fs::remove_all(dir);
  const Plan plan = make_plan("/s/chain.lua", "/w", -1, {{"segments", {"12", "24"}}}, 1, 3);
  // segments 12: sag 1, 2, 4 (seeds 1-3); segments 24: 5, failed, not run.
  finished(dir, 1, "1", "true");
  finished(dir, 2, "2", "false");
  finished(dir, 3, "4", "true");
  finished(dir, 4, "5", "true");
  write(dir / "run-5" / "done", "status,exit_status,wall_time_s,host,error\nfailed,1,0.1,node1,\"chain.lua:9: boom\"\n");
  write(dir / "run-6" / "stdout.txt", "");  // started, never finished: interrupted

  const Gathered g(plan, dir.string());
  const Tally t = g.tally();
  CHECK(t.ok == 4);
  CHECK(t.failed == 1);
  CHECK(t.waiting == 1);
  CHECK(g.runs()[5].status == "interrupted");

  CHECK(figure_kind(g, "sag") == FigureKind::kNumber);
  CHECK(figure_kind(g, "converged") == FigureKind::kBoolean);
  CHECK(figure_kind(g, "label") == FigureKind::kText);
  const auto sag = spreads(plan, g, "sag");
  REQUIRE(sag.size() == 2);
  CHECK(sag[0].values == std::vector<std::string>{"12"});
  CHECK(sag[0].runs == 3);
  CHECK(sag[0].mean == doctest::Approx(7.0 / 3).epsilon(1e-15));
  // Sample variance of 1, 2, 4 about 7/3: (16 + 1 + 25) / 9 / 2 = 7/3.
  CHECK(sag[0].sd == doctest::Approx(std::sqrt(7.0 / 3)).epsilon(1e-15));
  CHECK(sag[0].low == 1);
  CHECK(sag[0].low_run == 1);
  CHECK(sag[0].high == 4);
  CHECK(sag[0].high_run == 3);
  CHECK(sag[1].runs == 1);
  CHECK(sag[1].mean == 5);
  CHECK(std::isnan(sag[1].sd));
  const auto converged = spreads(plan, g, "converged");
  CHECK(converged[0].runs == 3);
  CHECK(converged[0].trues == 2);

  write_sweep_csv(plan, g, dir.string(), false);
  const auto rows = parse_csv(slurp(dir / "sweep.csv"));
  REQUIRE(rows.size() == 7);
  CHECK(rows[0] == std::vector<std::string>{"run", "segments", "seed", "status", "converged", "label", "sag", "error"});
  CHECK(rows[1] == std::vector<std::string>{"1", "12", "1", "ok", "true", "chain, 12", "1", ""});
  CHECK(rows[5] == std::vector<std::string>{"5", "24", "2", "failed", "", "", "", "chain.lua:9: boom"});
  CHECK(rows[6] == std::vector<std::string>{"6", "24", "3", "interrupted", "", "", "", ""});
  write_sweep_csv(plan, g, dir.string(), true);
  CHECK(parse_csv(slurp(dir / "sweep.csv")).size() == 6);  // the header and the 5 finished runs
  CHECK(parse_csv(slurp(dir / "times.csv"))[1] == std::vector<std::string>{"1", "ok", "0.500", "node1", "0"});

  write_summary(plan, g, dir.string());
  const std::string md = slurp(dir / "summary.md");
  CHECK(md.find("6 runs of `/s/chain.lua`: segments = 12, 24; seeds 1..3.") != std::string::npos);
  CHECK(md.find("4 ok, 1 failed, 0 cancelled, 1 not finished.") != std::string::npos);
  CHECK(md.find("| 5 | 24 | 2 | failed | chain.lua:9: boom |") != std::string::npos);
  CHECK(md.find("| 12 | 3 | 2.33333 | 1.52753 | 1 (run 1, seed 1) | 4 (run 3, seed 3) |") != std::string::npos);
  CHECK(md.find("| 24 | 1 | 5 |  | 5 (run 4, seed 1) | 5 (run 4, seed 1) |") != std::string::npos);
  CHECK(md.find("| 12 | 3 | 2 of 3 |") != std::string::npos);
  CHECK(md.find("Not summarised (text): label.") != std::string::npos);
}
