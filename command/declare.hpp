#pragma once
// Helpers for the declaration files (*_commands.cpp): the parameter lists
// several commands share, and how they read their Args.
#include <vector>

#include "command/command.hpp"
#include "model/limits.hpp"
#include "model/model.hpp"

namespace tendril::command {

// EA, EI, prestress, line_mass: the journal's four section words.
std::vector<Param> section_params();
// `before`, the section, then `after`.
std::vector<Param> with_section(std::vector<Param> before, std::vector<Param> after = {});
// The section starting at Args index `first`.
Section section_at(const Args& a, std::size_t first);

inline ParticleId particle(const Args& a, std::size_t k) { return ParticleId(a[k].id); }
inline BlockId block(const Args& a, std::size_t k) { return BlockId(a[k].id); }

Result nothing();
Result particle_result(ParticleId p);
Result block_result(BlockId b);
Result number_result(double x);
Result vector_result(const Vec3& x);

// The declarations, by kind (registry.cpp gathers them).
void declare_topology(std::vector<Command>& out);   // topology_commands.cpp
void declare_members(std::vector<Command>& out);    // member_commands.cpp
void declare_particle_settings(std::vector<Command>& out);  // particle_commands.cpp
void declare_goals(std::vector<Command>& out);      // goal_commands.cpp
void declare_solver(std::vector<Command>& out);     // solver_commands.cpp

}  // namespace tendril::command
