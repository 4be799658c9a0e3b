#pragma once
// The model database (thesis 5.4.1.1): a whole model and its solver settings
// as one XML document, written and read with tinyxml2.
//
//   <tendril version="1">
//     <solver dt damping viscous geometric_factor mass_factor integrator mass_mode/>
//     <gravity x y z/>
//     <particles>
//       <particle id x y z vx vy vz lock passive point_mass fx fy fz
//                 [qw qx qy qz] [wx wy wz] [mx my mz]/>  (frame, angular velocity,
//     </particles>                                     external moment; when set)
//     <blocks>
//       <cable id a b EA EI prestress line_mass rest_length/>
//       <bar id a b EA EI prestress line_mass rest_length/>  (two-way: tension
//                                                             and compression)
//       <beam id closed dofs EA EI prestress line_mass GJ EIy EIz>
//         <node p/> <segment rest/> <node p/> ...   (nodes in path order;
//       </beam>                                      segment k joins node k, k+1)
//         6-DOF beams: <segment rest aw ax ay az bw bx by bz/>, the beam ends
//         at node k and k+1 relative to their node frames (unit quaternions)
//       <patch id rows cols EA EI prestress line_mass>
//         <node p/> ... rows*cols, row-major      (a quad grid, see add_quad_grid)
//         <edge a b rest/> ... every grid edge once
//       </patch>
//       <patch id EA EI prestress line_mass>      (any other patch: paving,
//         <quad a b c d/> ...                       Catmull-Clark, projection)
//         <edge a b rest/> ... every quad edge once
//       </patch>
//       A patch in CST mode (thesis 5.5.2.2) adds membrane="form" sigma_warp
//       sigma_weft, or membrane="analysis" with also dxx dxy dyx dyy G, and
//       its triangles: <triangle a b c/> (side a-b along the warp), in
//       analysis <triangle a b c l1 h x/> with the reference shape (side
//       a-b of length l1, c at x along it and h across).
//     </blocks>
//     <joints> <joint particle angle stiffness/> ... </joints>   (only if any)
//     <goals> <goal kind i (j length | x y z [dx dy dz] | j k l) weight/> ... </goals>
//   </tendril>
//
// Saving numbers particles and blocks densely (0..n-1) in the order of their
// live ids and writes every double with 17 significant digits, so save, load,
// save gives the same bytes. Derived data (bars, hinges, 6-DOF beam elements,
// lumped masses, forces, torques) is not stored; loading recomputes it.
#include <string>

#include "model/model.hpp"
#include "physics/solver.hpp"

namespace tendril {

// A document that is not a valid model: the message names the file, the line,
// the element and the attribute at fault.
struct ModelFormatError : ModelError {
  using ModelError::ModelError;
};

// Written whole or not at all (io/atomic_file.hpp); throws OutputError when
// the file cannot be written.
void save_model_xml(const Model& m, const SolverSettings& s, const std::string& path);
std::string model_xml_string(const Model& m, const SolverSettings& s);

// `m` must be a fresh Model. On any error (ModelFormatError for a bad
// document, InputError for an unreadable file or one that is not a regular
// file, io/input_file.hpp) `m` and `s` are unchanged.
void load_model_xml(const std::string& path, Model& m, SolverSettings& s);
// Same, from a string; `name` stands for the file in error messages.
void load_model_xml_string(const std::string& xml, Model& m, SolverSettings& s,
                           const std::string& name = "<string>");

}  // namespace tendril
