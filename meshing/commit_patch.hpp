#pragma once
// Turning a meshing result into a patch of the model, all or nothing.
//
// Model operations validate before they change anything; a meshing rule adds
// particles *and* a patch, so it must validate the patch before adding the
// particles. validate_patch repeats add_patch's checks on the planned mesh
// (corners, edges in at most two quads, one piece, no edge between
// coincident points, the section) so that, once it passes, no later step can
// throw and leave half a result behind. If add_patch still refuses (its rules
// grew), commit_patch undoes what it did before rethrowing: the live model is
// the same, though freed particle slots keep bumped generations.
#include <string>
#include <utility>
#include <vector>

#include "model/model.hpp"
#include "quad_mesh.hpp"

namespace tendril::meshing {

// A mesh to add: vertex i < existing.size() is the existing particle
// existing[i] (at mesh.positions[i], which may differ from where it is now:
// see `moves`), vertex i >= existing.size() becomes a new particle.
struct PlannedPatch {
  QuadMesh mesh;
  std::vector<ParticleId> existing;
};

struct CommittedPatch {
  BlockId patch = kNone;
  std::vector<ParticleId> particles;  // particles[i] is mesh vertex i
  std::vector<ParticleId> created;    // the new particles, in vertex order
  // What a replayable trace needs to repeat the change primitive by primitive:
  // the existing particles that were moved (to mesh.positions of their
  // vertex), and the quads exactly as they were given to Model::add_patch.
  std::vector<ParticleId> moved;
  std::vector<Model::Quad> quads;
};

void validate_section(const Section& s, const std::string& what);
// Throws ModelError("<what>: ...") when the plan would be refused.
void validate_patch(const Model& m, const PlannedPatch& plan, const Section& s, const std::string& what);

// Validates, moves every existing particle whose planned position differs from
// its current one, adds the new particles and the patch.
CommittedPatch commit_patch(Model& m, const PlannedPatch& plan, const Section& s, const std::string& what);

}  // namespace tendril::meshing
