// Journals written before the command registry (format 1, generated on
// 3b364af by tests/lua/journals/gen_*.lua) replay bit for bit: the model they
// rebuild is the one the scene ended with (v1-*.xml, read and written again
// so that later additions to the model database's format do not matter).
// v1-beams.xml was replayed again when a moment on a particle without
// rotations began to act (issue 12: as couples across its 3-DOF beam
// segments, where it used to be ignored): its beam keeps m:torque after
// switching to 3 DOF, and only that beam's particles moved.
// v1-goals.xml was replayed again when projective dynamics began to follow
// a goal's new weight and a removed goal with a low-rank correction of its
// factor at the factorisation's positions (issue 18), where it used to
// factor again at the current ones: particles 1 and 2, still moving after
// the journal's 110 projective steps, moved by up to 1.1e-6 m.
// v1-patches.xml was replayed again when a particle's lumped mass began to
// keep its rounding error and fold it in after a cancellation (issue 13:
// masses removed to nothing now leave 0, not their rounding): five z
// coordinates moved by up to 3.5e-18 m.
// v1-patches.xml's solver reads vie_iterations="0" since that became the
// default (issue 18: the solver chooses; the journal never set it, and its
// leapfrog steps do not read it).
// v1-beams.xml and v1-patches.xml were replayed again when the hinges
// began to multiply by the reciprocals of their links' lengths instead of
// dividing by them (issue 18, stop 38, model/hinge_curvature.hpp):
// positions moved by up to 1.1e-19 m (beams) and 2.2e-16 m (patches).
// v1-goals.xml was replayed again when projective dynamics' low-rank
// correction moved between the halves of its factor's solve (issue 18,
// stop 46, low_rank_solve.hpp): positions moved by up to 3.1e-16 m and
// velocities by up to 4.9e-16 m/s.
// The v1-*.xml roots carry the steps and simulated time the journals
// integrate since the model database keeps them (issue 14).
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "scene_files.hpp"

using namespace tendril;

namespace {

const std::filesystem::path kJournals = std::filesystem::path(TENDRIL_SOURCE_DIR) / "tests/lua/journals";

// The model database file as the current writer writes it.
std::string rewritten(const std::filesystem::path& xml) {
  Model model;
  Solver solver(model);
  load_model_xml(xml.string(), model, solver.settings);
  return model_xml_string(model, solver.settings);
}

// `open base.xml` in a format-1 journal is resolved against the working folder.
struct InFolder {
  std::filesystem::path before = std::filesystem::current_path();
  explicit InFolder(const std::filesystem::path& dir) { std::filesystem::current_path(dir); }
  ~InFolder() { std::filesystem::current_path(before); }
};

}  // namespace

TEST_CASE("format-1 journals replay bit for bit") {
  for (const char* name : {"beams", "patches", "goals"}) {
    CAPTURE(name);
    InFolder here(kJournals);
    test::Replayed replayed(kJournals / (std::string("v1-") + name + ".journal"));
    CHECK(replayed.model.check() == "");
    CHECK(replayed.xml() == rewritten(kJournals / (std::string("v1-") + name + ".xml")));
  }
}
