#pragma once
// Flat particle buffers (structure of arrays) indexed by particle id. Slots of
// deleted particles are recycled; a generation counter invalidates handles.
#include <vector>

#include "model/types.hpp"
#include "model/undo_log.hpp"

namespace tendril {

// Writes through operator[] are logged during transactions; the solver
// reaches the hot columns through data().
struct Particles {
  LoggedVector<Vec3> position, velocity, force, load;
  LoggedVector<double> stiffness;   // greatest direct stiffness S (eq. 3.4)
  LoggedVector<double> point_mass;  // physical mass set on the particle [kg]
  LoggedVector<double> lumped_mass; // physical mass lumped from its elements
  LoggedVector<std::uint8_t> lock;  // LockBits
  LoggedVector<std::uint8_t> alive, passive;
  LoggedVector<std::uint8_t> role;    // Role, for the extended states
  LoggedVector<std::uint8_t> active;  // integrated this step: alive, has blocks, not passive
  LoggedVector<std::uint32_t> generation;
  LoggedVector<std::uint32_t> first_dart;  // head of the ring of darts embedding it
  LoggedVector<std::uint32_t> degree;      // number of darts embedding it
  LoggedVector<ParticleId> free_slots;
  std::size_t live = 0;
  UndoLog* log = nullptr;

  void attach(UndoLog* undo);
  std::size_t capacity() const { return alive.size(); }
  bool valid(ParticleId p) const { return p < alive.size() && alive[p]; }
  double mass(ParticleId p) const { return point_mass[p] + lumped_mass[p]; }
  ParticleId allocate(Vec3 x);  // by value: x may live in `position`
  void release(ParticleId p);
  void refresh_active(ParticleId p) { active[p] = alive[p] && degree[p] > 0 && !passive[p]; }
};

}  // namespace tendril
