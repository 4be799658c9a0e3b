#include "io/gltf.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/obj.hpp"

namespace tendril {

namespace {

const char* const kColours[] = {"kind", "axial", "moment", "stress", "utilisation", "s1"};

std::array<float, 3> kind_colour(BlockKind k) {
  switch (k) {
    case BlockKind::Beam: return {0.25f, 0.25f, 0.25f};
    case BlockKind::Cable: return {0.95f, 0.55f, 0.1f};
    case BlockKind::Bar: return {0.2f, 0.4f, 0.9f};
    case BlockKind::Patch: return {0.85f, 0.85f, 0.85f};
  }
  return {0.5f, 0.5f, 0.5f};
}

constexpr std::array<float, 3> kGrey = {0.6f, 0.6f, 0.6f};

// Vertices and colours of one primitive, glTF's y-up frame.
struct Primitive {
  std::vector<float> position, colour;
  void add(const Vec3& x, const std::array<float, 3>& c) {
    position.insert(position.end(), {float(x.x()), float(x.z()), float(-x.y())});
    colour.insert(colour.end(), c.begin(), c.end());
  }
  std::size_t count() const { return position.size() / 3; }
};

}  // namespace

bool gltf_colour_known(const std::string& name) {
  return std::find(std::begin(kColours), std::end(kColours), name) != std::end(kColours);
}

std::array<float, 3> gltf_ramp(double t) {
  t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0);
  if (t < 0.5) {
    const float u = float(2 * t);  // blue -> white
    return {u, u, 1.0f};
  }
  const float u = float(2 * (1 - t));  // white -> red
  return {1.0f, u, u};
}

