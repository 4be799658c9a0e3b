// Oracle test: random operation sequences are applied both to tendril::GMap
// and to CGAL::Generalized_map<2>, and the two maps are compared dart by
// dart (involutions, orbits of every kind, number of cells, validity).
#include <doctest/doctest.h>

#include <CGAL/Generalized_map.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "topology/gmap.hpp"

using tendril::Dart;
using tendril::GMap;

namespace {

using CG = CGAL::Generalized_map<2>;
using DH = CG::Dart_handle;

const void* key(DH h) { return static_cast<const void*>(&*h); }

// The seven orbit kinds that are compared.
struct OrbitKind {
  unsigned mask;
  const char* name;
};
constexpr std::array<OrbitKind, 7> kKinds{{{tendril::kA0, "<0>"},
                                           {tendril::kA1, "<1>"},
                                           {tendril::kA2, "<2>"},
                                           {tendril::kFaceOrbit, "<0,1>"},
                                           {tendril::kEdgeOrbit, "<0,2>"},
                                           {tendril::kVertexOrbit, "<1,2>"},
                                           {tendril::kComponentOrbit, "<0,1,2>"}}};

// Both maps plus the dart bijection between them.
struct Twin {
  GMap g;
  CG cg;
  std::vector<DH> to_cg;                         // by our dart index
  std::unordered_map<const void*, Dart> from_cg;  // by CGAL dart address

  Dart ours(DH h) const { return from_cg.at(key(h)); }

  Dart create() {
    Dart d = g.create_dart();
    DH h = cg.create_dart();
    if (to_cg.size() <= d) to_cg.resize(d + 1);
    to_cg[d] = h;
    from_cg[key(h)] = d;
    return d;
  }
  void erase(Dart d) {
    g.delete_dart(d);
    DH h = to_cg[d];
    from_cg.erase(key(h));
    cg.erase_dart(h);
  }
  void cg_link(int i, Dart a, Dart b) { cg.basic_link_alpha(to_cg[a], to_cg[b], static_cast<unsigned>(i)); }
  void cg_unlink(int i, Dart a) { cg.unlink_alpha(to_cg[a], static_cast<unsigned>(i)); }

  bool cg_valid() const {
    // is_valid() reports each violation on std::cerr; keep the log clean.
    std::ostringstream sink;
    auto* old = std::cerr.rdbuf(sink.rdbuf());
    bool ok = cg.is_valid();
    std::cerr.rdbuf(old);
    return ok;
  }

