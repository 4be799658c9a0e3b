// A sweep's plan: every combination with every seed, in a fixed order, and
// plan.csv read back into the same plan; the Slurm array's index ranges.
#include <doctest/doctest.h>

#include <stdexcept>

#include "sweep/plan.hpp"
#include "sweep/slurm.hpp"

using namespace tendril::sweep;

TEST_CASE("plan: the first parameter varies slowest, the seed fastest; runs numbered from 1") {
  const Plan p = make_plan("/s/grow.lua", "/w", -1, {{"spacing", {"0.25", "0.3"}}, {"view", {"35", "60", "90"}}}, 4, 5);
  REQUIRE(p.runs.size() == 2 * 3 * 2);
  CHECK(p.params == std::vector<std::string>{"spacing", "view"});
  CHECK(p.runs[0] == PlannedRun{1, 4, {"0.25", "35"}});
  CHECK(p.runs[1] == PlannedRun{2, 5, {"0.25", "35"}});
  CHECK(p.runs[2] == PlannedRun{3, 4, {"0.25", "60"}});
  CHECK(p.runs[11] == PlannedRun{12, 5, {"0.3", "90"}});
  const Plan seeds_only = make_plan("/s/grow.lua", "/w", 100, {}, 1, 3);
  REQUIRE(seeds_only.runs.size() == 3);
  CHECK(seeds_only.runs[2] == PlannedRun{3, 3, {}});
}

TEST_CASE("plan: plan.csv holds every run whole and reads back into the same plan") {
  const Plan p = make_plan("/my scenes/a,b.lua", "/w", 500, {{"label", {"x,y", "\"q\""}}}, 1, 2);
  const std::string csv = plan_csv(p);
  CHECK(csv.substr(0, csv.find('\n')) == "run,seed,scene,workdir,steps,label");
  CHECK(csv.find("\n1,1,\"/my scenes/a,b.lua\",/w,500,\"x,y\"\n") != std::string::npos);
  CHECK(parse_plan(csv, "plan.csv") == p);
}

TEST_CASE("plan: a damaged plan is refused with the row at fault") {
  const std::string head = "run,seed,scene,workdir,steps,view\n";
  CHECK_THROWS_WITH_AS(parse_plan("a,b\n", "p.csv"), doctest::Contains("not a sweep plan"), std::runtime_error);
  CHECK_THROWS_WITH_AS(parse_plan(head + "1,1,/s,/w,,35\n2,x,/s,/w,,60\n", "p.csv"),
                       "p.csv: row 3: seed: 'x' is not a whole number", std::runtime_error);
  CHECK_THROWS_WITH_AS(parse_plan(head + "1,1,/s,/w,,35\n3,1,/s,/w,,60\n", "p.csv"),
                       "p.csv: row 3 is run 3, expected 2", std::runtime_error);
  CHECK_THROWS_WITH_AS(parse_plan(head + "1,1,/s,/w,,35,extra\n", "p.csv"),
                       "p.csv: row 2 has 7 fields, the header 6", std::runtime_error);
  CHECK_THROWS_WITH_AS(parse_plan(head + "1,1,/s,/w,,35\n2,1,/t,/w,,60\n", "p.csv"),
                       doctest::Contains("every run of a sweep has the same scene"), std::runtime_error);
  CHECK_THROWS_WITH_AS(parse_plan(head, "p.csv"), "p.csv: the plan has no runs", std::runtime_error);
}

TEST_CASE("slurm: the array's index list in ranges") {
  CHECK(array_ranges({1, 2, 3, 4, 5, 6}) == "1-6");
  CHECK(array_ranges({2}) == "2");
  CHECK(array_ranges({1, 2, 3, 4, 7, 9, 10, 11, 12}) == "1-4,7,9-12");
}
