#include "lua_readouts.hpp"

#include <cstdint>
#include <string>

#include "lua_args.hpp"
#include "lua_scene.hpp"

namespace tendril::lua {

namespace {

struct Readout {
  const char* name;
  enum Of { Model, Particle, Block } of;
  void (*push)(lua_State* L, Scene& s, std::uint32_t id);  // pushes one value
  const char* instead = nullptr;  // what changes it, for the error of a call that gives a value
};

const Readout kReadouts[] = {
    {"position", Readout::Particle, [](lua_State* L, Scene& s, std::uint32_t p) { push_vec3(L, s.model.particles.position[p]); },
     "m:set_position(p, {x, y, z}) moves a particle"},
    {"velocity", Readout::Particle, [](lua_State* L, Scene& s, std::uint32_t p) { push_vec3(L, s.model.particles.velocity[p]); }},
    {"reaction", Readout::Particle, [](lua_State* L, Scene& s, std::uint32_t p) { push_vec3(L, s.solver.reaction(p)); }},
    {"state", Readout::Particle,
     [](lua_State* L, Scene& s, std::uint32_t p) { lua_pushstring(L, state_name(s.model.state(p))); }},
    {"kind", Readout::Block,
     [](lua_State* L, Scene& s, std::uint32_t b) { lua_pushstring(L, block_kind_name(s.model.blocks[b].kind)); }},
    {"closed", Readout::Block, [](lua_State* L, Scene& s, std::uint32_t b) { lua_pushboolean(L, s.model.blocks[b].closed); }},
    {"residual", Readout::Model, [](lua_State* L, Scene& s, std::uint32_t) { lua_pushnumber(L, s.solver.residual()); }},
    {"steps", Readout::Model,
     [](lua_State* L, Scene& s, std::uint32_t) { lua_pushinteger(L, lua_Integer(s.model.steps)); }},
    {"time", Readout::Model, [](lua_State* L, Scene& s, std::uint32_t) { lua_pushnumber(L, s.model.time); }},
};

int l_readout(lua_State* L) {
  const Readout& r = *static_cast<const Readout*>(lua_touserdata(L, lua_upvalueindex(1)));
  Scene& s = check_scene(L, r.name);
  std::uint32_t id = 0;
  if (r.of == Readout::Particle) id = check_particle(L, 2, s, r.name);
  else if (r.of == Readout::Block) id = check_block(L, 2, s, r.name);
  // A readout takes no value: m:position(p, {1, 2, 3}) used to read and
  // ignore the point, the particle staying where it was.
  const int takes = r.of == Readout::Model ? 1 : 2;
  if (lua_gettop(L) > takes)
    arg_error(r.name, takes + 1, std::string("a readout takes no value") + (r.instead ? std::string("; ") + r.instead : ""));
  r.push(L, s, id);
  return 1;
}

}  // namespace

void add_readout_methods(lua_State* L) {
  for (const Readout& r : kReadouts) {
    lua_pushlightuserdata(L, const_cast<Readout*>(&r));
    lua_pushcclosure(L, guarded<l_readout>, 1);
    lua_setfield(L, -2, r.name);
  }
}

}  // namespace tendril::lua
