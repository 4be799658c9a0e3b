// Handles shared by the Lua bindings: the model userdata and particle and
// block handles with (id, generation).
#include "lua_scene.hpp"

#include "lua_args.hpp"

namespace tendril::lua {


const SceneOptions* g_options = nullptr;
SceneReport* g_report = nullptr;

Scene& check_scene(lua_State* L, const char* fn) {
  auto* s = static_cast<Scene**>(luaL_testudata(L, 1, kModelMeta));
  if (!s || !*s) arg_error(fn, 1, "expected a model (call it as m:" + std::string(fn) + "(...))");
  return **s;
}

ParticleId check_particle(lua_State* L, int idx, Scene& scene, const char* fn) {
  auto* h = static_cast<Handle*>(luaL_testudata(L, idx, kParticleMeta));
  if (!h) arg_error(fn, idx, std::string("expected a particle, got ") + luaL_typename(L, idx));
  if (h->scene != &scene) arg_error(fn, idx, "the particle belongs to another model");
  const Particles& P = scene.model.particles;
  if (!P.valid(h->id) || P.generation[h->id] != h->generation)
    arg_error(fn, idx, "particle " + std::to_string(h->id) + " was deleted");
  return h->id;
}

BlockId check_block(lua_State* L, int idx, Scene& scene, const char* fn) {
  auto* h = static_cast<Handle*>(luaL_testudata(L, idx, kBlockMeta));
  if (!h) arg_error(fn, idx, std::string("expected a block, got ") + luaL_typename(L, idx));
  if (h->scene != &scene) arg_error(fn, idx, "the block belongs to another model");
  if (!scene.model.block_valid(h->id) || scene.model.blocks[h->id].generation != h->generation)
    arg_error(fn, idx, "block " + std::to_string(h->id) + " was deleted");
  return h->id;
}

void push_handle(lua_State* L, int model_idx, const char* meta, Scene& scene, std::uint32_t id, std::uint32_t gen) {
  model_idx = lua_absindex(L, model_idx);
  auto* h = static_cast<Handle*>(lua_newuserdatauv(L, sizeof(Handle), 1));
  *h = Handle{&scene, id, gen};
  luaL_setmetatable(L, meta);
  lua_pushvalue(L, model_idx);  // keeps the model alive while the handle lives
  lua_setiuservalue(L, -2, 1);
}

void push_particle(lua_State* L, Scene& s, ParticleId p) {
  push_handle(L, 1, kParticleMeta, s, p, s.model.particles.generation[p]);
}

void push_block(lua_State* L, Scene& s, BlockId b) {
  push_handle(L, 1, kBlockMeta, s, b, s.model.blocks[b].generation);
}

std::vector<ParticleId> check_particle_list(lua_State* L, int idx, Scene& s, const char* fn) {
  idx = lua_absindex(L, idx);
  check_table(L, idx, fn);
  std::vector<ParticleId> out;
  const lua_Integer n = lua_rawlen(L, idx);
  for (lua_Integer k = 1; k <= n; ++k) {
    lua_rawgeti(L, idx, k);
    auto* h = static_cast<Handle*>(luaL_testudata(L, -1, kParticleMeta));
    lua_pop(L, 1);
    if (!h) arg_error(fn, int(idx), "entry " + std::to_string(k) + " is not a particle");
    lua_rawgeti(L, idx, k);
    try {
      out.push_back(check_particle(L, lua_gettop(L), s, fn));
    } catch (...) {
      lua_pop(L, 1);
      throw;
    }
    lua_pop(L, 1);
  }
  return out;
}

}  // namespace tendril::lua
