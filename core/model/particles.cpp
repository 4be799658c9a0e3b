#include "model/particles.hpp"

#include <cmath>
#include <utility>

namespace tendril {

void Particles::attach(UndoLog* undo) {
  log = undo;
  for (auto* v : {&position, &velocity, &force, &load}) v->attach(undo);
  for (auto* v : {&stiffness, &point_mass, &lumped_mass, &lumped_mass_low}) v->attach(undo);
  for (auto* v : {&lock, &alive, &passive, &active, &role}) v->attach(undo);
  for (auto* v : {&generation, &first_dart, &degree, &free_slots}) v->attach(undo);
  orientation.attach(undo);
  for (auto* v : {&angular_velocity, &torque, &moment}) v->attach(undo);
  rot_stiffness.attach(undo);
  for (auto* v : {&rot_degree, &rotational_slot, &rotational, &integrated, &integrated_slot}) v->attach(undo);
  rotational.watch(&rotational_edits);
}

ParticleId Particles::allocate(Vec3 x) {
  ParticleId p;
  if (!free_slots.empty()) {
    p = free_slots.back();
    free_slots.pop_back();
  } else {
    p = static_cast<ParticleId>(alive.size());
    for (auto* v : {&position, &velocity, &force, &load}) v->push_back(Vec3::Zero());
    stiffness.push_back(0);
    point_mass.push_back(0);
    lumped_mass.push_back(0);
    lumped_mass_low.push_back(0);
    lock.push_back(0);
    alive.push_back(0);
    passive.push_back(0);
    active.push_back(0);
    role.push_back(0);
    generation.push_back(0);
    first_dart.push_back(kNone);
    degree.push_back(0);
    orientation.push_back(Quat::Identity());
    for (auto* v : {&angular_velocity, &torque, &moment}) v->push_back(Vec3::Zero());
    rot_stiffness.push_back(0);
    rot_degree.push_back(0);
    rotational_slot.push_back(kNone);
    integrated_slot.push_back(kNone);
  }
  position[p] = x;
  velocity[p].setZero();
  force[p].setZero();
  load[p].setZero();
  stiffness[p] = 0;
  point_mass[p] = 0;
  clear_lumped_mass(p);
  lock[p] = 0;
  alive[p] = 1;
  passive[p] = 0;
  active[p] = 0;
  role[p] = 0;
  first_dart[p] = kNone;
  degree[p] = 0;
  orientation[p] = Quat::Identity();
  angular_velocity[p].setZero();
  torque[p].setZero();
  moment[p].setZero();
  rot_stiffness[p] = 0;
  rot_degree[p] = 0;
  rotational_slot[p] = kNone;
  if (log) log->scalar(live);
  ++live;
  return p;
}

void Particles::add_rotational_end(ParticleId p) {
  if (rot_degree[p]++ != 0) return;
  rotational_slot[p] = static_cast<std::uint32_t>(rotational.size());
  rotational.push_back(p);
}

void Particles::remove_rotational_end(ParticleId p) {
  if (--rot_degree[p] != 0) return;
  const std::uint32_t slot = rotational_slot[p];
  const ParticleId last = rotational.back();
  if (last != p) {
    rotational[slot] = last;
    rotational_slot[last] = slot;
  }
  rotational.pop_back();
  rotational_slot[p] = kNone;
}

void Particles::clear_rotational() {
  for (ParticleId p = 0; p < capacity(); ++p) {
    rot_degree[p] = 0;
    rotational_slot[p] = kNone;
  }
  rotational.clear();
}

void Particles::add_lumped_mass(ParticleId p, double m) {
  // TwoSum: sum + error == lumped_mass[p] + m exactly.
  const double a = lumped_mass[p];
  double sum = a + m;
  const double b = sum - a, error = (a - (sum - b)) + (m - b);
  double low = lumped_mass_low[p] + error;
  // Only a rounding no longer small beside the sum (a cancellation) is
  // folded in: otherwise the mass is the plain running sum, the same
  // numbers as ever.
  if (std::abs(low) > 1e-12 * std::abs(sum)) {
    const double high = sum + low;  // FastTwoSum: |sum| >= |low| or sum ~ 0
    low -= high - sum;
    sum = high;
  }
  lumped_mass_low[p] = low;
  lumped_mass[p] = sum;
}

void Particles::clear_lumped_mass(ParticleId p) {
  lumped_mass[p] = 0;
  lumped_mass_low[p] = 0;
}

void Particles::refresh_active(ParticleId p) {
  const std::uint8_t now = alive[p] && degree[p] > 0 && !passive[p];
  if (now == std::as_const(active)[p]) return;
  active[p] = now;
  if (now) {
    integrated_slot[p] = static_cast<std::uint32_t>(integrated.size());
    integrated.push_back(p);
    return;
  }
  const std::uint32_t slot = integrated_slot[p];
  const ParticleId last = integrated.back();
  if (last != p) {
    integrated[slot] = last;
    integrated_slot[last] = slot;
  }
  integrated.pop_back();
  integrated_slot[p] = kNone;
}

void Particles::release(ParticleId p) {
  alive[p] = 0;
  refresh_active(p);
  ++generation[p];
  free_slots.push_back(p);
  if (log) log->scalar(live);
  --live;
}

}  // namespace tendril
