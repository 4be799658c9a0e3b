// libFuzzer target: the command layer (command/). The bytes choose a
// sequence of commands and their arguments - live ids or stale ones, values
// in range or not, NaN, infinities, huge counts - applied to a small model
// either typed (command::apply) or through their JSON form (to_json, text,
// from_json), as the studio's messages are. After every command:
//   - a refused command (CommandError; ModelError but from a step) changed nothing: the
//     model database text, the trace and the journal are as they were;
//   - the model is valid (Model::check() is empty);
// and at the end the trace of what was applied replays on an empty model to
// the same model database text, bit for bit. Any violation aborts.
// `open` is left out (it reads another file), and the steps are bounded (a
// journal's steps cost what they say; 32 in all here), as are the counts
// that only size a production (segments, rows): costs, not faults.
// FUZZ_COMMANDS_VERBOSE=1 prints each command and what became of it.
#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command/json_form.hpp"
#include "command/registry.hpp"
#include "command/replay.hpp"
#include "command/session.hpp"
#include "io/model_xml.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using command::Args;
using command::Value;

namespace {

[[noreturn]] void fail(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz_commands: %s\n%s\n", what, detail.c_str());
  std::abort();
}

struct Bench {
  Model model;
  Solver solver{model};
  Trace trace;
  Journal journal;
  command::Session session{model, solver, &trace, &journal};

  std::string xml() const { return model_xml_string(model, solver.settings); }
  std::string trace_text() const {
    std::string out;
    for (const std::string& line : trace.lines(solver)) out += line + "\n";
    return out;
  }
  std::vector<std::uint32_t> particles() const {
    std::vector<std::uint32_t> out;
    for (ParticleId p = 0; p < model.particles.capacity(); ++p)
      if (model.particles.valid(p)) out.push_back(p);
    return out;
  }
};

Value number(double x) { return Value::of_number(x); }
Value id(std::uint64_t i) { return Value::of_id(i); }

// The small model every input starts from, built through the commands (so
// that the trace holds it): a beam, a cable, a 3 x 3 patch, a joint-free
// corner; gravity on.
void build(Bench& b) {
  auto run = [&](const char* name, Args a) { return command::apply(b.session, name, std::move(a)); };
  auto particle = [&](double x, double y, double z) {
    return run("particle", {Value::of_vector(Vec3(x, y, z))}).ids[0];
  };
  const Args section{number(1e4), number(10), number(0), number(0)};
  auto with_section = [&](Args head, Args tail) {
    head.insert(head.end(), section.begin(), section.end());
    head.insert(head.end(), tail.begin(), tail.end());
    return head;
  };
  const std::uint32_t a = particle(0, 0, 0), m = particle(1, 0, 0.2), e = particle(2, 0, 0);
  run("beam", with_section({id(0)}, {Value::of_ids({a, m, e})}));
  run("lock", {id(a), id(7)});
  run("lock", {id(e), id(7)});
  const std::uint32_t c = particle(1, 1, 1);
  run("cable", with_section({id(m), id(c)}, {number(0)}));
  std::vector<std::uint32_t> grid;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) grid.push_back(particle(j, i + 3, 0));
  run("quad_grid", with_section({id(3), id(3)}, {Value::of_ids(grid)}));
  run("lock", {id(grid[0]), id(7)});
  run("gravity", {Value::of_vector(Vec3(0, 0, -9.81))});
}

class Chooser {
 public:
  Chooser(FuzzedDataProvider& in, const Bench& b) : in_(in), particles_(b.particles()), blocks_(b.model.live_blocks()),
                                                      goals_(b.model.goals.size()), joints_(b.model.joints.size()) {}

  Value value(const command::Param& p, std::uint64_t& steps_left) {
    if (p.optional && in_.ConsumeBool()) return Value::absent();
    const bool wrong = in_.ConsumeIntegralInRange(0, 15) == 0;
    switch (p.type) {
      case command::Type::Particle: return id(wrong ? stale() : pick(particles_));
      case command::Type::Block: return id(wrong ? stale() : pick(blocks_));
      case command::Type::Goal: return id(wrong ? stale() : in_.ConsumeIntegralInRange<std::uint64_t>(0, goals_));
      case command::Type::Joint: return id(wrong ? stale() : in_.ConsumeIntegralInRange<std::uint64_t>(0, joints_));
      case command::Type::Count:
        if (std::string(p.name) == "n") {  // steps
          const std::uint64_t n = std::min<std::uint64_t>(steps_left, in_.ConsumeIntegralInRange(0, 4));
          steps_left -= n;
          return id(n);
        }
        if (wrong) return id(huge_count());
        return id(in_.ConsumeIntegralInRange<std::uint64_t>(0, 8));
      case command::Type::Flag: return id(wrong ? in_.ConsumeIntegral<std::uint64_t>() : in_.ConsumeBool());
      case command::Type::Number: return number(real(wrong));
      case command::Type::Vector: return Value::of_vector(Vec3(real(wrong), real(false), real(false)));
      case command::Type::Word:
        if (wrong || p.choices.empty()) return Value::of_word(in_.ConsumeRandomLengthString(12));
        return Value::of_word(p.choices[in_.ConsumeIntegralInRange<std::size_t>(0, p.choices.size() - 1)]);
      case command::Type::Particles: {
        std::vector<std::uint32_t> list;
        const std::size_t n = in_.ConsumeIntegralInRange(0, 9);
        for (std::size_t k = 0; k < n; ++k)
          list.push_back(in_.ConsumeIntegralInRange(0, 15) == 0 ? std::uint32_t(stale()) : std::uint32_t(pick(particles_)));
        return Value::of_ids(std::move(list));
      }
      case command::Type::Path: return Value::of_word("no-such-file.xml");
    }
    return Value::absent();
  }

