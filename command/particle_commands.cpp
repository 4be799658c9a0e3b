// Settings of one particle: supports, roles, multi-resolution, loads,
// masses and positions.
#include "command/declare.hpp"
#include "model/limits.hpp"

namespace tendril::command {

namespace {
const Param kParticle{"particle", Type::Particle, "a particle"};
}

void declare_particle_settings(std::vector<Command>& out) {
  out.push_back({"lock", "a particle's supports: bits x=1 y=2 z=4 (translation), 8 16 32 (rotation about x y z)",
                 Effect::Setting, {kParticle, {"bits", Type::Count, "the locked axes", {0, 63}}}, Returns::Nothing,
                 [](Target& t, Args& a) {
                   t.model.set_lock(particle(a, 0), std::uint8_t(a[1].id));
                   return nothing();
                 }});
  out.push_back({"role", "a particle's role for agents: 0 none, 1 parent, 2 child, 3 volatile", Effect::Setting,
                 {kParticle, {"role", Type::Count, "the role", {0, double(Role::Volatile)}}}, Returns::Nothing,
                 [](Target& t, Args& a) {
                   t.model.set_role(particle(a, 0), Role(a[1].id));
                   return nothing();
                 }});
  out.push_back({"passive", "freezes a particle and its elements, or wakes them (thesis 5.5.2.3)", Effect::Setting,
                 {kParticle, {"passive", Type::Flag, "frozen"}}, Returns::Nothing, [](Target& t, Args& a) {
                   t.model.set_passive(particle(a, 0), a[1].id != 0);
                   return nothing();
                 }});
  out.push_back({"load", "an external force on a particle [N]", Effect::Setting,
                 {kParticle, {"force", Type::Vector, "the force [N]"}}, Returns::Nothing, [](Target& t, Args& a) {
                   t.model.set_load(particle(a, 0), a[1].vector);
                   return nothing();
                 }});
  out.push_back({"mass", "a point mass on a particle [kg] (its mass is this plus what its elements lump)",
                 Effect::Setting, {kParticle, {"kg", Type::Number, "the point mass [kg]", {0, kInf}}}, Returns::Nothing,
                 [](Target& t, Args& a) {
                   t.model.set_point_mass(particle(a, 0), a[1].number);
                   return nothing();
                 },
                 1, Returns::Number,
                 [](Target& t, const Args& a) { return number_result(t.model.particles.mass(particle(a, 0))); }});
  Command position{"position", "moves a particle (its velocity stays)", Effect::Setting,
                   {kParticle, {"x", Type::Vector, "the position [m]", {-kMaxCoordinate, kMaxCoordinate}}},
                   Returns::Nothing, [](Target& t, Args& a) {
                     t.model.particles.position[particle(a, 0)] = a[1].vector;
                     return nothing();
                   }};
  position.lua = "set_position";
  out.push_back(std::move(position));
}

}  // namespace tendril::command
