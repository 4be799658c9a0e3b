#include "io/ply.hpp"

#include <charconv>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/obj.hpp"

namespace tendril {

std::string ply_string(const Model& m) {
  const Particles& P = m.particles;
  std::vector<std::uint32_t> index(P.capacity(), 0);
  std::string vertices;
  std::uint32_t n = 0;
  for (ParticleId p = 0; p < P.capacity(); ++p) {
    if (!P.valid(p)) continue;
    index[p] = n++;
    for (int c = 0; c < 3; ++c) {
      char buf[40];
      auto r = std::to_chars(buf, buf + sizeof buf, P.position[p][c], std::chars_format::general, 17);
      vertices.append(buf, r.ptr);
      vertices += c < 2 ? ' ' : '\n';
    }
  }
  std::string edges, faces;
  std::size_t edge_count = 0, face_count = 0;
  for (BlockId b : m.live_blocks()) {
    const Block& blk = m.blocks[b];
    if (blk.kind == BlockKind::Patch) {
      for (const auto& face : patch_faces(m, b)) {
        faces += std::to_string(face.size());
        for (ParticleId p : face) faces += ' ' + std::to_string(index[p]);
        faces += ' ' + std::to_string(b) + '\n';
        ++face_count;
      }
      continue;
    }
    const std::vector<ParticleId> ps = m.particles_of(b);
    for (std::size_t k = 0; k + 1 < ps.size() + (blk.closed ? 1 : 0); ++k) {
      edges += std::to_string(index[ps[k]]) + ' ' + std::to_string(index[ps[(k + 1) % ps.size()]]) + ' ' +
               std::to_string(b) + '\n';
      ++edge_count;
    }
  }
  std::string out = "ply\nformat ascii 1.0\ncomment tendril model; units: m\n";
  out += "element vertex " + std::to_string(n) + "\nproperty double x\nproperty double y\nproperty double z\n";
  out += "element edge " + std::to_string(edge_count) + "\nproperty int vertex1\nproperty int vertex2\nproperty int block\n";
  out += "element face " + std::to_string(face_count) + "\nproperty list uchar int vertex_indices\nproperty int block\n";
  out += "end_header\n";
  return out + vertices + edges + faces;
}

void save_ply(const Model& m, const std::string& path) { write_file_atomically(path, ply_string(m)); }

}  // namespace tendril
