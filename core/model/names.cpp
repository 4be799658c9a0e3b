#include "model/types.hpp"

namespace tendril {

const char* state_name(State s) {
  switch (s) {
    case State::Isolated: return "isolated";
    case State::Passive: return "passive";
    case State::Lock: return "lock";
    case State::FullLock: return "full-lock";
    case State::Simple: return "simple";
    case State::Shared: return "shared";
    case State::Parent: return "parent";
    case State::Child: return "child";
    case State::Volatile: return "volatile";
  }
  return "?";
}

const char* role_name(Role r) {
  switch (r) {
    case Role::None: return "none";
    case Role::Parent: return "parent";
    case Role::Child: return "child";
    case Role::Volatile: return "volatile";
  }
  return "?";
}

bool parse_role(const std::string& name, Role& out) {
  for (Role r : {Role::None, Role::Parent, Role::Child, Role::Volatile})
    if (name == role_name(r)) {
      out = r;
      return true;
    }
  return false;
}

const char* block_kind_name(BlockKind k) {
  switch (k) {
    case BlockKind::Cable: return "cable";
    case BlockKind::Beam: return "beam";
    case BlockKind::Patch: return "patch";
    case BlockKind::Bar: return "bar";
  }
  return "?";
}

}  // namespace tendril
