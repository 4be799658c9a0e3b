#pragma once
// CSV as RFC 4180 has it: a field holding a comma, a quote or a line break is
// quoted and its quotes doubled. Every CSV tendril writes (summary.csv,
// sweep.csv, validate's table) goes through csv_line, and parse_csv reads
// them back, so a comma in a reported string never shifts a column.
#include <string>
#include <string_view>
#include <vector>

namespace tendril {

std::string csv_field(std::string_view field);
// The fields quoted where needed and joined by commas, without a line break.
std::string csv_line(const std::vector<std::string>& fields);
// Rows of fields; a line break inside quotes belongs to its field. Throws
// std::runtime_error naming the line where an unterminated quote began.
std::vector<std::vector<std::string>> parse_csv(std::string_view text);

}  // namespace tendril
