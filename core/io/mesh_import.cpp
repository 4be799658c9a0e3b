// Reading OBJ and ASCII PLY geometry (mesh_import.hpp).
#include "io/mesh_import.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include "io/input_file.hpp"

namespace tendril {

namespace {

[[noreturn]] void refuse(const std::string& name, std::size_t line, const std::string& why) {
  throw InputError(name + ":" + std::to_string(line) + ": " + why);
}

std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

double number(const std::string& w, const std::string& name, std::size_t line) {
  double x = 0;
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), x);
  if (ec != std::errc() || end != w.data() + w.size() || !std::isfinite(x))
    refuse(name, line, "'" + w + "' is not a finite number");
  return x;
}

long long integer(const std::string& w, const std::string& name, std::size_t line) {
  long long k = 0;
  const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), k);
  if (ec != std::errc() || end != w.data() + w.size()) refuse(name, line, "'" + w + "' is not a whole number");
  return k;
}

// The groups in first-appearance order, found by name.
struct Groups {
  std::vector<ImportedGroup> list;
  std::map<std::string, std::size_t> index;
  ImportedGroup& operator[](const std::string& name) {
    const auto [it, added] = index.emplace(name, list.size());
    if (added) list.push_back({name, {}, {}});
    return list[it->second];
  }
  std::vector<ImportedGroup> take() {
    std::vector<ImportedGroup> out;
    for (ImportedGroup& g : list)
      if (!g.lines.empty() || !g.faces.empty()) out.push_back(std::move(g));
    return out;
  }
};

}  // namespace

ImportedMesh parse_obj(const std::string& text, const std::string& name) {
  ImportedMesh mesh;
  Groups groups;
  std::string group = "default";
  std::istringstream in(text);
  std::size_t line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    const std::vector<std::string> w = words(line);
    if (w.empty()) continue;
    if (w[0] == "v") {
      if (w.size() < 4) refuse(name, line_number, "a vertex needs x y z");
      mesh.vertices.emplace_back(number(w[1], name, line_number), number(w[2], name, line_number),
                                 number(w[3], name, line_number));
    } else if (w[0] == "g" || w[0] == "o") {
      group = w.size() > 1 ? w[1] : "default";
      for (std::size_t k = 2; k < w.size(); ++k) group += " " + w[k];
    } else if (w[0] == "l" || w[0] == "f") {
      std::vector<std::size_t> ids;
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::string first = w[k].substr(0, w[k].find('/'));  // v of v/vt/vn
        long long i = integer(first, name, line_number);
        if (i < 0) i += (long long)mesh.vertices.size() + 1;  // -1: the last vertex so far
        if (i < 1 || i > (long long)mesh.vertices.size())
          refuse(name, line_number, "vertex " + first + " is not among the " + std::to_string(mesh.vertices.size()) +
                                        " vertices so far");
        ids.push_back(std::size_t(i - 1));
      }
      if (w[0] == "l") {
        if (ids.size() < 2) refuse(name, line_number, "a polyline needs at least 2 vertices");
        groups[group].lines.push_back(std::move(ids));
      } else {
        if (ids.size() < 3) refuse(name, line_number, "a face needs at least 3 vertices");
        groups[group].faces.push_back(std::move(ids));
      }
    }
  }
  mesh.groups = groups.take();
  return mesh;
}

