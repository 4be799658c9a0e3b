#pragma once
// Results for ParaView (issue 14): an ASCII VTK unstructured grid of the
// model's current state, legacy (.vtk) or VTK XML (.vtu), or VTK XML poly
// data (.vtp: lines, then triangles), with the same fields. Points: the live particles in id order, with point data
// `reaction` and `reaction_moment` (the supports' force and moment on
// locked particles, from the last force evaluation: Solver::reaction) and
// `locked`. Cells: one line per bar, cable segment, 3-DOF beam link and
// 6-DOF beam element, one triangle per CST triangle, with cell data
// `block`, `axial`, `strain`, `slack`, `My`, `Mz`, `torsion`, `moment`,
// `curvature`, and on CST triangles `warp`, `weft`, `shear`, `s1`, `s2`,
// `d1`, `d2` (query/element_results.hpp; 0 where a field does not apply).
// With sections for the beams, `stress` (and with a strength
// `utilisation`) too, 0 on beams without one. SI units: m, N, N m, Pa;
// membrane stresses N/m.
#include <string>

#include "model/model.hpp"
#include "query/element_results.hpp"

namespace tendril {

std::string vtk_string(const Model& m, const BeamSections* sections = nullptr);
std::string vtu_string(const Model& m, const BeamSections* sections = nullptr);
std::string vtp_string(const Model& m, const BeamSections* sections = nullptr);
// .vtu: VTK XML, .vtp: VTK XML poly data, else legacy. Written whole or not at all; throws OutputError when it cannot be (io/atomic_file.hpp).
void save_vtk(const Model& m, const std::string& path, const BeamSections* sections = nullptr);

}  // namespace tendril
