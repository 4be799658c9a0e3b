#pragma once
// Multi-resolution tensile patch (thesis 5.5.2.3, fig. 5.31-5.32): one patch
// at two resolutions. The fine patch splits every quad of a coarse patch into
// factor x factor quads; the coarse particles are on both, the fine-only
// particles are passive while the model is coarse, so neither they nor their
// bars cost anything in a step, and the coarse patch's bars are the
// "temporary links" between the non-passive particles.
//
//   coarse mode: coarse patch alive, fine-only particles passive
//   refine:      fine-only particles placed on the coarse surface (bilinear
//                in each coarse quad: the "first update" of fig. 5.31b),
//                made active; the coarse links deleted (rule 27)
//   coarsen:     fine-only particles passive again (frozen where they are);
//                the coarse links re-created between the coarse particles,
//                their rest lengths the current distances
//
// Fine section by default: the coarse one divided by the factor (EA,
// prestress, line mass), so both nets stand for the same membrane: the same
// tension and stiffness per unit width and the same mass per area.
// A fine particle on a coarse edge whose two ends are both locked takes the
// translation locks they share (a supported edge stays supported).
// Fine particles on the coarse boundary are new particles of the fine patch
// only: a boundary on a beam is followed by its chords, as in rule 25.
#include <array>
#include <vector>

#include "model/model.hpp"

namespace tendril::meshing {

inline constexpr int kMaxMultiresFactor = 16;

struct MultiresPatch {
  BlockId coarse = kNone;  // the coarse links; kNone while fine
  BlockId fine = kNone;
  std::uint32_t coarse_generation = 0, fine_generation = 0;
  int factor = 2;
  Section coarse_section, fine_section;
  std::vector<Model::Quad> fine_quads;  // as given to Model::add_patch (journals)
  std::vector<Model::Quad> coarse_quads;
  // The fine-only particles (with their generations, to refuse a recycled
  // slot) and where each sits on the coarse surface: weights of four coarse
  // particles (bilinear; two weights are 0 on a coarse edge).
  std::vector<ParticleId> particles;
  std::vector<std::uint32_t> generations;
  std::vector<std::array<ParticleId, 4>> corners;
  std::vector<std::array<double, 4>> weights;
  bool coarse_mode() const { return coarse != kNone; }
};

// Builds the fine patch of `coarse` (a live patch of bars, none of its
// particles passive), in coarse mode. `fine` null: the scaled section.
// Validates everything first; throws ModelError ("multires: ...").
MultiresPatch multires_patch(Model& m, BlockId coarse, int factor, const Section* fine = nullptr);
// Throw ModelError ("refine: ..." / "coarsen: ...") and change nothing when
// the patch is not in the other mode or a particle or block it needs is gone.
void multires_refine(Model& m, MultiresPatch& mr);
void multires_coarsen(Model& m, MultiresPatch& mr);

}  // namespace tendril::meshing
