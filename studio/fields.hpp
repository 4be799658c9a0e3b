#pragma once
// The colour maps the page offers: one value per drawn edge (frames.hpp),
// computed on the solver thread for the frame that carries it; NaN where the
// quantity does not apply (a cable's bending moment), drawn uncoloured. A new map is
// one entry in fields() (fields.cpp); the page lists them with their units.
#include <string>
#include <vector>

#include "frames.hpp"

namespace tendril::studio {

struct Field {
  std::string name;  // as the page shows it and asks for it
  std::string unit;
  std::vector<float> (*values)(const Model& m, const Topology& t);
};

const std::vector<Field>& fields();
// The field called name, or nullptr.
const Field* find_field(const std::string& name);

}  // namespace tendril::studio
