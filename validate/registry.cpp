#include "registry.hpp"

#include <algorithm>
#include <stdexcept>

namespace tendril::validate {

std::vector<Case> all_cases();  // case_list.cpp, generated from validate/cases/

namespace {

template <class T>
bool contains(const std::vector<T>& v, const T& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

// A case that cannot run its own defaults is a programming error: say which.
void check(const Case& c, const std::vector<Case>& before) {
  auto fail = [&](const std::string& what) { throw std::logic_error("validate case '" + c.name + "': " + what); };
  if (c.name.empty()) throw std::logic_error("validate: a case without a name");
  for (const Case& b : before)
    if (b.name == c.name) fail("registered twice");
  if (!c.run) fail("no run function");
  if (c.formulations.empty() || c.integrators.empty() || c.segments.empty() || c.quick_segments.empty())
    fail("needs formulations, integrators, segments and quick_segments");
  if (!contains(c.formulations, c.defaults.formulation)) fail("default formulation is not in its formulations");
  if (!contains(c.integrators, c.defaults.solver.integrator)) fail("default integrator is not in its integrators");
  if (!contains(c.segments, c.defaults.segments) || !contains(c.quick_segments, c.defaults.segments))
    fail("default segments missing from segments or quick_segments");
  if (!(c.tolerance > 0)) fail("tolerance must be positive");
}

std::vector<Case> checked_cases() {
  std::vector<Case> all = all_cases();
  for (std::size_t i = 0; i < all.size(); ++i) check(all[i], {all.begin(), all.begin() + i});
  return all;
}

}  // namespace

const std::vector<Case>& cases() {
  static const std::vector<Case> all = checked_cases();
  return all;
}

const Case* find_case(std::string_view name) {
  for (const Case& c : cases())
    if (c.name == name) return &c;
  return nullptr;
}

}  // namespace tendril::validate
