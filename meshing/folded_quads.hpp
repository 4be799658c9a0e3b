#pragma once
// Folded quads: what a run reports so that an equilibrium with inverted
// faces is not taken for a good shape (issue 11). A quad is folded when its
// scaled Jacobian (quality.hpp) is below zero: a corner turned inside out
// against the quad's mean normal, a bow-tie, as a membrane that collapsed
// or crossed itself leaves behind. Any winding counts alike.
#include <array>
#include <vector>

#include "model/model.hpp"

namespace tendril::meshing {

struct FoldedQuad {
  BlockId patch;
  std::array<ParticleId, 4> corners;  // in order round the quad
  double jacobian;                    // its scaled Jacobian, < 0
};

// Every folded quad of every live patch, worst (lowest Jacobian) first.
std::vector<FoldedQuad> folded_quads(const Model& m);

}  // namespace tendril::meshing
