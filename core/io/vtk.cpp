#include "io/vtk.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <utility>
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

// A named array of the grid: one or three components per cell or point.
struct Array {
  std::string name;
  int components = 1;
  bool integer = false;
  std::vector<double> values;
};

// The model's grid, whichever file it goes to: points, cells (connectivity
// and VTK type) and the cell and point arrays.
struct Grid {
  std::vector<Vec3> points;
  std::vector<std::vector<std::uint32_t>> cells;
  std::vector<int> types;  // VTK_LINE 3, VTK_TRIANGLE 5
  std::vector<Array> cell_data, point_data;
};

Grid grid_of(const Model& m, const BeamSections* sections) {
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
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    for (const LineResult& l : results[k].lines) cells.push_back({blocks[k], &l, nullptr});
    for (const TriangleResult& t : results[k].triangles) cells.push_back({blocks[k], nullptr, &t});
  }
  const bool stress = sections && sections->any(), utilisation = stress && sections->any_strength();

  Grid g;
  for (ParticleId p : live) g.points.push_back(P.position[p]);
  for (const Cell& c : cells) {
    if (c.line) g.cells.push_back({index[c.line->a], index[c.line->b]}), g.types.push_back(3);
    else g.cells.push_back({index[c.triangle->i], index[c.triangle->j], index[c.triangle->k]}), g.types.push_back(5);
  }
  auto scalars = [&](const char* name, auto&& value) {
    Array a{name, 1, false, {}};
    for (const Cell& c : cells) a.values.push_back(value(c));
    g.cell_data.push_back(std::move(a));
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
    Array a{name, 3, false, {}};
    for (const Cell& c : cells) {
      const Vec3 d = c.triangle ? (name[1] == '1' ? c.triangle->d1 : c.triangle->d2) : Vec3::Zero();
      a.values.insert(a.values.end(), {d.x(), d.y(), d.z()});
    }
    g.cell_data.push_back(std::move(a));
  }

  Array locked{"locked", 1, true, {}}, reaction{"reaction", 3, false, {}}, moment{"reaction_moment", 3, false, {}};
  for (ParticleId p : live) {
    locked.values.push_back(P.lock[p] ? 1 : 0);
    // Solver::reaction: minus the residual force along the locked axes
    const Vec3 r = -P.force[p].cwiseProduct(Vec3::Ones() - free_axes(P.lock[p]));
    reaction.values.insert(reaction.values.end(), {r.x(), r.y(), r.z()});
    const Vec3 t = P.rot_degree[p] ? Vec3(-P.torque[p].cwiseProduct(Vec3::Ones() - free_rotation_axes(P.lock[p])))
                                   : Vec3::Zero();
    moment.values.insert(moment.values.end(), {t.x(), t.y(), t.z()});
  }
  g.point_data = {std::move(locked), std::move(reaction), std::move(moment)};
  return g;
}

// Values of an array, `components` per line (legacy) or space-separated (XML).
void put_values(std::string& out, const Array& a, char separator) {
  for (std::size_t k = 0; k < a.values.size(); ++k) {
    if (a.integer) out += std::to_string(long(a.values[k]));
    else put(out, a.values[k]);
    out += (separator == '\n' && (k + 1) % std::size_t(a.components) != 0) ? ' ' : separator;
  }
}

}  // namespace

std::string vtk_string(const Model& m, const BeamSections* sections) {
  const Grid g = grid_of(m, sections);
  std::size_t size = 0;
  for (const auto& c : g.cells) size += c.size() + 1;
  std::string out = "# vtk DataFile Version 3.0\n";
  out += "tendril results, SI units: m, N, N m, Pa (membrane stresses N/m)\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out += "POINTS " + std::to_string(g.points.size()) + " double\n";
  for (const Vec3& x : g.points) put(out, x.x()), out += ' ', put(out, x.y()), out += ' ', put(out, x.z()), out += '\n';
  out += "CELLS " + std::to_string(g.cells.size()) + ' ' + std::to_string(size) + '\n';
  for (const auto& c : g.cells) {
    out += std::to_string(c.size());
    for (std::uint32_t i : c) out += ' ' + std::to_string(i);
    out += '\n';
  }
  out += "CELL_TYPES " + std::to_string(g.cells.size()) + '\n';
  for (int t : g.types) out += std::to_string(t) + '\n';
  auto arrays = [&](const std::vector<Array>& list) {
    for (const Array& a : list) {
      if (a.components == 3) out += "VECTORS " + a.name + " double\n";
      else out += "SCALARS " + a.name + (a.integer ? " int" : " double") + " 1\nLOOKUP_TABLE default\n";
      put_values(out, a, '\n');
    }
  };
  out += "CELL_DATA " + std::to_string(g.cells.size()) + '\n';
  arrays(g.cell_data);
  out += "POINT_DATA " + std::to_string(g.points.size()) + '\n';
  arrays(g.point_data);
  return out;
}

