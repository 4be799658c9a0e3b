// `tendril replay JOURNAL`: rebuilds a model from a journal written by
// m:save_journal (docs/rules.md), prints its assembly sequence and writes the
// model database and OBJ.
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <memory>

#include "command.hpp"
#include "io/input_file.hpp"
#include "io/model_xml.hpp"
#include "io/obj.hpp"
#include "command/replay.hpp"
#include "io/trace.hpp"

namespace tendril::app {

namespace {

// A journal's comment as the terminal shows it: control characters (an
// escape sequence, a carriage return that overwrites the line) written as
// \xHH, so a journal cannot drive the terminal or forge what it shows.
std::string printable(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (c >= 0x20 && c != 0x7f) out += char(c);
    else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  return out;
}

int replay(const std::string& journal, const std::string& out) {
  std::istringstream in(read_input_file(journal));
  Model model;
  Solver solver(model);
  replay_trace(in, journal, model, solver);
  std::filesystem::create_directories(out);
  save_model_xml(model, solver.settings, out + "/model.xml");
  save_obj(model, out + "/model.obj");
  in.clear();
  in.seekg(0);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("# ", 0) == 0) std::printf("%s\n", printable(line.substr(2)).c_str());
  std::printf("replayed %llu steps: %zu particles, %zu blocks -> %s/model.xml\n",
              static_cast<unsigned long long>(solver.steps()), model.particle_count(), model.block_count(),
              out.c_str());
  return kOk;
}

}  // namespace

Command replay_command() {
  return {"replay", "rebuilds a model from a journal (m:save_journal) and writes DIR/model.xml and DIR/model.obj",
          [](CLI::App& cli) {
            auto journal = std::make_shared<std::string>();
            auto out = std::make_shared<std::string>("out");
            cli.add_option("journal", *journal, "a journal written by m:save_journal")
                ->required()
                ->check(CLI::ExistingPath)
                ->type_name("JOURNAL");
            cli.add_option("--out", *out, "directory for model.xml and model.obj")
                ->type_name("DIR")
                ->capture_default_str();
            return [journal, out] { return replay(*journal, *out); };
          }};
}

}  // namespace tendril::app