  std::vector<Dart> live() const {
    std::vector<Dart> out;
    for (Dart d = 0; d < g.capacity(); ++d)
      if (g.alive(d)) out.push_back(d);
    return out;
  }
};

template <unsigned... A>
std::vector<Dart> cg_orbit(Twin& t, DH h) {
  std::vector<Dart> out;
  auto range = t.cg.darts_of_orbit<A...>(h);
  for (auto it = range.begin(), end = range.end(); it != end; ++it) out.push_back(t.ours(it));
  std::sort(out.begin(), out.end());
  // CGAL's <0,2> iterator walks a0, a2, a0 blindly and reports the darts of
  // a degenerate edge with alpha0(d) == alpha2(d) twice: compare as sets.
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<Dart> cg_orbit_by_mask(Twin& t, unsigned mask, DH h) {
  switch (mask) {
    case tendril::kA0: return cg_orbit<0>(t, h);
    case tendril::kA1: return cg_orbit<1>(t, h);
    case tendril::kA2: return cg_orbit<2>(t, h);
    case tendril::kFaceOrbit: return cg_orbit<0, 1>(t, h);
    case tendril::kEdgeOrbit: return cg_orbit<0, 2>(t, h);
    case tendril::kVertexOrbit: return cg_orbit<1, 2>(t, h);
    default: return cg_orbit<0, 1, 2>(t, h);
  }
}

// Number of distinct orbits, counted on the CGAL side with a mark.
std::size_t cg_count_orbits(Twin& t, unsigned mask) {
  auto m = t.cg.get_new_mark();
  std::size_t n = 0;
  for (auto it = t.cg.darts().begin(); it != t.cg.darts().end(); ++it) {
    if (t.cg.is_marked(it, m)) continue;
    ++n;
    for (Dart x : cg_orbit_by_mask(t, mask, it)) t.cg.mark(t.to_cg[x], m);
  }
  t.cg.free_mark(m);
  return n;
}

std::size_t our_count_orbits(const GMap& g, unsigned mask) {
  std::vector<bool> seen(g.capacity(), false);
  std::size_t n = 0;
  for (Dart d = 0; d < g.capacity(); ++d) {
    if (!g.alive(d) || seen[d]) continue;
    ++n;
    g.for_orbit(mask, d, [&](Dart x) {
      seen[x] = true;
      return true;
    });
  }
  return n;
}

std::string dump(const std::vector<Dart>& v) {
  std::string s = "{";
  for (Dart d : v) s += std::to_string(d) + " ";
  return s + "}";
}

struct Snapshot {
  std::size_t darts = 0;
  std::size_t biggest_face = 0, biggest_vertex = 0, biggest_component = 0;
  std::size_t components = 0;
};

// Compares the two maps completely. `quasi` says whether both maps are
// expected to be quasi-manifold (CGAL's <0,2> iterator and its edge cells
// assume it, so they are only compared on valid maps).
Snapshot compare(Twin& t, bool quasi) {
  Snapshot s;
  const bool ours_valid = t.g.check().empty();
  const bool cg_valid = t.cg_valid();
  CHECK(ours_valid == cg_valid);
  if (quasi) {
    CHECK_MESSAGE(ours_valid, t.g.check());
    CHECK(cg_valid);
  }
  const bool edges_comparable = ours_valid && cg_valid;

  REQUIRE(t.g.dart_count() == t.cg.number_of_darts());
  REQUIRE(t.from_cg.size() == t.cg.number_of_darts());
  s.darts = t.g.dart_count();

  // Every CGAL dart is in the bijection.
  std::size_t unknown = 0;
  for (auto it = t.cg.darts().begin(); it != t.cg.darts().end(); ++it) unknown += t.from_cg.count(key(it)) == 0;
  CHECK(unknown == 0);

  // Involutions, dart by dart.
  std::size_t alpha_mismatch = 0;
  std::string first_alpha;
  for (Dart d : t.live()) {
    DH h = t.to_cg[d];
    for (unsigned i = 0; i < 3; ++i) {
      Dart theirs = t.ours(t.cg.alpha(h, i));
      if (theirs != t.g.alpha(static_cast<int>(i), d) || t.cg.is_free(h, i) != t.g.is_free(static_cast<int>(i), d)) {
        if (alpha_mismatch++ == 0)
          first_alpha = "dart " + std::to_string(d) + " alpha" + std::to_string(i) + ": ours " +
                        std::to_string(t.g.alpha(static_cast<int>(i), d)) + " CGAL " + std::to_string(theirs);
      }
    }
  }
  CHECK_MESSAGE(alpha_mismatch == 0, first_alpha);

  // Orbits of every kind, from every dart.
  for (const auto& kind : kKinds) {
    if (kind.mask == tendril::kEdgeOrbit && !edges_comparable) continue;
    std::size_t mismatch = 0;
    std::string first;
    for (Dart d : t.live()) {
      auto mine = t.g.orbit(kind.mask, d);
      if (mine.empty() || mine.front() != d) ++mismatch;
      std::sort(mine.begin(), mine.end());
      auto theirs = cg_orbit_by_mask(t, kind.mask, t.to_cg[d]);
      if (mine != theirs && mismatch++ == 0)
        first = std::string(kind.name) + " of dart " + std::to_string(d) + ": ours " + dump(mine) + " CGAL " +
                dump(theirs);
      if (kind.mask == tendril::kFaceOrbit) s.biggest_face = std::max(s.biggest_face, mine.size());
      if (kind.mask == tendril::kVertexOrbit) s.biggest_vertex = std::max(s.biggest_vertex, mine.size());
      if (kind.mask == tendril::kComponentOrbit) s.biggest_component = std::max(s.biggest_component, mine.size());
    }
    CHECK_MESSAGE(mismatch == 0, first);
    // Number of distinct orbits.
    CHECK_MESSAGE(our_count_orbits(t.g, kind.mask) == cg_count_orbits(t, kind.mask), kind.name);
  }

  // Cells through CGAL's own cell ranges (i = 3 is the connected component).
  CHECK(our_count_orbits(t.g, tendril::kVertexOrbit) == t.cg.one_dart_per_cell<0>().size());
  if (edges_comparable) CHECK(our_count_orbits(t.g, tendril::kEdgeOrbit) == t.cg.one_dart_per_cell<1>().size());
  CHECK(our_count_orbits(t.g, tendril::kFaceOrbit) == t.cg.one_dart_per_cell<2>().size());
  s.components = our_count_orbits(t.g, tendril::kComponentOrbit);
  CHECK(s.components == t.cg.one_dart_per_cell<3>().size());
  return s;
}

struct Prim {
  bool link;
  int i;
  Dart a, b;  // for an unlink, b is the former partner
};

struct Stats {
  std::array<std::size_t, 3> links{}, unlinks{};
  std::size_t creates = 0, erases = 0, rejected = 0, compares = 0;
  std::size_t max_darts = 0, max_face = 0, max_vertex = 0, max_component = 0;
  std::size_t min_components_ratio_hits = 0;  // snapshots with components < darts / 4
  std::size_t invalid_snapshots = 0;
};

// Runs `ops` random operations. With `quasi`, every link/unlink is a
// (possibly paired) operation that keeps alpha0 o alpha2 an involution, and
// candidates that would break it are rejected; without it, single links and
// unlinks are applied blindly.
Stats run(std::uint32_t seed, int ops, bool quasi) {
  std::mt19937 rng(seed);
  auto pick = [&](const std::vector<Dart>& v) { return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)]; };
  Twin t;
  Stats st;
  for (int k = 0; k < 8; ++k) t.create();

