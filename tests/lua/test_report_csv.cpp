// tendril.report writes summary.csv through the one CSV routine: a string
// with a comma or a quote keeps its column when read back.
#include <doctest/doctest.h>

#include <map>

#include "io/csv.hpp"
#include "scene_files.hpp"

using namespace tendril;

TEST_CASE("tendril.report: a reported string with commas and quotes stays in its column") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-test-report-csv";
  std::filesystem::remove_all(dir);
  std::string error;
  REQUIRE(test::run_scene_in(dir, R"(
    local m = tendril.model()
    m:cable(m:particle{ 0, 0, 0 }, m:particle{ 2, 0, 0 }, { EA = 1e3 })
    tendril.report(m, { label = 'rod, "GFRP", 12 mm', zeta = 3 })
  )", &error) == 0);
  const auto rows = parse_csv(test::slurp(dir / "summary.csv"));
  REQUIRE(rows.size() == 2);
  REQUIRE(rows[0].size() == rows[1].size());
  std::map<std::string, std::string> row;
  for (std::size_t k = 0; k < rows[0].size(); ++k) row[rows[0][k]] = rows[1][k];
  CHECK(row["label"] == "rod, \"GFRP\", 12 mm");
  CHECK(row["zeta"] == "3");
  CHECK(row["cables"] == "1");
  CHECK(row["particles"] == "2");
}
