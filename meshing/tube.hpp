#pragma once
// Rule 22 (thesis 4.2.7, fig. 4.39): a tensile patch from particles on other
// patches. Two simple particles in the interiors of two patches with
// equivalent neighbourhoods: both neighbourhoods are cut out (rule 23: their
// quads and the particles left isolated go), and the two holes' rims are
// joined by a tube (rule 21, closed), the catenoid-like surface between two
// membranes. The rims stay in their patches and become shared with the tube.
//
// The neighbourhood of p is the quads touching the particles within `rings`
// - 1 edges of p (rings = 1: p's own quads). It must be a disc inside the
// patch: its particles other than the rim simple, its rim one closed loop of
// edges each of which still has a quad of the patch outside it. Equivalent
// neighbourhoods have rims of the same length. The second rim is matched to
// the first (direction and starting particle) by the least sum of squared
// rung lengths, so that two facing rings give a tube without twist.
#include <vector>

#include "commit_patch.hpp"
#include "model/model.hpp"

namespace tendril::meshing {

inline constexpr int kMaxTubeRings = 8;

struct TubeBetweenPatches {
  CommittedPatch tube;                    // rows: rim_a, interior rows, rim_b
  std::vector<ParticleId> rim_a, rim_b;   // rim_b[i] faces rim_a[i]
  std::vector<ParticleId> cut_a, cut_b;   // the particles that were cut out
  std::vector<ParticleId> removed;        // rule 23 was applied to these, in order
};

// Validates everything first (ModelError "tube: ..." naming the particle and
// the reason; the model is untouched), then cuts and builds. When the model
// is not already in a transaction it runs in one of its own, so that even an
// unforeseen failure leaves the model exactly as it was.
TubeBetweenPatches tube_between_patches(Model& m, ParticleId p1, ParticleId p2, int rows, const Section& s,
                                        int rings = 1);

}  // namespace tendril::meshing
