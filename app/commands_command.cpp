// `tendril commands`: every command a scene, a journal or the studio can
// apply, made from their declarations (command/): the text of
// docs/commands.md, or with --json the declarations for a front end's
// palette.
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "command/json_form.hpp"
#include "command/listing.hpp"

namespace tendril::app {

Command commands_command() {
  return {"commands", "lists the commands on a model with their arguments (docs/commands.md)", [](CLI::App& cli) {
            auto json = std::make_shared<bool>(false);
            cli.add_flag("--json", *json, "the declarations as JSON (name, kind, parameters with types and ranges)");
            return [json] {
              const std::string text = *json ? command::declarations_json().dump(1) + "\n" : command::markdown_listing();
              std::fwrite(text.data(), 1, text.size(), stdout);
              return int(kOk);
            };
          }};
}

}  // namespace tendril::app
