// Patch operations of thesis 4.2.7: rules 23 (remove a simple particle from a
// tensile patch), 26 (merge two patches) and 27 (delete a patch). Rule 24 is
// explode_from then rule 23 (grammar/rules/library.lua). Each one validates
// before touching the model, so a ModelError leaves it exactly as it was, and
// costs in proportion to the patches it touches.
#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include "model/model.hpp"

namespace tendril {

namespace {
std::string pid(ParticleId p) { return std::to_string(p); }
std::string bid(BlockId b) { return std::to_string(b); }
}  // namespace

void Model::delete_patch(BlockId b) {
  require_block(b, "delete_patch");
  if (blocks[b].kind != BlockKind::Patch) throw ModelError("delete_patch: block " + bid(b) + " is not a patch");
  delete_component(b);  // darts, bars, then rule 2 on particles left isolated
}

void Model::remove_from_patch(ParticleId p) {
  require_particle(p, "remove_from_patch");
  const State s = state(p);
  std::vector<Dart> ds = darts_of(p);
  if (s != State::Simple || blocks[dart_block[ds[0]]].kind != BlockKind::Patch)
    throw ModelError("remove_from_patch: particle " + pid(p) + " is " + state_name(s) +
                     "; only a simple particle of one patch can be removed (explode a shared one first)");
  const BlockId blk = dart_block[ds[0]];
  if (is_cst_patch(blk))
    throw ModelError("remove_from_patch: patch " + bid(blk) + " is in CST mode; switch patch " + bid(blk) +
                     " back to bars first");
  // The darts of every quad incident to p.
  std::set<Dart> gone;
  for (Dart d : ds)
    if (!gone.count(d))
      for (Dart x : map.orbit(kFaceOrbit, d)) gone.insert(x);
  if (gone.size() == blocks[blk].darts) {  // no quad is left: the patch goes
    delete_component(blk);
    return;  // p was released as isolated by delete_component
  }
  // Surviving darts sewn to a removed quad: their edges stay, on their side.
  std::vector<Dart> kept;
  std::vector<ParticleId> touched;
  for (Dart x : gone) {
    touched.push_back(dart_particle[x]);
    remove_edge_element(x);
    const Dart y = map.alpha(2, x);
    if (y != x && !gone.count(y)) kept.push_back(y);
  }
  for (Dart x : gone) free_dart(x);  // unlinks alpha2 of the neighbouring quads
  for (Dart y : kept)
    if (dart_bar[y] == kNone) add_bar(y);  // the edge keeps its rest length
  // The rest may have fallen apart: every piece touches a removed quad, so
  // the kept darts seed them all. The first piece keeps the block.
  const Section section = blocks[blk].section;
  std::set<Dart> seen;
  bool first = true;
  for (Dart y : kept) {
    if (seen.count(y)) continue;
    std::vector<Dart> piece = map.orbit(kComponentOrbit, y);
    seen.insert(piece.begin(), piece.end());
    if (first) {
      blocks[blk].dart = y;
      first = false;
      continue;
    }
    const BlockId nb = new_block(BlockKind::Patch, section, false);
    for (Dart x : piece) dart_block[x] = nb;
    blocks[nb].dart = y;
    blocks[nb].darts = piece.size();
    blocks[blk].darts -= piece.size();
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  for (ParticleId q : touched)
    if (particles.degree[q] == 0) free_particle(q);  // rule 2 (p among them)
}

BlockId Model::merge_patches(BlockId a, BlockId b) {
  require_block(a, "merge_patches");
  require_block(b, "merge_patches");
  if (a == b) throw ModelError("merge_patches: both arguments are block " + bid(a));
  if (blocks[a].kind != BlockKind::Patch) throw ModelError("merge_patches: block " + bid(a) + " is not a patch");
  if (blocks[b].kind != BlockKind::Patch) throw ModelError("merge_patches: block " + bid(b) + " is not a patch");
  for (BlockId x : {a, b})
    if (is_cst_patch(x))
      throw ModelError("merge_patches: patch " + bid(x) + " is in CST mode; switch patch " + bid(x) +
                       " back to bars first");
  using Key = std::pair<ParticleId, ParticleId>;
  struct Sides {
    std::size_t darts = 0;  // 2 per quad side on the edge
    Dart dart = kNoDart;    // one of them
  };
  auto edges_of = [&](const std::vector<Dart>& darts) {
    std::map<Key, Sides> out;
    for (Dart d : darts) {
      const ParticleId u = dart_particle[d], v = dart_particle[map.alpha(0, d)];
      Sides& s = out[{std::min(u, v), std::max(u, v)}];
      ++s.darts;
      if (s.dart == kNoDart || d < s.dart) s.dart = d;
    }
    return out;
  };
  const std::vector<Dart> da = map.orbit(kComponentOrbit, blocks[a].dart);
  const std::vector<Dart> db = map.orbit(kComponentOrbit, blocks[b].dart);
  const std::map<Key, Sides> ea = edges_of(da), eb = edges_of(db);
  std::vector<std::pair<Dart, Dart>> sew;  // (dart of a, dart of b) per common edge
  for (const auto& [key, sa] : ea) {
    auto it = eb.find(key);
    if (it == eb.end()) continue;
    if (sa.darts + it->second.darts > 4)
      throw ModelError("merge_patches: the edge " + pid(key.first) + "-" + pid(key.second) +
                       " would belong to more than two quads");
    sew.push_back({sa.dart, it->second.dart});
  }
  if (sew.empty())
    throw ModelError("merge_patches: patches " + bid(a) + " and " + bid(b) + " share no boundary edge");
  // b's bars go (the sewn edges keep a's rest length), b's darts become a's,
  // and b's edges get bars with a's section.
  for (Dart d : db) remove_edge_element(d);
  for (const auto& [x, y] : sew) {
    remove_edge_element(x);
    const Dart x0 = map.alpha(0, x), y0 = map.alpha(0, y);
    const bool same = dart_particle[x] == dart_particle[y];
    map.link(2, x, same ? y : y0);
    map.link(2, x0, same ? y0 : y);
    set_edge_rest_length(x, rest_length[x]);
  }
  for (Dart d : db) dart_block[d] = a;
  blocks[a].darts += db.size();
  blocks[b].darts = 0;
  free_block(b);
  for (Dart d : db)
    if (dart_bar[d] == kNone) add_bar(d);
  for (const auto& [x, y] : sew)
    if (dart_bar[x] == kNone) add_bar(x);
  return a;
}

}  // namespace tendril
