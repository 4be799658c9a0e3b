// m:run{relative =} and the verdict from Lua (issue 11): the result table's
// verdict, force_scale and relative_residual, the verdict column of
// tendril.report's summary.csv, the same verdicts with triggers, and the
// options refused.
#include <doctest/doctest.h>

#include <map>

#include "io/csv.hpp"
#include "scene_files.hpp"

using namespace tendril;

namespace {

std::map<std::string, std::string> summary_row(const std::filesystem::path& dir) {
  const auto rows = parse_csv(test::slurp(dir / "summary.csv"));
  std::map<std::string, std::string> row;
  if (rows.size() != 2 || rows[0].size() != rows[1].size()) return row;
  for (std::size_t k = 0; k < rows[0].size(); ++k) row[rows[0][k]] = rows[1][k];
  return row;
}

}  // namespace

TEST_CASE("m:run: the result table carries the verdict, the force scale and the relative residual") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-test-run-verdict";
  std::filesystem::remove_all(dir);
  std::string error;
  const int rc = test::run_scene_in(dir, R"(
    -- A 500 N load on a bar of EA = 1e6 N: converged to 1e-6 of the load.
    local m = tendril.model()
    local a, b = m:particle{ 0, 0, 0 }, m:particle{ 2, 0, 0 }
    m:cable(a, b, { EA = 1e6 })
    m:lock(a, "xyz"); m:lock(b, "yz")
    m:load(b, { 500, 0, 0 })
    assert(m:summary().verdict == "none")
    local r = m:run{ relative = 1e-6 }
    assert(r.verdict == "converged" and r.converged, r.verdict)
    assert(math.abs(r.force_scale - 500) < 1e-6, r.force_scale)
    assert(r.relative_residual <= 1e-6 and math.abs(r.relative_residual - r.residual / 500) < 1e-15)
    assert(r.residual <= 5e-4)
    -- The same model held to a tolerance Leapfrog needs more steps for.
    local short = tendril.model{ integrator = "leapfrog" }
    local c, d = short:particle{ 0, 0, 0 }, short:particle{ 2, 0, 0 }
    short:cable(c, d, { EA = 1e6 })
    short:lock(c, "xyz"); short:lock(d, "yz")
    short:load(d, { 500, 0, 0 })
    local s = short:run{ tolerance = 1e-9, max_steps = 3 }
    assert(s.verdict == "max_steps" and not s.converged and s.steps == 3, s.verdict)
    tendril.report(short, { label = "short" })
  )",
                                    &error);
  INFO(error);
  REQUIRE(rc == 0);
  auto row = summary_row(dir);
  CHECK(row["verdict"] == "max_steps");
  CHECK(row["label"] == "short");
}

TEST_CASE("m:run with triggers ends with the same verdicts") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-test-run-verdict-triggers";
  std::filesystem::remove_all(dir);
  std::string error;
  const int rc = test::run_scene_in(dir, R"(
    -- Nothing holds this cable; a rule that only looks runs every 10 steps.
    local m = tendril.model()
    local a, b = m:particle{ 0, 0, 0 }, m:particle{ 1, 0, 0 }
    m:cable(a, b, { EA = 1e3 })
    m:load(a, { 1, 0, 0 }); m:load(b, { 1, 0, 0 })
    local looked = 0
    m:trigger{ rule = tendril.rule{ name = "look", production = function() looked = looked + 1 end }, every = 10 }
    local r = m:run{ tolerance = 1e-6 }
    assert(r.verdict == "mechanism" and not r.converged, r.verdict)
    assert(r.steps % 64 == 0 and r.steps <= 256, r.steps)
    assert(looked == r.steps // 10, looked)
    assert(m:summary().verdict == "mechanism")
  )",
                                    &error);
  INFO(error);
  CHECK(rc == 0);
}

TEST_CASE("m:run refuses a relative tolerance outside (0, 1)") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-test-run-verdict-refused";
  for (const char* bad : {"relative = 0", "relative = 1", "relative = -1e-6", "relative = 1e-6, tolerance = 0"}) {
    std::string error;
    const int rc = test::run_scene_in(dir, std::string(R"(
      local m = tendril.model()
      m:cable(m:particle{ 0, 0, 0 }, m:particle{ 1, 0, 0 }, { EA = 1e3 })
      m:run{ )") + bad + " }\n",
                                      &error);
    CAPTURE(bad);
    CHECK(rc == 1);
    const std::string key = std::string(bad).find("tolerance") != std::string::npos ? "tolerance" : "relative";
    CHECK(error.find("run: '" + key + "' must be > 0") != std::string::npos);
  }
}