ImportedMesh parse_ply(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  std::size_t line_number = 0;
  std::string line;
  auto next = [&]() -> std::vector<std::string> {
    while (std::getline(in, line)) {
      ++line_number;
      std::vector<std::string> w = words(line);
      if (!w.empty()) return w;
    }
    refuse(name, line_number, "the file ends early");
  };
  if (next() != std::vector<std::string>{"ply"}) refuse(name, line_number, "a PLY file starts with 'ply'");
  struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<std::string> properties;  // a list property named by its name
    std::vector<bool> list;
  };
  std::vector<Element> elements;
  for (;;) {
    const std::vector<std::string> w = next();
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (w.size() < 2 || w[1] != "ascii") refuse(name, line_number, "only ASCII PLY is read (save it as ASCII)");
    } else if (w[0] == "element") {
      if (w.size() != 3) refuse(name, line_number, "an element needs a name and a count");
      const long long n = integer(w[2], name, line_number);
      if (n < 0) refuse(name, line_number, "a negative count");
      elements.push_back({w[1], std::size_t(n), {}, {}});
    } else if (w[0] == "property") {
      if (elements.empty()) refuse(name, line_number, "a property before any element");
      const bool list = w.size() > 1 && w[1] == "list";
      if (w.size() != (list ? 5u : 3u)) refuse(name, line_number, "a property needs a type and a name");
      elements.back().properties.push_back(w.back());
      elements.back().list.push_back(list);
    } else if (w[0] != "comment" && w[0] != "obj_info") {
      refuse(name, line_number, "'" + w[0] + "' is not a PLY header line");
    }
  }
  ImportedMesh mesh;
  Groups groups;
  auto column = [](const Element& e, const char* property) {
    const auto it = std::find(e.properties.begin(), e.properties.end(), property);
    return it == e.properties.end() ? -1 : int(it - e.properties.begin());
  };
  for (const Element& e : elements) {
    const int x = column(e, "x"), y = column(e, "y"), z = column(e, "z");
    const int v1 = column(e, "vertex1"), v2 = column(e, "vertex2"), block = column(e, "block");
    int indices = column(e, "vertex_indices");
    if (indices < 0) indices = column(e, "vertex_index");
    for (std::size_t k = 0; k < e.count; ++k) {
      const std::vector<std::string> w = next();
      std::vector<std::string> values;  // one per property; a list's values joined after its count
      std::vector<std::vector<std::size_t>> lists(e.properties.size());
      std::size_t at = 0;
      for (std::size_t p = 0; p < e.properties.size(); ++p) {
        if (at >= w.size()) refuse(name, line_number, "too few values for its " + e.name);
        if (e.list[p]) {
          const long long n = integer(w[at++], name, line_number);
          if (n < 0 || at + std::size_t(n) > w.size()) refuse(name, line_number, "a list runs past the line");
          for (long long i = 0; i < n; ++i) {
            const long long v = integer(w[at++], name, line_number);
            if (v < 0) refuse(name, line_number, "a negative vertex index");
            lists[p].push_back(std::size_t(v));
          }
          values.emplace_back();
        } else {
          values.push_back(w[at++]);
        }
      }
      if (e.name == "vertex") {
        if (x < 0 || y < 0 || z < 0) refuse(name, line_number, "a vertex needs properties x, y and z");
        mesh.vertices.emplace_back(number(values[std::size_t(x)], name, line_number),
                                   number(values[std::size_t(y)], name, line_number),
                                   number(values[std::size_t(z)], name, line_number));
        continue;
      }
      const std::string group = block >= 0 ? "block-" + values[std::size_t(block)] : e.name == "edge" ? "edges" : "faces";
      auto vertex = [&](std::size_t v) {
        if (v >= mesh.vertices.size())
          refuse(name, line_number, "vertex " + std::to_string(v) + " is not among the " +
                                        std::to_string(mesh.vertices.size()) + " vertices");
        return v;
      };
      if (e.name == "edge") {
        if (v1 < 0 || v2 < 0) refuse(name, line_number, "an edge needs properties vertex1 and vertex2");
        const long long a = integer(values[std::size_t(v1)], name, line_number);
        const long long b = integer(values[std::size_t(v2)], name, line_number);
        if (a < 0 || b < 0) refuse(name, line_number, "a negative vertex index");
        // An edge that starts where the group's last polyline ends continues
        // it: a beam written segment by segment reads back as one polyline.
        std::vector<std::vector<std::size_t>>& lines = groups[group].lines;
        if (!lines.empty() && lines.back().back() == vertex(std::size_t(a))) lines.back().push_back(vertex(std::size_t(b)));
        else lines.push_back({vertex(std::size_t(a)), vertex(std::size_t(b))});
      } else if (e.name == "face") {
        if (indices < 0) refuse(name, line_number, "a face needs a vertex_indices list");
        std::vector<std::size_t> f;
        for (std::size_t v : lists[std::size_t(indices)]) f.push_back(vertex(v));
        if (f.size() < 3) refuse(name, line_number, "a face needs at least 3 vertices");
        groups[group].faces.push_back(std::move(f));
      }
    }
  }
  mesh.groups = groups.take();
  return mesh;
}

ImportedMesh import_mesh(const std::string& path) {
  std::string ext = path.size() >= 4 ? path.substr(path.size() - 4) : "";
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".obj") return parse_obj(read_input_file(path), path);
  if (ext == ".ply") return parse_ply(read_input_file(path), path);
  throw InputError(path + ": tendril imports .obj and .ply files");
}

}  // namespace tendril
