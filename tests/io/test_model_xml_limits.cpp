// Issue 13: what a hostile model database can do to the reader. Each file is
// the smallest that hung it, crashed it or made it answer wrongly before.
#include <doctest/doctest.h>

#include <string>

#include "io/model_xml.hpp"

using namespace tendril;

namespace {

// Loads `xml` into a fresh model; returns the error ("" when it loaded).
std::string load(const std::string& xml) {
  Model m;
  SolverSettings s;
  try {
    load_model_xml_string(xml, m, s, "hostile.xml");
  } catch (const ModelError& e) {
    return e.what();
  }
  return "";
}

std::string with_particle(const std::string& attributes) {
  return "<tendril version=\"1\"><particles><particle " + attributes + "/></particles></tendril>";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("solver settings beyond what m:settings takes are refused (vie_iterations = 2^31 hung the first step)") {
  const std::string error = load("<tendril version=\"1\"><solver vie_iterations=\"2147483648\"/></tendril>");
  CHECK(error == "hostile.xml:1: <solver>: attribute 'vie_iterations' must be a whole number from 0 (the solver chooses) to 1000");
  CHECK(contains(load("<tendril version=\"1\"><solver vie_iterations=\"1e300\"/></tendril>"), "to 1000"));
  CHECK(contains(load("<tendril version=\"1\"><solver viscous=\"5\"/></tendril>"), "'viscous' must be in [0, 2)"));
  CHECK(load("<tendril version=\"1\"><solver vie_iterations=\"1000\"/></tendril>") == "");
}

TEST_CASE("an element with 40 000 attributes is refused before tinyxml2 spends minutes on it") {
  std::string attributes;
  for (int k = 0; k < 40000; ++k) attributes += " a" + std::to_string(k) + "=\"1\"";
  const std::string error = load("<tendril version=\"1\">\n<particles>\n<particle" + attributes + "/></particles></tendril>");
  CHECK(error == "hostile.xml:3: an element with more than 64 attributes; no element of a model database has more than 24");
  // '=' inside quoted values, comments and CDATA are not attributes.
  CHECK(contains(load("<tendril version=\"1\"><!--" + attributes + "--><particles><particle id=\"0\" x=\"0\" y=\"0\" "
                      "z=\"0\" role=\"" + std::string(100, '=') + "\"/></particles></tendril>"),
                 "attribute 'role' is not a non-negative integer"));
}

TEST_CASE("error messages quote at most 40 characters of a value, however long") {
  const std::string error = load(with_particle("id=\"0\" x=\"" + std::string(50'000'000, '7') + "x\" y=\"0\" z=\"0\""));
  CHECK(error == "hostile.xml:1: <particle id=\"0\">: attribute 'x' is not a number: \"77777777777777777777777777777777... "
                 "(50000001 characters)\"");
  const std::string name = load("<tendril version=\"1\"><" + std::string(1000, 'q') + "/></tendril>");
  CHECK(name.size() < 200);
}

TEST_CASE("a number out of a double's range is called what it is") {
  CHECK(load(with_particle("id=\"0\" x=\"1e-400\" y=\"0\" z=\"0\"")) ==
        "hostile.xml:1: <particle id=\"0\">: attribute 'x' is too small for a double (nonzero, below 4.9e-324): "
        "\"1e-400\"");
  CHECK(load(with_particle("id=\"0\" x=\"1e400\" y=\"0\" z=\"0\"")) ==
        "hostile.xml:1: <particle id=\"0\">: attribute 'x' is too large for a double (above 1.8e308): \"1e400\"");
  CHECK(load(with_particle("id=\"0\" x=\"4.9406564584124654e-324\" y=\"0\" z=\"0\"")) == "");  // a denormal is fine
}

TEST_CASE("coordinates beyond 1e12 m are refused (above 1e154 a rest length overflowed to infinity)") {
  const std::string error = load(with_particle("id=\"0\" x=\"1e155\" y=\"0\" z=\"0\""));
  CHECK(error == "hostile.xml:1: <particle id=\"0\">: add_particle: position (1e+155, 0, 0) is beyond 1e+12 m from the origin");
}