std::string gltf_bytes(const Model& m, const GltfOptions& o) {
  const std::string& by = o.colour;
  if (!gltf_colour_known(by))
    throw ModelError("export_gltf: no colour '" + by + "' (kind, axial, moment, stress, utilisation, s1)");
  if ((by == "stress" || by == "utilisation") && !(o.sections && o.sections->any()))
    throw ModelError("export_gltf: colour '" + by + "' needs a section (tendril.section.rod/tube/rect)");
  if (by == "utilisation" && !o.sections->any_strength())
    throw ModelError("export_gltf: colour 'utilisation' needs a section with a material's strength");
  const Vec3* x = m.particles.position.data();
  const std::vector<BlockId> blocks = m.live_blocks();
  std::vector<BlockResults> results;
  for (BlockId b : blocks) results.push_back(element_results(m, b, o.sections ? o.sections->of(b) : nullptr));
  // The scale of the field: its largest magnitude over the model.
  double scale = 0;
  for (const BlockResults& r : results) {
    for (const LineResult& l : r.lines) {
      if (by == "axial") scale = std::max(scale, std::abs(l.axial));
      if (by == "moment") scale = std::max(scale, l.moment);
      if (by == "stress" && std::isfinite(l.stress)) scale = std::max(scale, l.stress);
    }
    if (by == "s1")
      for (const TriangleResult& t : r.triangles) scale = std::max(scale, t.s1);
  }
  if (by == "utilisation") scale = 1;
  auto line_colour = [&](BlockKind kind, const LineResult& l) {
    if (by == "kind") return kind_colour(kind);
    if (by == "s1" || !(scale > 0)) return kGrey;
    if (by == "axial") return gltf_ramp(0.5 + 0.5 * l.axial / scale);
    const double v = by == "moment" ? l.moment : by == "stress" ? l.stress : l.utilisation;
    return std::isfinite(v) ? gltf_ramp(v / scale) : kGrey;
  };
  Primitive lines, faces;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const BlockKind kind = m.blocks[blocks[k]].kind;
    for (const LineResult& l : results[k].lines) {
      const std::array<float, 3> c = line_colour(kind, l);
      lines.add(x[l.a], c);
      lines.add(x[l.b], c);
    }
    for (const TriangleResult& t : results[k].triangles) {
      const std::array<float, 3> c =
          by == "kind" ? kind_colour(kind) : by == "s1" && scale > 0 ? gltf_ramp(t.s1 / scale) : kGrey;
      for (ParticleId p : {t.i, t.j, t.k}) faces.add(x[p], c);
    }
    if (kind == BlockKind::Patch && results[k].triangles.empty())  // a patch of bars: its quads
      for (const auto& f : patch_faces(m, blocks[k]))
        for (std::size_t c = 1; c + 1 < f.size(); ++c)
          for (ParticleId p : {f[0], f[c], f[c + 1]}) faces.add(x[p], by == "kind" ? kind_colour(kind) : kGrey);
  }

  tinygltf::Model g;
  g.asset.version = "2.0";
  g.asset.generator = "tendril";
  g.asset.copyright = "";
  g.buffers.emplace_back();
  std::vector<unsigned char>& bytes = g.buffers[0].data;
  auto view = [&](const std::vector<float>& data) {
    tinygltf::BufferView v;
    v.buffer = 0;
    v.byteOffset = bytes.size();
    v.byteLength = data.size() * sizeof(float);
    v.target = TINYGLTF_TARGET_ARRAY_BUFFER;
    const std::size_t at = bytes.size();
    bytes.resize(at + v.byteLength);
    if (v.byteLength) std::memcpy(bytes.data() + at, data.data(), v.byteLength);
    g.bufferViews.push_back(v);
    return int(g.bufferViews.size() - 1);
  };
  auto accessor = [&](const std::vector<float>& data, bool bounds) {
    tinygltf::Accessor a;
    a.bufferView = view(data);
    a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    a.count = data.size() / 3;
    a.type = TINYGLTF_TYPE_VEC3;
    if (bounds) {  // POSITION needs them (glTF 2.0, 3.7.2.1)
      a.minValues = {1e300, 1e300, 1e300};
      a.maxValues = {-1e300, -1e300, -1e300};
      for (std::size_t k = 0; k < data.size(); ++k) {
        a.minValues[k % 3] = std::min(a.minValues[k % 3], double(data[k]));
        a.maxValues[k % 3] = std::max(a.maxValues[k % 3], double(data[k]));
      }
    }
    g.accessors.push_back(a);
    return int(g.accessors.size() - 1);
  };
  tinygltf::Material material;
  material.name = "vertex colours";
  material.pbrMetallicRoughness.metallicFactor = 0;
  material.pbrMetallicRoughness.roughnessFactor = 1;
  material.doubleSided = true;
  g.materials.push_back(material);
  tinygltf::Mesh mesh;
  mesh.name = "tendril";
  for (const auto& [p, mode] : {std::pair{&lines, TINYGLTF_MODE_LINE}, std::pair{&faces, TINYGLTF_MODE_TRIANGLES}}) {
    if (!p->count()) continue;
    tinygltf::Primitive prim;
    prim.mode = mode;
    prim.material = 0;
    prim.attributes["POSITION"] = accessor(p->position, true);
    prim.attributes["COLOR_0"] = accessor(p->colour, false);
    mesh.primitives.push_back(prim);
  }
  g.buffers[0].data.resize((bytes.size() + 3) / 4 * 4);  // GLB chunks are 4-byte aligned
  if (!mesh.primitives.empty()) {
    g.meshes.push_back(mesh);
    tinygltf::Node node;
    node.mesh = 0;
    node.name = "tendril model (m, y up)";
    g.nodes.push_back(node);
  }
  tinygltf::Scene scene;
  if (!g.nodes.empty()) scene.nodes.push_back(0);
  g.scenes.push_back(scene);
  g.defaultScene = 0;
  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&g, out, false, true)) throw ModelError("export_gltf: tinygltf could not write the model");
  return out.str();
}

void save_gltf(const Model& m, const std::string& path, const GltfOptions& options) {
  write_file_atomically(path, gltf_bytes(m, options));
}

}  // namespace tendril
