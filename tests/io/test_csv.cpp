// The one CSV routine: fields with commas, quotes and line breaks survive a
// write and a read; the reader takes RFC 4180 text written elsewhere.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "io/csv.hpp"

using namespace tendril;

TEST_CASE("csv: plain fields stay bare, the others are quoted with their quotes doubled") {
  CHECK(csv_field("0.25") == "0.25");
  CHECK(csv_field("") == "");
  CHECK(csv_field("a,b") == "\"a,b\"");
  CHECK(csv_field("say \"hi\"") == "\"say \"\"hi\"\"\"");
  CHECK(csv_field("two\nlines") == "\"two\nlines\"");
  CHECK(csv_line({"run", "a,b", "3"}) == "run,\"a,b\",3");
}

TEST_CASE("csv: what csv_line writes, parse_csv reads back field for field") {
  const std::vector<std::vector<std::string>> rows{
      {"run", "label", "seed", "error"},
      {"1", "beam, 3 DOF", "7", ""},
      {"2", "\"quoted\"", "8", "scene.lua:4: beam: unknown key 'segmnts'\nstack traceback:\n\t[C]: in ?"},
      {"3", ",", "", "\""}};
  std::string text;
  for (const auto& r : rows) text += csv_line(r) + "\n";
  const auto back = parse_csv(text);
  REQUIRE(back.size() == rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) CHECK(back[k] == rows[k]);
}

TEST_CASE("csv: RFC 4180 text with CRLF line ends, empty fields and no final line break") {
  const auto rows = parse_csv("a,b,c\r\n1,,\"x\"\"y\"\r\n\"p\r\nq\",2,3");
  REQUIRE(rows.size() == 3);
  CHECK(rows[0] == std::vector<std::string>{"a", "b", "c"});
  CHECK(rows[1] == std::vector<std::string>{"1", "", "x\"y"});
  CHECK(rows[2] == std::vector<std::string>{"p\r\nq", "2", "3"});
}

TEST_CASE("csv: an unterminated quote is an error naming its line") {
  CHECK_THROWS_WITH_AS(parse_csv("a,b\n1,\"open\n2,3\n"), "CSV: the quote opened on line 2 is never closed",
                       std::runtime_error);
}
