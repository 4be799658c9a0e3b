// Sections from Lua option tables (lua_section_args.hpp).
#include "lua_section_args.hpp"

#include "lua_args.hpp"

namespace tendril::lua {

using command::Value;

// Section from {EA=, EI=} or {E=, A=, I=}, plus prestress and line_mass.
Section read_section(lua_State* L, int idx, const char* fn, bool beam) {
  Section s;
  const bool by_products = has_field(L, idx, "EA") || has_field(L, idx, "EI");
  const bool by_modulus = has_field(L, idx, "E");
  if (by_products && by_modulus) throw LuaArgError(std::string(fn) + ": give EA/EI or E with A/I, not both");
  if (by_modulus) {
    const double E = field_number(L, idx, "E", fn, 0);
    if (!has_field(L, idx, "A")) key_error(fn, "A", "is required with E");
    s.EA = E * field_number(L, idx, "A", fn, 0);
    if (beam) {
      if (!has_field(L, idx, "I")) key_error(fn, "I", "is required with E for a beam");
      s.EI = E * field_number(L, idx, "I", fn, 0);
    }
  } else {
    if (!has_field(L, idx, "EA")) key_error(fn, "EA", "is required (or E with A)");
    s.EA = field_number(L, idx, "EA", fn, 0);
    if (beam) {
      if (!has_field(L, idx, "EI")) key_error(fn, "EI", "is required for a beam (or E with I)");
      s.EI = field_number(L, idx, "EI", fn, 0);
    }
  }
  s.prestress = field_number(L, idx, "prestress", fn, 0);
  s.line_mass = field_number(L, idx, "line_mass", fn, 0);
  return s;
}

// A section as the command's four section arguments (EA, EI, prestress, line_mass).
void append_section(command::Args& args, const Section& sec) {
  for (double x : {sec.EA, sec.EI, sec.prestress, sec.line_mass}) args.push_back(Value::of_number(x));
}

}  // namespace tendril::lua
