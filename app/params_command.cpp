// `tendril params SCENE.lua`: the parameters a scene declares with
// tendril.param and their defaults, one a line, the values --param takes.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "scene_declarations.hpp"

namespace tendril::app {

Command params_command() {
  return {"params", "lists the parameters a scene declares (tendril.param) and their defaults", [](CLI::App& cli) {
            auto scene = std::make_shared<std::string>();
            add_scene(cli, *scene);
            return [scene] {
              const auto params = declared_params(*scene);
              std::size_t width = 0;
              for (const auto& p : params) width = std::max(width, p.name.size());
              for (const auto& p : params)
                std::printf("%-*s  %s\n", int(width), p.name.c_str(), p.default_value.c_str());
              return int(kOk);
            };
          }};
}

}  // namespace tendril::app
