#include "static_view.hpp"

#include <filesystem>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "fields.hpp"
#include "frames.hpp"
#include "io/input_file.hpp"
#include "io/model_xml.hpp"
#include "command/replay.hpp"
#include "io/trace.hpp"
#include "timeline.hpp"

namespace tendril::studio {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

std::string base64(const std::string& in) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  std::size_t k = 0;
  for (; k + 2 < in.size(); k += 3) {
    const unsigned v = unsigned(std::uint8_t(in[k])) << 16 | unsigned(std::uint8_t(in[k + 1])) << 8 | std::uint8_t(in[k + 2]);
    for (int s = 18; s >= 0; s -= 6) out += kAlphabet[(v >> s) & 63];
  }
  if (k < in.size()) {
    unsigned v = unsigned(std::uint8_t(in[k])) << 16;
    if (k + 1 < in.size()) v |= unsigned(std::uint8_t(in[k + 1])) << 8;
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += k + 1 < in.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

json entry(const Model& m, const Solver& s, const std::string& label) {
  const Topology t = topology_of(m);
  json maps = json::object();
  for (const Field& f : fields()) {
    const std::vector<float> v = f.values(m, t);
    maps[f.name] = base64(std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(float)));
  }
  return {{"label", label},
          {"step", s.steps()},
          {"topology", base64(encode(t))},
          {"frame", base64(encode_frame(m, s, t, {}))},
          {"fields", maps}};
}

// The journal's models after its productions (at most max_entries of them).
json journal_timeline(const std::string& path, std::size_t max_entries) {
  std::vector<std::string> lines;
  std::istringstream in(read_input_file(path));
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  std::vector<std::size_t> prods;
  for (std::size_t k = 0; k < lines.size(); ++k)
    if (is_production(lines[k])) prods.push_back(k);
  if (prods.empty()) throw std::runtime_error(path + ": the journal holds no production");
  std::vector<bool> keep(lines.size(), false);
  const std::size_t n = std::min(max_entries, prods.size());
  for (std::size_t i = 1; i <= n; ++i) keep[prods[(i * prods.size()) / n - 1]] = true;  // the last is kept
  Model m;
  Solver s(m);
  json timeline = json::array();
  std::size_t production = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    std::istringstream one(lines[k]);
    replay_trace(one, path + " (production " + std::to_string(production + 1) + ")", m, s);
    if (is_production(lines[k])) ++production;
    if (keep[k])
      timeline.push_back(entry(m, s, "production " + std::to_string(production) + " of " + std::to_string(prods.size()) +
                                         ", step " + std::to_string(s.steps())));
  }
  if (!is_production(lines.back()))  // the steps after the last production: the model the journal ends with
    timeline.push_back(entry(m, s, "the end of the journal, step " + std::to_string(s.steps())));
  return timeline;
}

// The page's file, its script and style sheet inlined.
std::string page(const std::string& web_dir) {
  const fs::path dir = fs::path(web_dir) / "view";
  const fs::path html_path = dir / "view.html";
  if (!fs::exists(html_path))
    throw std::runtime_error("the view page is not built (" + html_path.string() + " is missing): run `bash tools/setup.sh`");
  std::string html = read_input_file(html_path.string());
  auto inline_asset = [&](const std::regex& tag, const char* open, const char* close) {
    std::smatch m;
    if (!std::regex_search(html, m, tag)) throw std::runtime_error(html_path.string() + ": no asset to inline");
    std::string body = read_input_file((dir / m[1].str()).string());
    for (std::size_t at = 0; (at = body.find("</", at)) != std::string::npos; at += 3) body.replace(at, 2, "<\\/");
    html = m.prefix().str() + open + body + close + m.suffix().str();
  };
  inline_asset(std::regex(R"re(<script type="module" crossorigin src="\./([^"]+)"></script>)re"), "<script type=\"module\">", "</script>");
  inline_asset(std::regex(R"re(<link rel="stylesheet" crossorigin href="\./([^"]+)">)re"), "<style>", "</style>");
  return html;
}

}  // namespace

std::string static_view(const std::string& input, const std::string& web_dir, std::size_t max_entries) {
  fs::path source = input;
  if (fs::is_directory(source)) {
    if (fs::exists(source / "journal.txt")) source /= "journal.txt";
    else if (fs::exists(source / "model.xml")) source /= "model.xml";
    else {
      std::vector<fs::path> xml;
      for (const auto& e : fs::directory_iterator(source))
        if (e.path().extension() == ".xml") xml.push_back(e.path());
      if (xml.size() != 1)
        throw std::runtime_error(input + ": a folder needs journal.txt, model.xml or exactly one .xml file");
      source = xml[0];
    }
  }
  json timeline;
  if (source.extension() == ".xml") {
    Model m;
    Solver s(m);
    load_model_xml(source.string(), m, s.settings);
    timeline = json::array({entry(m, s, source.filename().string())});
  } else {
    timeline = journal_timeline(source.string(), max_entries);
  }
  json f = json::array();
  for (const Field& field : fields()) f.push_back({{"name", field.name}, {"unit", field.unit}});
  std::string data = json{{"title", source.string()}, {"fields", f}, {"timeline", timeline}}.dump();
  for (std::size_t at = 0; (at = data.find("</", at)) != std::string::npos; at += 3) data.replace(at, 2, "<\\/");
  std::string html = page(web_dir);
  const std::string tag = "<script id=\"tendril-data\" type=\"application/json\">" + data + "</script>\n";
  const std::size_t body = html.find("<body>");
  if (body == std::string::npos) throw std::runtime_error("the view page has no <body>");
  html.insert(body + 6, "\n" + tag);
  return html;
}

}  // namespace tendril::studio