  auto step = [&]() {
    const int roll = std::uniform_int_distribution<int>(0, 99)(rng);
    const auto live = t.live();
    if (roll < 20 || live.size() < 4) {
      Dart d = t.create();
      REQUIRE(t.g.alive(d));
      for (unsigned i = 0; i < 3; ++i) CHECK(t.cg.is_free(t.to_cg[d], i));
      ++st.creates;
    } else if (roll < 30) {
      std::vector<Dart> cand;
      for (Dart d : live)
        if (t.g.is_free(0, d) && t.g.is_free(1, d) && t.g.is_free(2, d)) cand.push_back(d);
      if (!cand.empty()) {
        t.erase(pick(cand));
        ++st.erases;
      }
    } else {
      const bool do_link = roll < 72;
      const int i = std::uniform_int_distribution<int>(0, 2)(rng);
      std::vector<Prim> plan;
      if (do_link) {
        std::vector<Dart> cand;
        for (Dart d : live)
          if (t.g.is_free(i, d)) cand.push_back(d);
        if (cand.size() < 2) return;
        Dart a = pick(cand), b = pick(cand);
        if (a == b) return;
        plan.push_back({true, i, a, b});
        if (quasi && i != 1) {
          // Sewing along alpha_i also sews the alpha_j images (j = 2 - i).
          const int j = 2 - i;
          Dart a2 = t.g.alpha(j, a), b2 = t.g.alpha(j, b);
          if (a2 != a && b2 != b && a2 != b && t.g.is_free(i, a2) && t.g.is_free(i, b2))
            plan.push_back({true, i, a2, b2});
        }
      } else {
        std::vector<Dart> cand;
        for (Dart d : live)
          if (!t.g.is_free(i, d)) cand.push_back(d);
        if (cand.empty()) return;
        Dart a = pick(cand);
        plan.push_back({false, i, a, t.g.alpha(i, a)});
        if (quasi && i != 1) {
          const int j = 2 - i;
          Dart a2 = t.g.alpha(j, a);
          if (a2 != a && a2 != plan[0].b && !t.g.is_free(i, a2)) plan.push_back({false, i, a2, t.g.alpha(i, a2)});
        }
      }
      // Apply to our map first; in quasi-manifold mode undo and reject when
      // the result is not valid.
      for (const auto& p : plan) {
        if (p.link)
          t.g.link(p.i, p.a, p.b);
        else
          t.g.unlink(p.i, p.a);
      }
      if (quasi && !t.g.check().empty()) {
        for (auto it = plan.rbegin(); it != plan.rend(); ++it) {
          if (it->link)
            t.g.unlink(it->i, it->a);
          else
            t.g.link(it->i, it->a, it->b);
        }
        REQUIRE(t.g.check().empty());
        ++st.rejected;
        return;
      }
      for (const auto& p : plan) {
        if (p.link) {
          t.cg_link(p.i, p.a, p.b);
          ++st.links[p.i];
        } else {
          t.cg_unlink(p.i, p.a);
          ++st.unlinks[p.i];
        }
      }
    }
  };

  for (int op = 1; op <= ops; ++op) {
    step();
    if (op % 100 == 0 || op == ops) {
      CAPTURE(seed);
      CAPTURE(op);
      Snapshot s = compare(t, quasi);
      ++st.compares;
      st.max_darts = std::max(st.max_darts, s.darts);
      st.max_face = std::max(st.max_face, s.biggest_face);
      st.max_vertex = std::max(st.max_vertex, s.biggest_vertex);
      st.max_component = std::max(st.max_component, s.biggest_component);
      if (s.components * 4 < s.darts) ++st.min_components_ratio_hits;
      if (!t.g.check().empty()) ++st.invalid_snapshots;
    }
  }
  return st;
}

constexpr std::array<std::uint32_t, 5> kSeeds{1u, 7u, 42u, 2024u, 987654321u};

}  // namespace

