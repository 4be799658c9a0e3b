#include "io/obj.hpp"

#include "io/atomic_file.hpp"

#include <algorithm>
#include <charconv>
#include <deque>
#include <unordered_map>
#include <vector>

namespace tendril {

namespace {

void put(std::string& out, double v) {
  char buf[40];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  out.append(buf, r.ptr);
}

void put_index(std::string& out, std::uint32_t v) { out += std::to_string(v); }

}  // namespace

// Each face starts on a dart of the same orientation class as the block's
// start dart (the map is 2-coloured by alpha0, alpha1, alpha2 each flipping
// the class), so all quads wind alike.
std::vector<std::vector<ParticleId>> patch_faces(const Model& m, BlockId b) {
  const GMap& map = m.map;
  std::unordered_map<Dart, bool> positive;  // dart -> orientation class
  std::deque<Dart> queue{m.blocks[b].dart};
  std::vector<Dart> order;
  positive[m.blocks[b].dart] = true;
  while (!queue.empty()) {
    Dart d = queue.front();
    queue.pop_front();
    order.push_back(d);
    for (int i = 0; i < 3; ++i) {
      Dart e = map.alpha(i, d);
      if (e != d && positive.emplace(e, !positive[d]).second) queue.push_back(e);
    }
  }
  std::vector<std::vector<ParticleId>> faces;
  std::unordered_map<Dart, bool> done;
  for (Dart d : order) {
    if (!positive[d] || done.count(d)) continue;
    std::vector<ParticleId> face;
    Dart x = d;
    do {
      face.push_back(m.dart_particle[x]);
      done[x] = true;
      done[map.alpha(0, x)] = true;
      x = map.alpha(1, map.alpha(0, x));
    } while (x != d && face.size() <= m.blocks[b].darts);
    std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());  // canonical start
    faces.push_back(std::move(face));
  }
  return faces;
}

std::string obj_string(const Model& m) {
  const Particles& ps = m.particles;
  std::vector<std::uint32_t> index(ps.capacity(), 0);
  // The units, and one group per block named KIND-ID (the block's id as
  // b.id reads in Lua): Rhino, Blender and MeshLab list them as layers or
  // objects.
  std::string out = "# tendril model; units: m\n";
  std::uint32_t n = 0;
  for (ParticleId p = 0; p < ps.capacity(); ++p) {
    if (!ps.valid(p)) continue;
    index[p] = ++n;
    out += "v ";
    put(out, ps.position[p].x());
    out += ' ';
    put(out, ps.position[p].y());
    out += ' ';
    put(out, ps.position[p].z());
    out += '\n';
  }
  auto line = [&](char tag, const std::vector<ParticleId>& vs, bool repeat_first) {
    out += tag;
    for (ParticleId p : vs) {
      out += ' ';
      put_index(out, index[p]);
    }
    if (repeat_first) {
      out += ' ';
      put_index(out, index[vs.front()]);
    }
    out += '\n';
  };
  for (BlockId b : m.live_blocks()) {
    const Block& blk = m.blocks[b];
    out += "g ";
    out += block_kind_name(blk.kind);
    out += '-' + std::to_string(b) + '\n';
    if (blk.kind == BlockKind::Patch) {
      for (const auto& face : patch_faces(m, b)) line('f', face, false);
    } else {
      line('l', m.particles_of(b), blk.closed);
    }
  }
  return out;
}

void save_obj(const Model& m, const std::string& path) {
  const std::string text = obj_string(m);
  write_file_atomically(path, text);
}

}  // namespace tendril
