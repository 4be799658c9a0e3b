#pragma once
// The scene behind a model userdata, and the handle helpers every binding
// uses. A handle to something deleted is refused, never aliased.
#include <lua.hpp>

#include <cstdint>
#include <vector>

#include "lua_host.hpp"
#include "command/session.hpp"
#include "folded_quads.hpp"
#include "io/trace.hpp"
#include "model/journal.hpp"
#include "model/model.hpp"
#include "physics/solver.hpp"
#include "query/neighbours.hpp"

namespace tendril::lua {

inline constexpr const char* kModelMeta = "tendril.Model";
inline constexpr const char* kParticleMeta = "tendril.Particle";
inline constexpr const char* kBlockMeta = "tendril.Block";

struct Trigger;  // lua_rules.cpp

struct Scene {
  Model model;
  Solver solver{model};
  Journal journal;
  Trace trace;  // the replayable record of every change (io/trace.hpp)
  // Every change goes through it (command/session.hpp): checked, applied, recorded.
  command::Session session{model, solver, &trace, &journal};
  // Rebuilt when the solver stepped or the trace grew since the last query.
  NeighbourIndex neighbours;
  std::pair<std::uint64_t, std::size_t> neighbours_built_at{~0ull, 0};
  std::vector<Trigger*> triggers;  // owned by lua_rules.cpp, freed with the scene
  const SceneOptions* options = nullptr;
  // The verdict of the model's last m:run{} (physics/run_verdict.hpp), or
  // "none": m:summary reports it, so tendril.report's summary.csv does.
  const char* last_verdict = "none";
  meshing::FoldedQuadCheck folded;  // what every m:run{} reports (its quads kept while the topology holds)
  ~Scene();
};

struct Handle {
  Scene* scene;
  std::uint32_t id;
  std::uint32_t generation;
};

extern const SceneOptions* g_options;  // set by open_tendril for the host's lifetime
extern SceneReport* g_report;          // set by run_scene for the host's lifetime

Scene& check_scene(lua_State* L, const char* fn);
ParticleId check_particle(lua_State* L, int idx, Scene& scene, const char* fn);
BlockId check_block(lua_State* L, int idx, Scene& scene, const char* fn);
// Handles keep the model userdata at stack index 1 alive.
void push_particle(lua_State* L, Scene& s, ParticleId p);
void push_block(lua_State* L, Scene& s, BlockId b);
std::vector<ParticleId> check_particle_list(lua_State* L, int idx, Scene& s, const char* fn);

}  // namespace tendril::lua
