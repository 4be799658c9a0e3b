#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace tendril {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
// Orientations (node frames, beam ends). Unaligned so they sit in plain
// vectors, element structs and undo-log closures without alignment rules.
using Quat = Eigen::Quaternion<double, Eigen::DontAlign>;
using ParticleId = std::uint32_t;
using BlockId = std::uint32_t;
using ElementIndex = std::uint32_t;
inline constexpr std::uint32_t kNone = 0xffffffffu;

// Vertex states of thesis 4.2.6, derived from blocks and constraints, and
// the extended states of 5.5.1 and 6.5.2 (parent, child, volatile): roles an
// agent's or a joint's rule gives a particle, which then take precedence.
enum class State { Isolated, Passive, Lock, FullLock, Simple, Shared, Parent, Child, Volatile };
const char* state_name(State s);

enum class Role : std::uint8_t { None, Parent, Child, Volatile };
const char* role_name(Role r);
bool parse_role(const std::string& name, Role& out);

// Bar: a two-way elastic bar (tension and compression), a cable's twin.
enum class BlockKind { Cable, Beam, Patch, Bar };
const char* block_kind_name(BlockKind k);

// Lock bits: translation x, y, z then rotation x, y, z (global axes).
enum LockBits : std::uint8_t { kLockX = 1, kLockY = 2, kLockZ = 4, kLockRX = 8, kLockRY = 16, kLockRZ = 32 };
inline constexpr std::uint8_t kLockTranslation = kLockX | kLockY | kLockZ;
inline constexpr std::uint8_t kLockRotation = kLockRX | kLockRY | kLockRZ;

// Section and material of a block. Stiffnesses are given as products so a
// scene may state either E, A, I or EA, EI directly.
// The 6-DOF beam (eq. 3.44-3.50) also reads GJ, EIy and EIz; 0 means "as EI"
// (EIy = EIz = EI, and GJ = EI: a circular tube with G = E/2, the thesis'
// material of 5.5.2). The 3-DOF spline beam reads EI only.
struct Section {
  double EA = 0;         // axial stiffness [N]
  double EI = 0;         // bending stiffness [N m^2], beams only
  double prestress = 0;  // geometric tension T of eq. 3.32 [N]
  double line_mass = 0;  // physical mass per length [kg/m], lumped to particles
  double GJ = 0;         // torsional stiffness [N m^2], 6-DOF beams; 0: EI
  double EIy = 0;        // bending about the section's y axis [N m^2]; 0: EI
  double EIz = 0;        // bending about the section's z axis [N m^2]; 0: EI
  double torsion() const { return GJ > 0 ? GJ : EI; }
  double bending_y() const { return EIy > 0 ? EIy : EI; }
  double bending_z() const { return EIz > 0 ? EIz : EI; }
};

// Thrown for any invalid request on the model: the model is unchanged.
struct ModelError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace tendril
