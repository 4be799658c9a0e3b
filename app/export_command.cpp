// `tendril export --ccx FILE MODEL`: a model database (m:save) as a CalculiX
// input deck (io/ccx.hpp, docs/calculix.md), for a model saved in the state
// to analyse (CST patches in analysis, beams at the rest shape wanted).
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "io/ccx.hpp"
#include "io/model_xml.hpp"
#include "physics/solver.hpp"

namespace tendril::app {

namespace {

int export_ccx(const std::string& model_path, const std::string& deck) {
  Model model;
  SolverSettings settings;
  load_model_xml(model_path, model, settings);
  save_ccx(model, deck);
  std::printf("%s: %zu particles, %zu blocks -> %s\n", model_path.c_str(), model.particle_count(),
              model.block_count(), deck.c_str());
  return kOk;
}

}  // namespace

Command export_command() {
  return {"export", "writes a model database (m:save) as a CalculiX input deck (docs/calculix.md)",
          [](CLI::App& cli) {
            auto model = std::make_shared<std::string>();
            auto deck = std::make_shared<std::string>();
            cli.add_option("--ccx", *deck, "the CalculiX deck to write (ccx -i NAME reads NAME.inp)")
                ->required()
                ->type_name("FILE");
            cli.add_option("model", *model, "a model database written by m:save")
                ->required()
                ->check(CLI::ExistingPath)
                ->type_name("MODEL");
            return [model, deck] { return export_ccx(*model, *deck); };
          }};
}

}  // namespace tendril::app
