// Warp and weft prestress on a patch of bars (issue 11). A bar patch has
// one prestress in its section; a cable net or a bar patch form-found with
// different forces in its two yarn families needs one per edge. The value
// lives on the edge (a dart column, rolled back with the map) and a bar
// reads it when it is made, so a CST switch that drops the interior bars
// gives them back with their prestress.
#include <cmath>
#include <map>

#include "model/model.hpp"

namespace tendril {

double Model::bar_prestress(Dart d) const {
  const double own = edge_prestress[d];
  return std::isnan(own) ? blocks[dart_block[d]].section.prestress : own;
}

void Model::set_patch_prestress(BlockId b, double warp, double weft, const std::vector<EdgePair>& warp_edges,
                                const std::vector<EdgePair>& weft_edges) {
  require_block(b, "patch_prestress");
  const std::string what = "patch_prestress: ";
  if (blocks[b].kind != BlockKind::Patch) throw ModelError(what + "block " + std::to_string(b) + " is not a patch");
  for (double T : {warp, weft})
    if (!std::isfinite(T) || T < 0) throw ModelError(what + "the warp and weft prestress must be finite numbers >= 0 [N]");
  // Per edge of the patch (its smaller particle first): the sum of the
  // values it is listed with and how many.
  std::map<EdgePair, std::pair<double, int>> edges;
  for (Dart x : map.orbit(kComponentOrbit, blocks[b].dart)) {
    ParticleId i = dart_particle[x], j = dart_particle[map.alpha(0, x)];
    edges[{std::min(i, j), std::max(i, j)}] = {0.0, 0};
  }
  auto list = [&](const std::vector<EdgePair>& pairs, double T) {
    for (const EdgePair& e : pairs) {
      auto it = edges.find({std::min(e[0], e[1]), std::max(e[0], e[1])});
      if (it == edges.end())
        throw ModelError(what + "particles " + std::to_string(e[0]) + " and " + std::to_string(e[1]) +
                         " are not an edge of patch " + std::to_string(b));
      it->second.first += T;
      it->second.second += 1;
    }
  };
  list(warp_edges, warp);
  list(weft_edges, weft);
  for (const auto& [e, sum] : edges)
    if (sum.second == 0)
      throw ModelError(what + "edge " + std::to_string(e[0]) + "-" + std::to_string(e[1]) + " of patch " +
                       std::to_string(b) + " is neither warp nor weft");
  ++revision;
  for (Dart x : map.orbit(kComponentOrbit, blocks[b].dart)) {
    ParticleId i = dart_particle[x], j = dart_particle[map.alpha(0, x)];
    const auto& sum = edges.at({std::min(i, j), std::max(i, j)});
    // A seam listed twice as warp (or weft) keeps that value; warp and weft: the mean.
    edge_prestress[x] = sum.first / sum.second;
  }
  for (Dart x : map.orbit(kComponentOrbit, blocks[b].dart)) {
    const ElementIndex e = dart_bar[x];
    if (e == kNone || bars[e].dart != x) continue;
    unbind_bar(e);
    bars[e].prestress = edge_prestress[x];
    bind_bar(e);
  }
}

}  // namespace tendril
