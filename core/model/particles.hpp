#pragma once
// Flat particle buffers (structure of arrays) indexed by particle id. Slots of
// deleted particles are recycled; a generation counter invalidates handles.
#include <vector>

#include "model/edit_list.hpp"
#include "model/types.hpp"
#include "model/undo_log.hpp"

namespace tendril {

// Writes through operator[] are logged during transactions; the solver
// reaches the hot columns through data().
//
// Rotational degrees of freedom (thesis 3.2.3, 3.2.6) live in their own
// columns and only matter for particles on a 6-DOF beam: `rot_degree` counts
// the 6-DOF beam ends on a particle, and `rotational` lists the particles
// whose count is > 0 (`rotational_slot` is the place in that list), so the
// solver's rotational work touches those only.
//
// Multi-resolution (thesis 5.5.2.3): `integrated` lists the active particles
// (alive, on a block, not passive) and `integrated_slot` is each one's place
// in it (kNone when not active). refresh_active keeps both in step by one
// push or one swap-remove, logged like every write, so a rollback restores
// the list exactly. The solver and every integrator loop over `integrated`
// only, so a passive particle costs nothing in a step; its order is the
// order of activation (deterministic for a given history).
struct Particles {
  LoggedVector<Vec3> position, velocity, force, load;
  LoggedVector<double> stiffness;   // greatest direct stiffness S (eq. 3.4)
  LoggedVector<double> point_mass;  // physical mass set on the particle [kg]
  LoggedVector<double> lumped_mass; // physical mass lumped from its elements
  LoggedVector<double> lumped_mass_low;  // what rounding left out of lumped_mass (see add_lumped_mass)
  LoggedVector<std::uint8_t> lock;  // LockBits
  LoggedVector<std::uint8_t> alive, passive;
  LoggedVector<std::uint8_t> role;    // Role, for the extended states
  LoggedVector<std::uint8_t> active;  // integrated this step: alive, has blocks, not passive
  LoggedVector<std::uint32_t> generation;
  LoggedVector<std::uint32_t> first_dart;  // head of the ring of darts embedding it
  LoggedVector<std::uint32_t> degree;      // number of darts embedding it
  LoggedVector<ParticleId> free_slots;
  // Rotation: node frame R (its columns are the local axes in global
  // coordinates), angular velocity, residual torque, external moment, and the
  // greatest rotational stiffness (eq. 3.49-3.50) of the last evaluation.
  LoggedVector<Quat> orientation;
  LoggedVector<Vec3> angular_velocity, torque, moment;
  LoggedVector<double> rot_stiffness;
  LoggedVector<std::uint32_t> rot_degree;       // 6-DOF beam ends on the particle
  LoggedVector<std::uint32_t> rotational_slot;  // index in `rotational`, or kNone
  LoggedVector<ParticleId> rotational;          // particles with rot_degree > 0
  EditList rotational_edits;  // its writes, for the solver's rotating chunk shares (edit_list.hpp)
  LoggedVector<ParticleId> integrated;          // the particles with active == 1
  LoggedVector<std::uint32_t> integrated_slot;  // index in `integrated`, or kNone
  std::size_t live = 0;
  UndoLog* log = nullptr;

  void attach(UndoLog* undo);
  std::size_t capacity() const { return alive.size(); }
  bool valid(ParticleId p) const { return p < alive.size() && alive[p]; }
  double mass(ParticleId p) const { return point_mass[p] + lumped_mass[p]; }
  // Adds m (< 0 removes) to p's lumped mass, keeping what rounding left out
  // in lumped_mass_low (error-free transformations) and folding it in when
  // it is no longer small beside the mass: removing a heavy element from a
  // light particle subtracts what was added, and a plain double kept the
  // rounding of the heavy sum as mass (1e12 kg/m beside 1 kg/m: off by 1e-4).
  void add_lumped_mass(ParticleId p, double m);
  void clear_lumped_mass(ParticleId p);
  ParticleId allocate(Vec3 x);  // by value: x may live in `position`
  void release(ParticleId p);
  void refresh_active(ParticleId p);  // active and `integrated` from alive, degree and passive
  // One more / one fewer 6-DOF beam end on p; keeps `rotational` in step.
  void add_rotational_end(ParticleId p);
  void remove_rotational_end(ParticleId p);
  void clear_rotational();  // every count 0, the list empty (rebuilds)
};

}  // namespace tendril
