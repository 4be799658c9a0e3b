#pragma once
// tendril.csv_line(fields): the CSV routine of io/csv.hpp for scenes and
// tendril.report, so a string with a comma stays in its column.
#include <lua.hpp>

namespace tendril::lua {

// Adds csv_line to the `tendril` table on top of the stack.
void add_csv(lua_State* L);

}  // namespace tendril::lua