namespace {

void put_xml_array(std::string& out, const Array& a) {
  out += std::string("<DataArray type=\"") + (a.integer ? "Int32" : "Float64") + "\" Name=\"" + a.name +
         "\" NumberOfComponents=\"" + std::to_string(a.components) + "\" format=\"ascii\">\n";
  put_values(out, a, ' ');
  out += "\n</DataArray>\n";
}

// Connectivity and offsets of the given cells, in that order.
std::pair<Array, Array> connectivity_of(const Grid& g, const std::vector<std::size_t>& cells) {
  Array connectivity{"connectivity", 1, true, {}}, offsets{"offsets", 1, true, {}};
  for (std::size_t k : cells) {
    for (std::uint32_t i : g.cells[k]) connectivity.values.push_back(i);
    offsets.values.push_back(double(connectivity.values.size()));
  }
  return {std::move(connectivity), std::move(offsets)};
}

// A VTK XML file of one piece: `kind` UnstructuredGrid or PolyData, its
// cells' counts in `counts` (NumberOfCells=..., or NumberOfLines=...
// NumberOfPolys=...), the cell data in `order`, then the cells' own
// sections (`cells`, written by the caller).
std::string xml_file(const Grid& g, const char* kind, const std::string& counts, const std::vector<std::size_t>& order,
                     const std::string& cells) {
  std::string out = "<?xml version=\"1.0\"?>\n<!-- tendril results, SI units: m, N, N m, Pa (membrane stresses N/m) -->\n";
  out += std::string("<VTKFile type=\"") + kind + "\" version=\"1.0\" byte_order=\"LittleEndian\">\n<" + kind + ">\n";
  out += "<Piece NumberOfPoints=\"" + std::to_string(g.points.size()) + "\" " + counts + ">\n";
  out += "<PointData>\n";
  for (const Array& a : g.point_data) put_xml_array(out, a);
  out += "</PointData>\n<CellData>\n";
  for (const Array& a : g.cell_data) {
    Array ordered{a.name, a.components, a.integer, {}};
    for (std::size_t k : order)
      for (int c = 0; c < a.components; ++c) ordered.values.push_back(a.values[k * std::size_t(a.components) + c]);
    put_xml_array(out, ordered);
  }
  out += "</CellData>\n<Points>\n";
  Array points{"Points", 3, false, {}};
  for (const Vec3& x : g.points) points.values.insert(points.values.end(), {x.x(), x.y(), x.z()});
  put_xml_array(out, points);
  out += "</Points>\n" + cells + "</Piece>\n</" + kind + ">\n</VTKFile>\n";
  return out;
}

bool ends_with(const std::string& s, const char* tail) {
  const std::string t = tail;
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

}  // namespace

std::string vtu_string(const Model& m, const BeamSections* sections) {
  const Grid g = grid_of(m, sections);
  std::vector<std::size_t> order(g.cells.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  auto [connectivity, offsets] = connectivity_of(g, order);
  Array types{"types", 1, true, {}};
  for (int t : g.types) types.values.push_back(t);
  std::string cells = "<Cells>\n";
  for (const Array* a : {&connectivity, &offsets, &types}) put_xml_array(cells, *a);
  cells += "</Cells>\n";
  return xml_file(g, "UnstructuredGrid", "NumberOfCells=\"" + std::to_string(g.cells.size()) + "\"", order, cells);
}

std::string vtp_string(const Model& m, const BeamSections* sections) {
  const Grid g = grid_of(m, sections);
  // PolyData keeps lines before polygons: the cell data follows that order.
  std::vector<std::size_t> lines, polys;
  for (std::size_t k = 0; k < g.cells.size(); ++k) (g.types[k] == 3 ? lines : polys).push_back(k);
  std::string cells;
  for (const auto& [name, list] : {std::pair{"Lines", &lines}, std::pair{"Polys", &polys}}) {
    auto [connectivity, offsets] = connectivity_of(g, *list);
    cells += std::string("<") + name + ">\n";
    put_xml_array(cells, connectivity);
    put_xml_array(cells, offsets);
    cells += std::string("</") + name + ">\n";
  }
  std::vector<std::size_t> order = lines;
  order.insert(order.end(), polys.begin(), polys.end());
  return xml_file(g, "PolyData",
                  "NumberOfVerts=\"0\" NumberOfLines=\"" + std::to_string(lines.size()) +
                      "\" NumberOfStrips=\"0\" NumberOfPolys=\"" + std::to_string(polys.size()) + "\"",
                  order, cells);
}

void save_vtk(const Model& m, const std::string& path, const BeamSections* sections) {
  write_file_atomically(path, ends_with(path, ".vtu")   ? vtu_string(m, sections)
                              : ends_with(path, ".vtp") ? vtp_string(m, sections)
                                                        : vtk_string(m, sections));
}

}  // namespace tendril
