// `tendril studio SCENE.lua`: the scene runs and keeps integrating on a
// solver thread while a page watches and rewrites it (docs/studio.md);
// Ctrl-C saves the model, journal and OBJ and exits.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <limits>
#include <memory>
#include <thread>

#include "agents_library.hpp"
#include "command.hpp"
#include "server.hpp"
#include "session.hpp"

namespace tendril::app {

namespace {

std::atomic<bool> g_interrupted{false};

void on_signal(int) { g_interrupted = true; }

struct StudioArguments {
  studio::SessionOptions session;
  studio::ServerOptions server;
  std::vector<std::string> params;
  bool no_wait = false;
};

int run(StudioArguments& a) {
  using namespace tendril::studio;
  for (const std::string& p : a.params) a.session.run.params.push_back(split_param(p));
  a.session.run.preload = agents_library();
  a.session.wait_for_page = !a.no_wait;
  Session* live = nullptr;
  try {
    Server web(
        a.server, [&](ClientId c, json cmd) { live->post(c, std::move(cmd)); }, Session::is_command);
    Session s(a.session, web);
    live = &s;
    std::signal(SIGINT, on_signal);
    std::signal(SIGTERM, on_signal);
    std::printf("tendril studio: %s\ntendril studio: open %s   (Ctrl-C saves into %s/ and stops)\n",
                a.session.scene.c_str(), web.url().c_str(), a.session.run.out_dir.c_str());
    std::fflush(stdout);
    int status = kOk;
    std::thread solver([&] { status = s.run(); });
    while (!g_interrupted) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    s.stop();
    solver.join();
    live = nullptr;
    return status;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tendril studio: %s\n", e.what());
    return kSceneError;
  }
}

}  // namespace

Command studio_command() {
  return {"studio", "runs a scene live in the browser: watch, drag, apply rules, scrub the journal (docs/studio.md)",
          [](CLI::App& cli) {
            auto a = std::make_shared<StudioArguments>();
            a->server.web_dir = TENDRIL_WEB_DIR;
            add_scene(cli, a->session.scene);
            cli.add_option("--port", a->server.port, "port to listen on; 0: any free one")
                ->check(CLI::Range(0, 65535))
                ->capture_default_str();
            cli.add_option_function<std::string>(
                   "--host",
                   [a](const std::string& h) {
                     a->server.host = h;
                     a->server.token = true;  // an address given by hand: the URL's token is required
                   },
                   "listen on this address instead of 127.0.0.1; the printed URL then carries a token")
                ->type_name("ADDRESS");
            cli.add_option("--param", a->params, "a value for tendril.param(NAME, default) (repeatable)")
                ->type_name("NAME=VALUE")
                ->expected(1)
                ->take_all();
            add_integer(cli, "--seed", a->session.run.seed, std::numeric_limits<std::int64_t>::min(),
                        std::numeric_limits<std::int64_t>::max(), "seeds math.random; tendril.seed reads it")
                ->capture_default_str();
            cli.add_option("--out", a->session.run.out_dir, "where Ctrl-C and the page's save write model.xml, model.obj, journal.txt")
                ->type_name("DIR")
                ->capture_default_str();
            cli.add_option("--tolerance", a->session.tolerance, "residual [N] at which the live model is at equilibrium")
                ->check(CLI::PositiveNumber)
                ->capture_default_str();
            cli.add_option("--speed", a->session.speed, "at most this many solver steps per second (0: no limit)")
                ->check(CLI::NonNegativeNumber)
                ->capture_default_str();
            cli.add_flag("--no-wait", a->no_wait, "start the scene at once, not when the first page connects");
            cli.add_option("--web", a->server.web_dir, "the built page (web/dist)")->type_name("DIR");
            return [a] { return run(*a); };
          }};
}

}  // namespace tendril::app
