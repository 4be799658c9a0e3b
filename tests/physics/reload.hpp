#pragma once
// A model written to the model database and read back, for the tests of
// what the database keeps: the loaded model must write the same file.
#include <doctest/doctest.h>

#include <string>

#include "io/model_xml.hpp"

namespace tendril::test {

// Loads m's database text (named `name` in messages) into `loaded` and
// returns the text.
inline std::string reload(const Model& m, Model& loaded, const char* name) {
  SolverSettings settings;
  const std::string text = model_xml_string(m, settings);
  load_model_xml_string(text, loaded, settings, name);
  CHECK(model_xml_string(loaded, settings) == text);
  return text;
}

}  // namespace tendril::test
