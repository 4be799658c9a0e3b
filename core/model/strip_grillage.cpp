// The grillage of a bending strip (strip_grillage.hpp).
#include "model/strip_grillage.hpp"

#include <stdexcept>

namespace tendril {

StripGrillage strip_grillage(const std::vector<std::vector<Vec3>>& grid, const StripMaterial& m) {
  const int rows = int(grid.size());
  if (rows < 2) throw std::invalid_argument("a strip needs at least 2 rows");
  const int cols = int(grid[0].size());
  if (cols < 2) throw std::invalid_argument("a strip needs at least 2 points along each row");
  for (const auto& row : grid)
    if (int(row.size()) != cols) throw std::invalid_argument("every row of a strip needs the same number of points");
  auto at = [&](int r, int c) { return grid[std::size_t(r)][std::size_t(c)]; };
  // Half the distances to the neighbours across (along) at a point: its
  // tributary width (length).
  auto width = [&](int r, int c) {
    double w = 0;
    if (r > 0) w += 0.5 * (at(r, c) - at(r - 1, c)).norm();
    if (r + 1 < rows) w += 0.5 * (at(r + 1, c) - at(r, c)).norm();
    return w;
  };
  auto length = [&](int r, int c) {
    double a = 0;
    if (c > 0) a += 0.5 * (at(r, c) - at(r, c - 1)).norm();
    if (c + 1 < cols) a += 0.5 * (at(r, c + 1) - at(r, c)).norm();
    return a;
  };
  const double D = m.D(), Et = m.E * m.t, Gt = m.G() * m.t;
  StripGrillage g;
  for (int r = 0; r < rows; ++r) {
    double w = 0;
    for (int c = 0; c < cols; ++c) w += width(r, c) / cols;
    g.rows.push_back({Et * w, D * w, m.density * m.t * w});
  }
  for (int c = 0; c < cols; ++c) {
    double a = 0;
    for (int r = 0; r < rows; ++r) a += length(r, c) / rows;
    g.columns.push_back({Et * a, D * a, 0});  // the rows carry the weight
  }
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < cols; ++c) {
      const double a = 0.5 * ((at(r, c + 1) - at(r, c)).norm() + (at(r + 1, c + 1) - at(r + 1, c)).norm());
      const double b = 0.5 * ((at(r + 1, c) - at(r, c)).norm() + (at(r + 1, c + 1) - at(r, c + 1)).norm());
      if (!(a > 0 && b > 0)) throw std::invalid_argument("a strip's quad has a zero side");
      StripQuad q;
      q.row = r, q.column = c;
      const double d[2] = {(at(r + 1, c + 1) - at(r, c)).norm(), (at(r + 1, c) - at(r, c + 1)).norm()};
      for (int k = 0; k < 2; ++k) q.diagonal_EA[k] = Gt * d[k] * d[k] * d[k] / (2 * a * b);
      q.twist_weight = 8 * D * (1 - m.nu) / (a * b);
      g.quads.push_back(q);
    }
  return g;
}

StripMembers make_strip(const std::vector<std::vector<ParticleId>>& ids, const StripGrillage& g, StripMaker& make) {
  StripMembers out;
  for (std::size_t r = 0; r < ids.size(); ++r) out.rows.push_back(make.beam(g.rows[r], ids[r]));
  for (std::size_t c = 0; c < ids[0].size(); ++c) {
    std::vector<ParticleId> column;
    for (const auto& row : ids) column.push_back(row[c]);
    out.columns.push_back(make.beam(g.columns[c], column));
  }
  for (const StripQuad& q : g.quads) {
    const std::size_t r = std::size_t(q.row), c = std::size_t(q.column);
    const std::vector<ParticleId> corner = {ids[r][c], ids[r][c + 1], ids[r + 1][c + 1], ids[r + 1][c]};
    for (int k = 0; k < 2; ++k) out.bars.push_back(make.bar(corner[k], corner[k + 2], q.diagonal_EA[k]));
    out.twist.push_back(make.planarity(q.twist_weight, corner));
  }
  return out;
}

}  // namespace tendril
