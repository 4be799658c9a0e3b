#include "ply_openmesh.hpp"

// MeshIO before the mesh kernel: OpenMesh registers its readers and writers there.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <array>
#include <map>
#include <sstream>

#include "io/input_file.hpp"
#include "patch_mesh.hpp"

namespace tendril::meshing {

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
};
using Mesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

// The header's count of element `name` (0 when absent), and whether the
// format is binary.
struct Header {
  bool ply = false, binary = false;
  std::size_t vertices = 0, faces = 0, edges = 0;
};

Header header_of(const std::string& bytes) {
  Header h;
  std::istringstream in(bytes.substr(0, std::min<std::size_t>(bytes.size(), 1 << 16)));
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return h;
  h.ply = true;
  while (std::getline(in, line)) {
    std::istringstream w(line);
    std::string word, name;
    w >> word;
    if (word == "end_header") break;
    if (word == "format") {
      w >> name;
      h.binary = name.rfind("binary", 0) == 0;
    } else if (word == "element") {
      std::size_t n = 0;
      w >> name >> n;
      if (name == "vertex") h.vertices = n;
      if (name == "face") h.faces = n;
      if (name == "edge") h.edges = n;
    }
  }
  return h;
}

bool has_ply_extension(const std::string& path) {
  if (path.size() < 4) return false;
  std::string ext = path.substr(path.size() - 4);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".ply";
}

// Neighbouring quads of a G-map may wind either way (patch_mesh.hpp);
// OpenMesh's halfedge mesh needs one orientation. Breadth-first over shared
// edges, each quad is reversed when it walks a shared edge the same way as
// the neighbour it was reached from. Throws ModelError for a patch that is
// not orientable (a Moebius band).
std::vector<std::array<ParticleId, 4>> orient_alike(std::vector<std::array<ParticleId, 4>> quads, BlockId b) {
  std::map<std::pair<ParticleId, ParticleId>, std::vector<std::size_t>> faces_of;  // undirected edge -> quads
  auto key = [](ParticleId a, ParticleId c) { return std::pair{std::min(a, c), std::max(a, c)}; };
  for (std::size_t f = 0; f < quads.size(); ++f)
    for (int k = 0; k < 4; ++k) faces_of[key(quads[f][k], quads[f][(k + 1) % 4])].push_back(f);
  auto walks = [&](std::size_t f, ParticleId a, ParticleId c) {  // quad f has the directed edge a -> c
    for (int k = 0; k < 4; ++k)
      if (quads[f][k] == a && quads[f][(k + 1) % 4] == c) return true;
    return false;
  };
  std::vector<int> state(quads.size(), 0);  // 0 unvisited, 1 placed
  for (std::size_t seed = 0; seed < quads.size(); ++seed) {
    if (state[seed]) continue;
    state[seed] = 1;
    std::vector<std::size_t> queue{seed};
    for (std::size_t at = 0; at < queue.size(); ++at) {
      const std::size_t f = queue[at];
      for (int k = 0; k < 4; ++k) {
        const ParticleId a = quads[f][k], c = quads[f][(k + 1) % 4];
        for (std::size_t g : faces_of[key(a, c)]) {
          if (g == f) continue;
          if (!state[g]) {
            if (walks(g, a, c)) std::reverse(quads[g].begin(), quads[g].end());
            state[g] = 1;
            queue.push_back(g);
          } else if (walks(g, a, c)) {
            throw ModelError("save_ply: patch " + std::to_string(b) + " is not orientable; write ASCII PLY");
          }
        }
      }
    }
  }
  return quads;
}

}  // namespace

ImportedMesh read_binary_ply(const std::string& bytes, const std::string& name) {
  const Header h = header_of(bytes);
  if (!h.ply) throw InputError(name + ": a PLY file starts with 'ply'");
  if (h.edges > 0)
    throw InputError(name + ": a binary PLY's edges are not read (OpenMesh reads faces); save it as ASCII PLY");
  Mesh mesh;
  OpenMesh::IO::Options options = OpenMesh::IO::Options::Binary;
  std::istringstream in(bytes);
  if (!OpenMesh::IO::read_mesh(mesh, in, ".ply", options))
    throw InputError(name + ": OpenMesh could not read this binary PLY");
  // OpenMesh splits the vertices of what is not manifold, or drops faces:
  // a model built from an altered drawing would mislead.
  if (mesh.n_vertices() != h.vertices || mesh.n_faces() != h.faces)
    throw InputError(name + ": OpenMesh read " + std::to_string(mesh.n_vertices()) + " of " +
                     std::to_string(h.vertices) + " vertices and " + std::to_string(mesh.n_faces()) + " of " +
                     std::to_string(h.faces) + " faces (it splits or drops what is not manifold); save it as ASCII PLY");
  ImportedMesh out;
  for (const auto& v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    out.vertices.push_back(Vec3(p[0], p[1], p[2]));
  }
  ImportedGroup group;
  group.name = "faces";  // as an ASCII PLY's faces without a block property
  for (const auto& f : mesh.faces()) {
    std::vector<std::size_t> face;
    for (const auto& v : mesh.fv_range(f)) face.push_back(std::size_t(v.idx()));
    group.faces.push_back(std::move(face));
  }
  if (!group.faces.empty()) out.groups.push_back(std::move(group));
  return out;
}

ImportedMesh import_mesh_file(const std::string& path) {
  if (has_ply_extension(path)) {
    const std::string bytes = read_input_file(path);
    if (header_of(bytes).binary) return read_binary_ply(bytes, path);
    return parse_ply(bytes, path);
  }
  return import_mesh(path);
}

std::string patches_ply_binary(const Model& m) {
  Mesh mesh;
  std::vector<Mesh::VertexHandle> vertex(m.particles.capacity());
  std::vector<std::pair<BlockId, std::vector<std::array<ParticleId, 4>>>> patches;
  std::vector<bool> used(m.particles.capacity(), false);
  for (BlockId b : m.live_blocks()) {
    if (m.blocks[b].kind != BlockKind::Patch) continue;
    const PatchMesh pm = patch_mesh(m, b, "save_ply");
    std::vector<std::array<ParticleId, 4>> quads;
    for (const QuadIndices& q : pm.mesh.quads) {
      quads.push_back({pm.particles[q[0]], pm.particles[q[1]], pm.particles[q[2]], pm.particles[q[3]]});
      for (ParticleId p : quads.back()) used[p] = true;
    }
    patches.emplace_back(b, orient_alike(std::move(quads), b));
  }
  if (patches.empty()) throw ModelError("save_ply: a binary PLY holds patches, and the model has none");
  for (ParticleId p = 0; p < m.particles.capacity(); ++p)
    if (used[p]) {
      const Vec3& x = m.particles.position[p];
      vertex[p] = mesh.add_vertex(Mesh::Point(x.x(), x.y(), x.z()));
    }
  for (const auto& [b, quads] : patches)
    for (const auto& q : quads)
      if (!mesh.add_face(vertex[q[0]], vertex[q[1]], vertex[q[2]], vertex[q[3]]).is_valid())
        throw ModelError("save_ply: patch " + std::to_string(b) +
                         " is not a manifold surface OpenMesh can hold (patches sharing an edge?); write ASCII PLY");
  std::ostringstream out;
  if (!OpenMesh::IO::write_mesh(mesh, out, ".ply", OpenMesh::IO::Options::Binary))
    throw ModelError("save_ply: OpenMesh could not write the binary PLY");
  return out.str();
}

}  // namespace tendril::meshing
