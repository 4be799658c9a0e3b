#pragma once
// Folded quads: what a run reports so that an equilibrium with inverted
// faces is not taken for a good shape (issue 11). A quad is folded when its
// scaled Jacobian (quality.hpp) is below zero: a corner turned inside out
// against the quad's mean normal, a bow-tie, as a membrane that collapsed
// or crossed itself leaves behind. Any winding counts alike.
#include <array>
#include <cstdint>
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

// The same, for one model checked again and again (every m:run): the
// patches' quads are derived from the map again only when the model's
// revision moved (on the 128 x 128 net deriving them took 25 ms, a third
// of a Newton run to equilibrium); the Jacobians are the positions' own.
class FoldedQuadCheck {
 public:
  std::vector<FoldedQuad> operator()(const Model& m);

 private:
  struct Patch {
    BlockId block;
    std::vector<std::array<ParticleId, 4>> quads;  // corners in order round each quad
  };
  std::uint64_t revision_ = ~std::uint64_t(0);
  std::vector<Patch> patches_;
};

}  // namespace tendril::meshing
