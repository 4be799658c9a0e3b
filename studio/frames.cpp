#include "frames.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <unordered_set>

#include "io/obj.hpp"

namespace tendril::studio {

namespace {

class Writer {
 public:
  template <class T>
  void put(const T& v) {
    const auto at = out.size();
    out.resize(at + sizeof(T));
    std::memcpy(out.data() + at, &v, sizeof(T));
  }
  template <class T>
  void put(const std::vector<T>& v) {
    const auto at = out.size();
    out.resize(at + v.size() * sizeof(T));
    if (!v.empty()) std::memcpy(out.data() + at, v.data(), v.size() * sizeof(T));
    while (out.size() % 4) out.push_back('\0');  // keeps every later array aligned for typed views
  }
  std::string out;
};

}  // namespace

Topology topology_of(const Model& m) {
  Topology t;
  t.revision = std::uint32_t(m.revision);
  const Particles& P = m.particles;
  t.index_of.assign(P.capacity(), kNone);
  for (ParticleId p = 0; p < P.capacity(); ++p) {
    if (!P.valid(p)) continue;
    t.index_of[p] = std::uint32_t(t.ids.size());
    t.ids.push_back(p);
    t.states.push_back(std::uint8_t(m.state(p)));
    t.locks.push_back(P.lock[p]);
  }
  // Patch edges' rest lengths and prestress are their bars' (a CST patch's
  // inner edges have none: 0); beams and cables ask the model.
  std::unordered_map<std::uint64_t, double> patch_rest, patch_prestress;
  auto key = [](ParticleId a, ParticleId b) { return std::uint64_t(std::min(a, b)) << 32 | std::max(a, b); };
  for (std::size_t e = 0; e < m.bars.size(); ++e) {
    const Bar& bar = m.bars[e];
    if (m.blocks[m.dart_block[bar.dart]].kind != BlockKind::Patch) continue;
    patch_rest[key(bar.i, bar.j)] = bar.rest_length;
    patch_prestress[key(bar.i, bar.j)] = bar.prestress;
  }
  auto edge = [&](ParticleId a, ParticleId b, EdgeKind kind, std::uint32_t block) {
    t.edges.push_back(t.index_of[a]);
    t.edges.push_back(t.index_of[b]);
    t.edge_kind.push_back(std::uint8_t(kind));
    t.edge_block.push_back(block);
    double rest = 0, prestress = m.blocks[t.blocks[block]].section.prestress;
    if (kind != EdgeKind::PatchBar) {
      rest = m.edge_rest_length(a, b);
    } else if (auto it = patch_rest.find(key(a, b)); it != patch_rest.end()) {
      rest = it->second;
      prestress = patch_prestress.at(key(a, b));
    }
    t.rest_length.push_back(float(rest));
    t.prestress.push_back(float(prestress));
  };
  for (BlockId b : m.live_blocks()) {
    const Block& blk = m.blocks[b];
    const auto k = std::uint32_t(t.blocks.size());
    t.blocks.push_back(b);
    t.block_kind.push_back(std::uint8_t(blk.kind));
    if (blk.kind == BlockKind::Patch) {
      t.block_form.push_back(blk.membrane.cst() ? 1 : 0);
      std::unordered_set<std::uint64_t> seen;  // an inner edge is in two faces: drawn once
      for (const auto& face : patch_faces(m, b)) {
        for (std::size_t i = 0; i < face.size(); ++i) {
          const ParticleId a = std::min(face[i], face[(i + 1) % face.size()]);
          const ParticleId c = std::max(face[i], face[(i + 1) % face.size()]);
          if (seen.insert(std::uint64_t(a) << 32 | c).second) edge(a, c, EdgeKind::PatchBar, k);
        }
        for (std::size_t i = 1; i + 1 < face.size(); ++i) {  // a fan: quads and the odd triangle
          t.triangles.push_back(t.index_of[face[0]]);
          t.triangles.push_back(t.index_of[face[i]]);
          t.triangles.push_back(t.index_of[face[i + 1]]);
          t.triangle_block.push_back(k);
        }
      }
    } else {
      t.block_form.push_back(blk.kind == BlockKind::Beam ? blk.dofs : 3);
      const std::vector<ParticleId> ps = m.particles_of(b);
      const EdgeKind kind = blk.kind == BlockKind::Beam ? EdgeKind::Beam : EdgeKind::Cable;
      for (std::size_t i = 0; i + 1 < ps.size(); ++i) edge(ps[i], ps[i + 1], kind, k);
      if (blk.closed && ps.size() > 2) edge(ps.back(), ps.front(), kind, k);
    }
  }
  return t;
}

std::string encode(const Topology& t) {
  Writer w;
  w.put(kTopology);
  w.put(t.revision);
  w.put(std::uint32_t(t.ids.size()));
  w.put(std::uint32_t(t.edge_kind.size()));
  w.put(std::uint32_t(t.triangle_block.size()));
  w.put(std::uint32_t(t.blocks.size()));
  w.put(t.ids);
  w.put(t.blocks);
  w.put(t.block_kind);
  w.put(t.block_form);
  w.put(t.states);
  w.put(t.locks);
  w.put(t.edge_kind);
  w.put(t.edges);
  w.put(t.edge_block);
  w.put(t.rest_length);
  w.put(t.triangles);
  w.put(t.triangle_block);
  return std::move(w.out);
}

void encode_frame(const Model& m, const Solver& s, const Topology& t, const std::vector<float>& field, std::string& out) {
  Writer w;
  w.out.swap(out);
  w.out.clear();  // keeps its capacity
  w.out.reserve(40 + 12 * t.ids.size() + 4 * field.size());
  w.put(kFrame);
  w.put(t.revision);
  w.put(double(s.steps()));
  w.put(s.residual());
  w.put(s.time());
  w.put(std::uint32_t(t.ids.size()));
  w.put(std::uint32_t(field.size()));
  // The positions as float32, written straight into the message.
  const std::size_t at = w.out.size();
  w.out.resize(at + 12 * t.ids.size());
  auto* xyz = reinterpret_cast<unsigned char*>(w.out.data() + at);
  const Vec3* x = m.particles.position.data();
  for (std::size_t k = 0; k < t.ids.size(); ++k) {
    const float v[3] = {float(x[t.ids[k]][0]), float(x[t.ids[k]][1]), float(x[t.ids[k]][2])};
    std::memcpy(xyz + 12 * k, v, 12);
  }
  w.put(field);
  out.swap(w.out);
}

std::string encode_frame(const Model& m, const Solver& s, const Topology& t, const std::vector<float>& field) {
  std::string out;
  encode_frame(m, s, t, field, out);
  return out;
}

bool Topology::same_drawing(const Topology& o) const {
  return ids == o.ids && states == o.states && locks == o.locks && blocks == o.blocks && block_kind == o.block_kind &&
         block_form == o.block_form && edge_kind == o.edge_kind && edges == o.edges && edge_block == o.edge_block &&
         rest_length == o.rest_length && prestress == o.prestress && triangles == o.triangles && triangle_block == o.triangle_block;
}

}  // namespace tendril::studio