TEST_CASE("GMap oracle: quasi-manifold random operations match CGAL::Generalized_map<2>") {
  for (std::uint32_t seed : kSeeds) {
    CAPTURE(seed);
    Stats st = run(seed, 2000, true);
    INFO("seed " << seed << ": links " << st.links[0] << "/" << st.links[1] << "/" << st.links[2] << " unlinks "
                    << st.unlinks[0] << "/" << st.unlinks[1] << "/" << st.unlinks[2] << " creates " << st.creates
                    << " erases " << st.erases << " rejected " << st.rejected << " max darts " << st.max_darts
                    << " max face " << st.max_face << " max vertex " << st.max_vertex << " max component "
                    << st.max_component);
    // The sequence must actually exercise the maps.
    CHECK(st.compares == 20);
    CHECK(st.invalid_snapshots == 0);
    CHECK(st.erases >= 50);
    CHECK(st.rejected >= 20);
    for (int i = 0; i < 3; ++i) {
      CHECK(st.links[i] >= 100);
      CHECK(st.unlinks[i] >= 30);
    }
    CHECK(st.max_face >= 6);
    CHECK(st.max_vertex >= 4);
    CHECK(st.max_component >= 16);
  }
}

TEST_CASE("GMap oracle: unrestricted random operations match CGAL::Generalized_map<2>") {
  // Links are applied without the quasi-manifold condition; orbits other
  // than <0,2> are still well defined and validity must be judged the same.
  for (std::uint32_t seed : kSeeds) {
    CAPTURE(seed);
    Stats st = run(seed + 1000, 2000, false);
    CHECK(st.compares == 20);
    CHECK(st.invalid_snapshots >= 10);
    CHECK(st.rejected == 0);
    for (int i = 0; i < 3; ++i) CHECK(st.links[i] >= 100);
    CHECK(st.max_component >= 16);
  }
}

TEST_CASE("GMap oracle: hand-built quad grid matches CGAL") {
  // A 3x2 grid of quads built identically in both maps.
  Twin t;
  std::vector<std::vector<Dart>> q;
  for (int k = 0; k < 6; ++k) {
    std::vector<Dart> f;
    for (int n = 0; n < 8; ++n) f.push_back(t.create());
    for (int s = 0; s < 4; ++s) {
      t.g.link(0, f[2 * s], f[2 * s + 1]);
      t.cg_link(0, f[2 * s], f[2 * s + 1]);
      t.g.link(1, f[2 * s + 1], f[(2 * s + 2) % 8]);
      t.cg_link(1, f[2 * s + 1], f[(2 * s + 2) % 8]);
    }
    q.push_back(f);
  }
  auto sew = [&](const std::vector<Dart>& f, int k, const std::vector<Dart>& h, int m) {
    t.g.link(2, f[2 * k], h[2 * m + 1]);
    t.cg_link(2, f[2 * k], h[2 * m + 1]);
    t.g.link(2, f[2 * k + 1], h[2 * m]);
    t.cg_link(2, f[2 * k + 1], h[2 * m]);
  };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      if (i + 1 < 3) sew(q[j * 3 + i], 1, q[j * 3 + i + 1], 3);
      if (j + 1 < 2) sew(q[j * 3 + i], 2, q[(j + 1) * 3 + i], 0);
    }
  compare(t, true);
  CHECK(t.cg.one_dart_per_cell<0>().size() == 12);
  CHECK(t.cg.one_dart_per_cell<1>().size() == 17);
  CHECK(t.cg.one_dart_per_cell<2>().size() == 6);
  CHECK(our_count_orbits(t.g, tendril::kVertexOrbit) == 12);
  CHECK(our_count_orbits(t.g, tendril::kEdgeOrbit) == 17);
  CHECK(t.g.orbit_size(tendril::kVertexOrbit, q[0][3]) == 8);
  CHECK(t.cg.darts_of_orbit<1, 2>(t.to_cg[q[0][3]]).size() == 8);

  // Remove the middle quad of the bottom row and compare again.
  for (int s = 0; s < 4; ++s) {
    Dart d = q[1][2 * s];
    for (Dart x : {d, q[1][2 * s + 1]})
      if (!t.g.is_free(2, x)) {
        t.cg_unlink(2, x);
        t.g.unlink(2, x);
      }
  }
  for (Dart x : q[1]) {
    for (int i = 0; i < 2; ++i)
      if (!t.g.is_free(i, x)) {
        t.cg_unlink(i, x);
        t.g.unlink(i, x);
      }
  }
  for (Dart x : q[1]) t.erase(x);
  compare(t, true);
  CHECK(t.g.dart_count() == 40);
  CHECK(our_count_orbits(t.g, tendril::kFaceOrbit) == 5);
  CHECK(our_count_orbits(t.g, tendril::kEdgeOrbit) == 16);
  CHECK(our_count_orbits(t.g, tendril::kVertexOrbit) == 12);
  CHECK(t.cg.one_dart_per_cell<3>().size() == 1);
}
