#include "io/vtk.hpp"

#include <charconv>
#include <cmath>
#include <vector>

#include "io/atomic_file.hpp"
#include "physics/free_axes.hpp"

namespace tendril {

namespace {

void put(std::string& out, double v) {
  if (!std::isfinite(v)) v = 0;  // VTK's reader takes no nan or inf: an infinite radius is written as curvature 0 only
  char buf[40];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  out.append(buf, r.ptr);
}

struct Cell {
  BlockId block;
  const LineResult* line = nullptr;
  const TriangleResult* triangle = nullptr;
};

}  // namespace

std::string vtk_string(const Model& m, const BeamSections* sections) {
  const Particles& P = m.particles;
  std::vector<std::uint32_t> index(P.capacity(), 0);
  std::vector<ParticleId> live;
  for (ParticleId p = 0; p < P.capacity(); ++p)
    if (P.valid(p)) {
      index[p] = std::uint32_t(live.size());
      live.push_back(p);
    }
  std::vector<BlockId> blocks = m.live_blocks();
  std::vector<BlockResults> results;
  results.reserve(blocks.size());
  for (BlockId b : blocks) results.push_back(element_results(m, b, sections ? sections->of(b) : nullptr));
  std::vector<Cell> cells;
  std::size_t size = 0;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    for (const LineResult& l : results[k].lines) cells.push_back({blocks[k], &l, nullptr}), size += 3;
    for (const TriangleResult& t : results[k].triangles) cells.push_back({blocks[k], nullptr, &t}), size += 4;
  }
  const bool stress = sections && sections->any(), utilisation = stress && sections->any_strength();

  std::string out = "# vtk DataFile Version 3.0\n";
  out += "tendril results, SI units: m, N, N m, Pa (membrane stresses N/m)\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out += "POINTS " + std::to_string(live.size()) + " double\n";
  for (ParticleId p : live) {
    put(out, P.position[p].x()), out += ' ', put(out, P.position[p].y()), out += ' ', put(out, P.position[p].z());
    out += '\n';
  }
  out += "CELLS " + std::to_string(cells.size()) + ' ' + std::to_string(size) + '\n';
  for (const Cell& c : cells) {
    if (c.line)
      out += "2 " + std::to_string(index[c.line->a]) + ' ' + std::to_string(index[c.line->b]) + '\n';
    else
      out += "3 " + std::to_string(index[c.triangle->i]) + ' ' + std::to_string(index[c.triangle->j]) + ' ' +
             std::to_string(index[c.triangle->k]) + '\n';
  }
  out += "CELL_TYPES " + std::to_string(cells.size()) + '\n';
  for (const Cell& c : cells) out += c.line ? "3\n" : "5\n";  // VTK_LINE, VTK_TRIANGLE

  out += "CELL_DATA " + std::to_string(cells.size()) + '\n';
  auto scalars = [&](const char* name, auto&& value) {
    out += "SCALARS ";
    out += name;
    out += " double 1\nLOOKUP_TABLE default\n";
    for (const Cell& c : cells) put(out, value(c)), out += '\n';
  };
  auto line = [](double LineResult::*f) {
    return [f](const Cell& c) { return c.line ? c.line->*f : 0.0; };
  };
  auto membrane = [](double TriangleResult::*f) {
    return [f](const Cell& c) { return c.triangle ? c.triangle->*f : 0.0; };
  };
  scalars("block", [](const Cell& c) { return double(c.block); });
  scalars("axial", line(&LineResult::axial));
  scalars("strain", line(&LineResult::strain));
  scalars("slack", [](const Cell& c) { return c.line && c.line->slack ? 1.0 : 0.0; });
  scalars("My", line(&LineResult::My));
  scalars("Mz", line(&LineResult::Mz));
  scalars("torsion", line(&LineResult::torsion));
  scalars("moment", line(&LineResult::moment));
  scalars("curvature", line(&LineResult::curvature));
  if (stress) scalars("stress", [](const Cell& c) { return c.line && !std::isnan(c.line->stress) ? c.line->stress : 0.0; });
  if (utilisation)
    scalars("utilisation",
            [](const Cell& c) { return c.line && !std::isnan(c.line->utilisation) ? c.line->utilisation : 0.0; });
  scalars("warp", membrane(&TriangleResult::warp));
  scalars("weft", membrane(&TriangleResult::weft));
  scalars("shear", membrane(&TriangleResult::shear));
  scalars("s1", membrane(&TriangleResult::s1));
  scalars("s2", membrane(&TriangleResult::s2));
  for (const char* name : {"d1", "d2"}) {
    out += "VECTORS ";
    out += name;
    out += " double\n";
    for (const Cell& c : cells) {
      const Vec3 d = c.triangle ? (name[1] == '1' ? c.triangle->d1 : c.triangle->d2) : Vec3::Zero();
      put(out, d.x()), out += ' ', put(out, d.y()), out += ' ', put(out, d.z()), out += '\n';
    }
  }

  out += "POINT_DATA " + std::to_string(live.size()) + '\n';
  out += "SCALARS locked int 1\nLOOKUP_TABLE default\n";
  for (ParticleId p : live) out += P.lock[p] ? "1\n" : "0\n";
  out += "VECTORS reaction double\n";
  for (ParticleId p : live) {  // Solver::reaction: minus the residual force along the locked axes
    const Vec3 r = -P.force[p].cwiseProduct(Vec3::Ones() - free_axes(P.lock[p]));
    put(out, r.x()), out += ' ', put(out, r.y()), out += ' ', put(out, r.z()), out += '\n';
  }
  out += "VECTORS reaction_moment double\n";
  for (ParticleId p : live) {
    const Vec3 r = P.rot_degree[p] ? Vec3(-P.torque[p].cwiseProduct(Vec3::Ones() - free_rotation_axes(P.lock[p])))
                                   : Vec3::Zero();
    put(out, r.x()), out += ' ', put(out, r.y()), out += ' ', put(out, r.z()), out += '\n';
  }
  return out;
}

void save_vtk(const Model& m, const std::string& path, const BeamSections* sections) {
  write_file_atomically(path, vtk_string(m, sections));
}

}  // namespace tendril