 private:
  std::uint64_t pick(const std::vector<std::uint32_t>& from) {
    if (from.empty()) return 0;
    return from[in_.ConsumeIntegralInRange<std::size_t>(0, from.size() - 1)];
  }
  std::uint64_t stale() {
    static constexpr std::uint64_t kStale[] = {999, 1u << 20, 0xffffffffu, std::uint64_t(1) << 32,
                                               std::numeric_limits<std::uint64_t>::max()};
    return in_.PickValueInArray(kStale);
  }
  std::uint64_t huge_count() {
    static constexpr std::uint64_t kHuge[] = {1000001, std::uint64_t(1) << 31, std::uint64_t(1) << 53,
                                              std::numeric_limits<std::uint64_t>::max()};
    return in_.PickValueInArray(kHuge);
  }
  // Ordinary values mostly; the edges of what a double holds when wrong.
  double real(bool wrong) {
    static constexpr double kEdges[] = {std::numeric_limits<double>::quiet_NaN(),
                                        std::numeric_limits<double>::infinity(),
                                        -std::numeric_limits<double>::infinity(),
                                        std::numeric_limits<double>::max(),
                                        std::numeric_limits<double>::denorm_min(),
                                        -0.0,
                                        1e12,
                                        1.0000001e12,
                                        -1e300,
                                        1e-300};
    if (wrong) return in_.PickValueInArray(kEdges);
    static constexpr double kUsual[] = {0, 1, -1, 0.5, 2, 10, 1e3, 1e4, 1e6};
    if (in_.ConsumeBool()) return in_.PickValueInArray(kUsual);
    return in_.ConsumeFloatingPointInRange(-10.0, 10.0);
  }

  FuzzedDataProvider& in_;
  std::vector<std::uint32_t> particles_;
  std::vector<std::uint32_t> blocks_;
  std::size_t goals_, joints_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::vector<const command::Command*> pool = [] {
    std::vector<const command::Command*> out;
    for (const command::Command& c : command::commands())
      if (std::string(c.name) != "open") out.push_back(&c);
    return out;
  }();
  static const bool verbose = std::getenv("FUZZ_COMMANDS_VERBOSE") != nullptr;  // each command, to stderr
  FuzzedDataProvider in(data, size);
  Bench b;
  build(b);
  std::uint64_t steps_left = 32;
  for (int k = 0; k < 32 && in.remaining_bytes() > 0; ++k) {
    const command::Command& c = *pool[in.ConsumeIntegralInRange<std::size_t>(0, pool.size() - 1)];
    const bool as_json = in.ConsumeBool();
    Args args;
    {
      Chooser choose(in, b);
      for (const command::Param& p : c.params) args.push_back(choose.value(p, steps_left));
    }
    if (verbose)
      std::fprintf(stderr, "  %s\n",
                   command::to_json(c, args).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace).c_str());
    const std::string before = b.xml();
    const std::size_t lines = b.trace.size(), entries = b.journal.entries.size();
    const std::uint64_t steps = b.solver.steps();
    std::string refused;
    try {
      if (as_json) {
        // JSON text is UTF-8: a word of other bytes goes as U+FFFD, as a
        // front end's JSON library would send it.
        const std::string message =
            command::to_json(c, args).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        const auto [back, decoded] = command::from_json(nlohmann::json::parse(message));
        if (back != &c) fail("the JSON form names another command", message);
        command::apply(b.session, *back, decoded);
      } else {
        command::apply(b.session, c, args);
      }
    } catch (const command::CommandError& e) {
      refused = e.what();
    } catch (const ModelError& e) {
      // A step that fails (a runaway, no stiffness) is no refusal: the steps
      // before it stand, and the failure is journaled (failed_step).
      if (c.effect != command::Effect::Steps) refused = e.what();
    }
    if (verbose)
      std::fprintf(stderr, "%s%s: %s\n", c.name, as_json ? " (JSON)" : "", refused.empty() ? "applied" : refused.c_str());
    if (!refused.empty()) {
      if (b.xml() != before) fail("a refused command changed the model", std::string(c.name) + ": " + refused);
      if (b.trace.size() != lines || b.solver.steps() != steps)
        fail("a refused command was traced", std::string(c.name) + ": " + refused);
      if (b.journal.entries.size() != entries) fail("a refused command was journaled", std::string(c.name) + ": " + refused);
    }
    const std::string problem = b.model.check();
    if (!problem.empty()) fail("the model is not valid", std::string(c.name) + ": " + problem);
  }
  const std::string journal = b.trace_text();
  Model again;
  Solver solver(again);
  std::istringstream lines(journal);
  try {
    replay_trace(lines, "fuzz.journal", again, solver);
  } catch (const ModelError& e) {
    fail("the trace of what was applied does not replay", std::string(e.what()) + "\n" + journal);
  }
  const std::string replayed = model_xml_string(again, solver.settings), built = b.xml();
  if (replayed != built) {
    // The first line that differs, then the journal.
    std::istringstream x(built), y(replayed);
    std::string a, c;
    while (std::getline(x, a) && std::getline(y, c) && a == c) {
    }
    fail("the replay differs from the model", "model:  " + a + "\nreplay: " + c + "\n" + journal);
  }
  return 0;
}
