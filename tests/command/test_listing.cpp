// The docs agree with the registry: docs/commands.md is the generated
// listing, and docs/lua-api.md documents every command's Lua method.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "command/listing.hpp"
#include "command/registry.hpp"

using namespace tendril;

namespace {

std::string doc(const char* name) {
  std::ifstream in(std::filesystem::path(TENDRIL_SOURCE_DIR) / "docs" / name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("docs/commands.md is the listing the declarations make (build/tendril commands > docs/commands.md)") {
  CHECK(doc("commands.md") == command::markdown_listing());
}

TEST_CASE("docs/lua-api.md documents the Lua method of every command") {
  const std::string api = doc("lua-api.md");
  for (const command::Command& c : command::commands()) {
    const std::string method = command::lua_method(c);
    if (method.empty()) continue;
    CAPTURE(method);
    CHECK((api.find("`" + method + "(") != std::string::npos || api.find("`" + method + "{") != std::string::npos));
  }
}

TEST_CASE("every parameter is documented, and names are unique") {
  std::set<std::string> names;
  for (const command::Command& c : command::commands()) {
    CAPTURE(std::string(c.name));
    CHECK(names.insert(c.name).second);
    CHECK(std::string(c.summary).size() > 10);
    std::set<std::string> params;
    for (const command::Param& p : c.params) {
      CHECK(params.insert(p.name).second);
      CHECK((std::string(p.doc).size() > 0 || !p.choices.empty()));
    }
  }
}
