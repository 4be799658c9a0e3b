#include "io/trace.hpp"

#include "io/model_xml.hpp"

#include <cstdio>
#include <cstdlib>
#include <istream>
#include <sstream>

namespace tendril {

void Trace::record(const Solver& s, const std::string& line) {
  if (s.steps() > traced_steps_) {
    lines_.push_back("steps " + std::to_string(s.steps() - traced_steps_));
    traced_steps_ = s.steps();
  }
  lines_.push_back(line);
}

std::vector<std::string> Trace::lines(const Solver& s) const {
  std::vector<std::string> out = lines_;
  if (s.steps() > traced_steps_) out.push_back("steps " + std::to_string(s.steps() - traced_steps_));
  return out;
}

std::string Trace::number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

std::string Trace::vec(const Vec3& v) { return number(v.x()) + " " + number(v.y()) + " " + number(v.z()); }

std::string Trace::patch_formulation(BlockId b, const Membrane& m, const std::vector<Model::Triangle>& triangles) {
  std::string line = "formulation " + std::to_string(b) + " " + membrane_mode_name(m.mode);
  if (m.cst()) line += " " + number(m.sigma_warp) + " " + number(m.sigma_weft);
  if (m.mode == Membrane::Analysis)
    for (double d : {m.dxx, m.dxy, m.dyx, m.dyy, m.G}) line += " " + number(d);
  for (const Model::Triangle& t : triangles)
    for (ParticleId p : t) line += " " + std::to_string(p);
  return line;
}

std::string Trace::section(const Section& s) {
  return number(s.EA) + " " + number(s.EI) + " " + number(s.prestress) + " " + number(s.line_mass);
}

namespace {

struct Reader {
  std::istringstream words;
  std::string where;
  std::string word() {
    std::string w;
    if (!(words >> w)) throw ModelError(where + ": the line ends too early");
    return w;
  }
  double number() { return number_of(word()); }
  double number_of(const std::string& w) {
    char* end = nullptr;
    double x = std::strtod(w.c_str(), &end);
    if (end == w.c_str() || *end) throw ModelError(where + ": '" + w + "' is not a number");
    return x;
  }
  std::uint32_t id() { return id_of(word()); }
  std::uint32_t id_of(const std::string& w) {
    double x = number_of(w);
    if (x < 0 || x != std::uint32_t(x)) throw ModelError(where + ": '" + w + "' is not an id");
    return std::uint32_t(x);
  }
  Vec3 vec() {
    double x = number(), y = number(), z = number();
    return Vec3(x, y, z);
  }
  Section section() {
    Section s;
    s.EA = number();
    s.EI = number();
    s.prestress = number();
    s.line_mass = number();
    return s;
  }
  std::vector<ParticleId> rest() {  // the ids up to the end of the line
    std::vector<ParticleId> ids;
    for (std::string w; words >> w;) ids.push_back(id_of(w));
    return ids;
  }
};

Damping damping_from(const std::string& name, const std::string& where) {
  if (name == "kinetic") return Damping::Kinetic;
  if (name == "viscous") return Damping::Viscous;
  if (name == "none") return Damping::None;
  throw ModelError(where + ": unknown damping '" + name + "'");
}

}  // namespace

void replay_trace(std::istream& in, const std::string& name, Model& m, Solver& s) {
  std::string line;
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    Reader r{std::istringstream(line), name + ":" + std::to_string(number)};
    const std::string op = r.word();
    try {
      if (op == "particle") m.add_particle(r.vec());
      else if (op == "open") {  // a model database the scene started from
        std::string path;
        std::getline(r.words >> std::ws, path);
        load_model_xml(path, m, s.settings);
      }
      else if (op == "cable") {
        ParticleId a = r.id(), b = r.id();
        Section sec = r.section();
        m.add_cable(a, b, sec, r.number());
      } else if (op == "beam") {
        bool closed = r.number() != 0;
        Section sec = r.section();
        m.add_beam(r.rest(), sec, closed);
      } else if (op == "beam_from") {
        ParticleId p = r.id();
        Vec3 d = r.vec();
        int n = int(r.number());
        m.add_beam_from(p, d, n, r.section());
      } else if (op == "quad_grid") {
        int rows = int(r.number()), cols = int(r.number());
        Section sec = r.section();
        m.add_quad_grid(r.rest(), rows, cols, sec);
      } else if (op == "patch") {
        Section sec = r.section();
        std::vector<ParticleId> ids = r.rest();
        if (ids.size() % 4) throw ModelError(r.where + ": a patch needs four particles per quad");
        std::vector<Model::Quad> quads;
        for (std::size_t k = 0; k < ids.size(); k += 4) quads.push_back({ids[k], ids[k + 1], ids[k + 2], ids[k + 3]});
        m.add_patch(quads, sec);
      } else if (op == "extend") {
        BlockId b = r.id();
        ParticleId end = r.id();
        m.extend_beam(b, end, r.id());
      } else if (op == "section6") {  // a beam's 6-DOF stiffnesses, set while it is still 3 DOF
        BlockId b = r.id();
        m.require_block(b, "section6");
        if (m.blocks[b].dofs != 3) throw ModelError(r.where + ": section6 on a beam that is already 6 DOF");
        Section sec = m.blocks[b].section;
        sec.GJ = r.number();
        sec.EIy = r.number();
        sec.EIz = r.number();
        m.blocks[b].section = sec;
      } else if (op == "formulation") {
        BlockId b = r.id();
        const std::string kind = r.word();
        if (kind == "bars" || kind == "form" || kind == "analysis") {  // a patch (thesis 5.5.2.2)
          Membrane mem;
          if (kind != "bars") {
            mem.mode = kind == "form" ? Membrane::FormFinding : Membrane::Analysis;
            mem.sigma_warp = r.number();
            mem.sigma_weft = r.number();
          }
          if (kind == "analysis") {
            mem.dxx = r.number();
            mem.dxy = r.number();
            mem.dyx = r.number();
            mem.dyy = r.number();
            mem.G = r.number();
          }
          const std::vector<ParticleId> ids = r.rest();
          if (ids.size() % 3) throw ModelError(r.where + ": CST triangles need three particles each");
          std::vector<Model::Triangle> tris;
          for (std::size_t k = 0; k < ids.size(); k += 3) tris.push_back({ids[k], ids[k + 1], ids[k + 2]});
          m.set_patch_formulation(b, mem, tris);
        } else {
          m.set_beam_formulation(b, int(r.number_of(kind)));
        }
      } else if (op == "orientation") {
        ParticleId p = r.id();
        const double w = r.number(), x = r.number(), y = r.number(), z = r.number();
        m.set_orientation(p, Quat(w, x, y, z));
      } else if (op == "torque") {
        ParticleId p = r.id();
        m.set_moment(p, r.vec());
      } else if (op == "joint") {
        ParticleId p = r.id();
        const double angle = r.number();
        m.add_joint(p, angle, r.number());
      } else if (op == "joint_angle") {
        std::size_t j = r.id();
        m.set_joint_angle(j, r.number());
      } else if (op == "goal") {
        Goal g;
        if (!parse_goal_kind(r.word(), g.kind)) throw ModelError(r.where + ": unknown goal kind");
        g.i = r.id();
        if (g.kind == Goal::Length) {
          g.j = r.id();
          g.length = r.number();
        } else {
          g.point = r.vec();
        }
        if (g.kind == Goal::Plane || g.kind == Goal::Line) g.direction = r.vec();
        g.weight = r.number();
        m.add_goal(g);
      } else if (op == "goal_weight") {
        const std::size_t k = r.id();
        m.set_goal_weight(k, r.number());
      } else if (op == "remove_goal") m.remove_goal(r.id());
      else if (op == "delete_particle") m.delete_particle(r.id());
      else if (op == "merge") m.merge(r.rest());
      else if (op == "explode") m.explode(r.id());
      else if (op == "explode_from") {
        ParticleId p = r.id();
        m.explode_from(p, r.id());
      } else if (op == "delete") {
        BlockId b = r.id();
        m.require_block(b, "delete");
        if (m.blocks[b].kind == BlockKind::Cable) m.delete_cable(b);
        else if (m.blocks[b].kind == BlockKind::Patch) m.delete_patch(b);
        else m.delete_beam(b);
      } else if (op == "insert") {
        ParticleId a = r.id();
        m.insert_particle(a, r.id());
      } else if (op == "split") {
        BlockId b = r.id();
        m.split_beam(b, r.id());
      } else if (op == "rest_length") {
        ParticleId a = r.id(), b = r.id();
        m.set_rest_length(a, b, r.number());
      } else if (op == "remove_from_beam") m.remove_from_beam(r.id());
      else if (op == "remove_from_patch") m.remove_from_patch(r.id());
      else if (op == "merge_patches") {
        const BlockId a = r.id();
        m.merge_patches(a, r.id());
      } else if (op == "lock") {
        ParticleId p = r.id();
        m.set_lock(p, std::uint8_t(r.number()));
      } else if (op == "role") {
        ParticleId p = r.id();
        const double role = r.number();
        if (role < 0 || role > double(Role::Volatile)) throw ModelError(r.where + ": unknown role");
        m.set_role(p, Role(int(role)));
      } else if (op == "passive") {
        ParticleId p = r.id();
        m.set_passive(p, r.number() != 0);
      } else if (op == "load") {
        ParticleId p = r.id();
        m.set_load(p, r.vec());
      } else if (op == "mass") {
        ParticleId p = r.id();
        m.set_point_mass(p, r.number());
      } else if (op == "position") {
        ParticleId p = r.id();
        m.require_particle(p, "position");
        m.particles.position[p] = r.vec();
      } else if (op == "gravity") m.gravity = r.vec();
      else if (op == "settings") {
        std::string kv;
        while (r.words >> kv) {
          const auto eq = kv.find('=');
          if (eq == std::string::npos) throw ModelError(r.where + ": expected key=value, got '" + kv + "'");
          const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
          if (key == "damping") s.settings.damping = damping_from(value, r.where);
          else if (key == "integrator") {
            auto i = parse_integrator(value);
            if (!i) throw ModelError(r.where + ": unknown integrator '" + value + "'");
            s.settings.integrator = *i;
          } else if (key == "mixed_implicit") {
            auto i = parse_integrator(value);
            if (!i || (*i != Integrator::VariationalImplicitEuler && *i != Integrator::ProjectiveDynamics))
              throw ModelError(r.where + ": mixed_implicit must be vie or projective, got '" + value + "'");
            s.settings.mixed_implicit = *i;
          } else if (key == "mass_mode") {
            auto mm = parse_mass_mode(value);
            if (!mm) throw ModelError(r.where + ": unknown mass mode '" + value + "'");
            s.settings.mass_mode = *mm;
          }
          else {
            double x = std::strtod(value.c_str(), nullptr);
            if (key == "dt") s.settings.dt = x;
            else if (key == "viscous") s.settings.viscous = x;
            else if (key == "geometric_factor") s.settings.geometric_factor = x;
            else if (key == "mass_factor") s.settings.mass_factor = x;
            else if (key == "vie_iterations") s.settings.vie_iterations = int(x);
            else if (key == "vie_dt") s.settings.vie_dt = x;
            else if (key == "mixed_switch") s.settings.mixed_switch = x;
            else throw ModelError(r.where + ": unknown setting '" + key + "'");
          }
        }
      } else if (op == "steps") {
        const double n = r.number();
        for (double k = 0; k < n; ++k) s.step();
      } else {
        throw ModelError(r.where + ": unknown operation '" + op + "'");
      }
    } catch (const NumericalError&) {
      throw;
    } catch (const ModelError& e) {
      const std::string what = e.what();
      if (what.rfind(name + ":", 0) == 0) throw;
      throw ModelError(r.where + ": " + what);
    }
  }
}

}  // namespace tendril
