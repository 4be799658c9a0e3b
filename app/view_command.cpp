// `tendril view OUT_DIR | model.xml | journal.txt -o page.html`: one
// self-contained HTML file showing the model, its growth timeline and its
// colour maps (docs/studio.md), to open anywhere without a server.
#include <cstdio>
#include <memory>

#include "command.hpp"
#include "io/atomic_file.hpp"
#include "static_view.hpp"

namespace tendril::app {

namespace {

struct ViewArguments {
  std::string input, output = "view.html", web_dir = TENDRIL_WEB_DIR;
  std::int64_t entries = 120;
};

int view(const ViewArguments& a) {
  const std::string html = studio::static_view(a.input, a.web_dir, std::size_t(a.entries));
  write_file_atomically(a.output, html);
  std::printf("tendril view: %s -> %s (%.1f MB)\n", a.input.c_str(), a.output.c_str(), html.size() / 1e6);
  return kOk;
}

}  // namespace

Command view_command() {
  return {"view", "writes one self-contained HTML page of a model and its growth timeline (docs/studio.md)",
          [](CLI::App& cli) {
            auto a = std::make_shared<ViewArguments>();
            cli.add_option("input", a->input, "an output folder, a model database (.xml) or a journal")
                ->required()
                ->check(CLI::ExistingPath)
                ->type_name("OUT_DIR|MODEL.xml|JOURNAL");
            cli.add_option("-o,--output", a->output, "the HTML file to write")->type_name("PAGE.html")->capture_default_str();
            add_integer(cli, "--entries", a->entries, 1, 100000, "at most this many models in the timeline")
                ->capture_default_str();
            cli.add_option("--web", a->web_dir, "the built page (web/dist)")->type_name("DIR");
            return [a] { return view(*a); };
          }};
}

}  // namespace tendril::app
