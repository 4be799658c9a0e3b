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
  }
  return "?";
}

const char* block_kind_name(BlockKind k) {
  switch (k) {
    case BlockKind::Cable: return "cable";
    case BlockKind::Beam: return "beam";
    case BlockKind::Patch: return "patch";
  }
  return "?";
}

}  // namespace tendril
