// Productions on particles, cables, beams and patches (rules 1-27): each
// creates, deletes or reconnects, and is a journal entry of its own.
#include "command/declare.hpp"

namespace tendril::command {

namespace {

const Param kParticle{"particle", Type::Particle, "a particle"};

Result particles_result(std::vector<ParticleId> ps) {
  Result r;
  r.kind = Returns::Particles;
  r.ids.assign(ps.begin(), ps.end());
  return r;
}

}  // namespace

void declare_topology(std::vector<Command>& out) {
  out.push_back({"particle", "rule 1: a new particle at x", Effect::Topology,
                 {{"x", Type::Vector, "position [m]"}}, Returns::Particle,
                 [](Target& t, Args& a) { return particle_result(t.model.add_particle(a[0].vector)); }});
  out.push_back({"delete_particle", "rule 2: deletes a particle and the blocks that need it", Effect::Topology,
                 {kParticle}, Returns::Nothing, [](Target& t, Args& a) {
                   t.model.delete_particle(particle(a, 0));
                   return nothing();
                 }});
  out.push_back({"merge", "rule 3: merges particles into the first; each reference remembers where it came from",
                 Effect::Topology, {{"particles", Type::Particles, "the particles to merge"}}, Returns::Particle,
                 [](Target& t, Args& a) { return particle_result(t.model.merge({a[0].ids.begin(), a[0].ids.end()})); }});
  out.push_back({"explode", "rule 4: one particle per reference of p (a merge reverted)", Effect::Topology, {kParticle},
                 Returns::Particles,
                 [](Target& t, Args& a) { return particles_result(t.model.explode(particle(a, 0))); }});
  out.push_back({"explode_from", "rule 5: detaches a block from a particle, on a particle of its own",
                 Effect::Topology, {kParticle, {"block", Type::Block, "a block at the particle"}}, Returns::Particle,
                 [](Target& t, Args& a) { return particle_result(t.model.explode_from(particle(a, 0), block(a, 1))); }});
  out.push_back({"cable", "rule 6: a tension-only cable between two particles", Effect::Topology,
                 with_section({{"a", Type::Particle, "one end"}, {"b", Type::Particle, "the other end"}},
                              {{"rest_length", Type::Number, "rest length [m]; 0: the current distance", {0, kMaxRestLength}}}),
                 Returns::Block, [](Target& t, Args& a) {
                   return block_result(t.model.add_cable(particle(a, 0), particle(a, 1), section_at(a, 2), a[6].number));
                 }});
  out.push_back({"bar", "rule 6: a two-way elastic bar (tension and compression) between two particles",
                 Effect::Topology,
                 with_section({{"a", Type::Particle, "one end"}, {"b", Type::Particle, "the other end"}},
                              {{"rest_length", Type::Number, "rest length [m]; 0: the current distance", {0, kMaxRestLength}}}),
                 Returns::Block, [](Target& t, Args& a) {
                   return block_result(
                       t.model.add_elastic_bar(particle(a, 0), particle(a, 1), section_at(a, 2), a[6].number));
                 }});
  out.push_back({"delete", "rules 7, 18, 27: deletes a cable, bar, beam or patch", Effect::Topology,
                 {{"block", Type::Block, "the block"}}, Returns::Nothing, [](Target& t, Args& a) {
                   Model& m = t.model;
                   const BlockId b = block(a, 0);
                   if (m.blocks[b].kind == BlockKind::Cable) m.delete_cable(b);
                   else if (m.blocks[b].kind == BlockKind::Bar) m.delete_elastic_bar(b);
                   else if (m.blocks[b].kind == BlockKind::Patch) m.delete_patch(b);
                   else m.delete_beam(b);
                   return nothing();
                 }});
  out.push_back({"beam", "rule 8: a spline beam through particles (a path, or a ring when closed)", Effect::Topology,
                 with_section({{"closed", Type::Flag, "a ring"}}, {{"particles", Type::Particles, "the particles in order"}}),
                 Returns::Block, [](Target& t, Args& a) {
                   return block_result(t.model.add_beam({a[5].ids.begin(), a[5].ids.end()}, section_at(a, 1), a[0].id != 0));
                 }});
  out.push_back({"extend", "rule 9: grows an open beam by one segment from its end to a particle", Effect::Topology,
                 {{"beam", Type::Block, "an open beam"}, {"end", Type::Particle, "the end to grow from"},
                  {"to", Type::Particle, "the new end"}},
                 Returns::Nothing, [](Target& t, Args& a) {
                   t.model.extend_beam(block(a, 0), particle(a, 1), particle(a, 2));
                   return nothing();
                 }});
  out.push_back({"beam_from", "rule 10: a beam from a particle along a span, in segments", Effect::Topology,
                 with_section({{"from", Type::Particle, "the start"},
                               {"span", Type::Vector, "the beam's full length and direction [m]"},
                               {"segments", Type::Count, "segments", {1, 1e6}}}),
                 Returns::Block, [](Target& t, Args& a) {
                   return block_result(
                       t.model.add_beam_from(particle(a, 0), a[1].vector, int(a[2].id), section_at(a, 3)));
                 }});
  out.push_back({"remove_from_beam", "rule 11: takes an interior particle out of its beam", Effect::Topology, {kParticle},
                 Returns::Nothing, [](Target& t, Args& a) {
                   t.model.remove_from_beam(particle(a, 0));
                   return nothing();
                 }});
  out.push_back({"insert", "rule 13: a new particle halfway between two consecutive particles of a block",
                 Effect::Topology, {{"a", Type::Particle, "one particle"}, {"b", Type::Particle, "its neighbour"}},
                 Returns::Particle,
                 [](Target& t, Args& a) { return particle_result(t.model.insert_particle(particle(a, 0), particle(a, 1))); }});
  out.push_back({"split", "rule 16: breaks a beam at an interior particle; returns the new particle and beam",
                 Effect::Topology, {{"beam", Type::Block, "the beam"}, kParticle}, Returns::ParticleAndBlock,
                 [](Target& t, Args& a) {
                   const auto [q, b] = t.model.split_beam(block(a, 0), particle(a, 1));
                   Result r;
                   r.kind = Returns::ParticleAndBlock;
                   r.ids = {q, b};
                   return r;
                 }});
  out.push_back({"quad_grid", "a patch over a grid of rows x cols particles (row by row), one bar per edge", Effect::Topology,
                 with_section({{"rows", Type::Count, "rows of particles", {2, 1e6}}, {"cols", Type::Count, "particles in a row", {2, 1e6}}},
                              {{"particles", Type::Particles, "rows x cols particles, row by row"}}),
                 Returns::Block, [](Target& t, Args& a) {
                   return block_result(t.model.add_quad_grid({a[6].ids.begin(), a[6].ids.end()}, int(a[0].id),
                                                             int(a[1].id), section_at(a, 2)));
                 }});
  out.push_back({"patch", "a patch from quads of particles (four corners in order round each quad)", Effect::Topology,
                 with_section({}, {{"corners", Type::Particles, "four particles per quad"}}), Returns::Block,
                 [](Target& t, Args& a) {
                   const std::vector<std::uint32_t>& ids = a[4].ids;
                   if (ids.size() % 4) throw ArgumentError(4, "needs four particles per quad");
                   std::vector<Model::Quad> quads;
                   for (std::size_t k = 0; k < ids.size(); k += 4) quads.push_back({ids[k], ids[k + 1], ids[k + 2], ids[k + 3]});
                   return block_result(t.model.add_patch(quads, section_at(a, 0)));
                 }});
  for (Command& c : out)  // made by m:beam{from =} and the meshing calls
    if (std::string(c.name) == "beam_from" || std::string(c.name) == "patch") c.lua = "";
  out.push_back({"remove_from_patch", "rule 23: a simple particle of a patch and its quads; the rest may split",
                 Effect::Topology, {kParticle}, Returns::Nothing, [](Target& t, Args& a) {
                   t.model.remove_from_patch(particle(a, 0));
                   return nothing();
                 }});
  out.push_back({"merge_patches", "rule 26: sews patch b onto patch a along their common boundary edges",
                 Effect::Topology, {{"a", Type::Block, "the patch that stays"}, {"b", Type::Block, "the patch sewn on"}},
                 Returns::Block,
                 [](Target& t, Args& a) { return block_result(t.model.merge_patches(block(a, 0), block(a, 1))); }});
}

}  // namespace tendril::command
