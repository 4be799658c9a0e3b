// A uniform pressure on a patch (pneumatic cushions, inflated tubes, wind
// and snow on a membrane): per block a value and a side; the oriented quads
// are derived from the map when the solver needs them (its cache follows
// the model's revision), so every rule that rewrites the patch is followed.
//
// Orientation: in a generalized map a dart and its alpha_i images have
// opposite orientations, so the darts reached from one dart by words of
// even length are one side of an orientable surface. A face is walked from
// one of its darts d along (alpha1 alpha0)^k d; across an edge, the
// neighbour's dart alpha2 alpha0 x walks the shared edge the other way.
#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "model/model.hpp"

namespace tendril {

namespace {

std::string bid(BlockId b) { return std::to_string(b); }

// The oriented faces of patch b, each walked from one of its darts of the
// block dart's side; false when the patch is not orientable.
bool oriented_faces(const Model& m, BlockId b, std::vector<Model::Quad>& out) {
  const GMap& map = m.map;
  std::unordered_map<Dart, bool> side;  // dart -> on the block dart's side
  // Claims the face of dart f for the side of f: its four darts of that
  // side and the four of the other; false on a dart already on the other.
  auto claim = [&](Dart f) {
    Dart y = f;
    for (int k = 0; k < 4; ++k) {  // patches are quads (add_patch): the walk closes after four
      if (!side.emplace(y, true).first->second) return false;
      const Dart back = map.alpha(0, y);
      if (side.emplace(back, false).first->second) return false;
      y = map.alpha(1, back);
    }
    return true;
  };
  std::vector<Dart> queue{m.blocks[b].dart};
  if (!claim(queue[0])) return false;
  out.clear();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    Model::Quad q{};
    Dart x = queue[head];
    for (int k = 0; k < 4; ++k) {
      q[k] = m.dart_particle[x];
      const Dart back = map.alpha(0, x);
      if (!map.is_free(2, back)) {  // the neighbour across this edge, walked the other way
        const Dart next = map.alpha(2, back);
        const auto it = side.find(next);
        if (it == side.end()) {
          if (!claim(next)) return false;
          queue.push_back(next);
        } else if (!it->second) {
          return false;  // reached from both sides: a Moebius strip
        }
      }
      x = map.alpha(1, back);
    }
    out.push_back(q);
  }
  return true;
}

Vec3 area_vector(const Particles& P, const Model::Quad& q) {
  return 0.5 * (P.position[q[2]] - P.position[q[0]]).cross(P.position[q[3]] - P.position[q[1]]);
}

}  // namespace

void Model::set_pressure(BlockId b, double p, const Vec3& towards) {
  require_block(b, "pressure");
  if (blocks[b].kind != BlockKind::Patch) throw ModelError("pressure: block " + bid(b) + " is not a patch");
  if (!std::isfinite(p)) throw ModelError("pressure: the pressure must be a finite number [Pa]");
  if (!towards.allFinite()) throw ModelError("pressure: the direction must be finite");
  std::vector<Quad> faces;
  if (p != 0 && !oriented_faces(*this, b, faces))
    throw ModelError("pressure: patch " + bid(b) + " is not orientable (a Moebius strip): a pressure has no side");
  blocks[b].pressure = p;
  blocks[b].pressure_towards = towards;
  ++revision;
}

void Model::set_area_load(BlockId b, double q, const Vec3& direction) {
  require_block(b, "area_load");
  if (blocks[b].kind != BlockKind::Patch) throw ModelError("area_load: block " + bid(b) + " is not a patch");
  if (!std::isfinite(q)) throw ModelError("area_load: the load must be a finite number [N/m^2]");
  if (!direction.allFinite() || !(direction.norm() > 0))
    throw ModelError("area_load: the direction must be a finite, non-zero vector");
  std::vector<Quad> faces;
  if (q != 0 && !oriented_faces(*this, b, faces))
    throw ModelError("area_load: patch " + bid(b) + " is not orientable (a Moebius strip)");
  blocks[b].area_load = q;
  // A unit vector is kept as given (normalising it again could move its last
  // bit, and a saved model would not load back to the same bytes).
  const bool unit = std::abs(direction.norm() - 1) <= 4 * std::numeric_limits<double>::epsilon();
  blocks[b].area_load_direction = q == 0 ? Vec3::Zero() : unit ? direction : Vec3(direction.normalized());
  ++revision;
}

std::vector<Model::Quad> Model::area_load_quads(BlockId b) const {
  std::vector<Quad> faces;
  if (blocks[b].area_load == 0 || !oriented_faces(*this, b, faces)) return {};
  return faces;
}

std::vector<Model::Quad> Model::pressure_quads(BlockId b) const {
  std::vector<Quad> faces;
  if (blocks[b].pressure == 0 || !oriented_faces(*this, b, faces)) return {};
  const Vec3& towards = blocks[b].pressure_towards;
  double measure = 0;
  if (towards != Vec3::Zero()) {
    for (const Quad& q : faces) measure += area_vector(particles, q).dot(towards);
  } else {  // outward: away from the centroid of the corners
    Vec3 centre = Vec3::Zero();
    for (const Quad& q : faces)
      for (ParticleId c : q) centre += particles.position[c];
    centre /= double(4 * faces.size());
    for (const Quad& q : faces) {
      const Vec3 mid = 0.25 * (particles.position[q[0]] + particles.position[q[1]] + particles.position[q[2]] +
                               particles.position[q[3]]);
      measure += area_vector(particles, q).dot(mid - centre);
    }
  }
  if (measure < 0)
    for (Quad& q : faces) std::swap(q[1], q[3]);
  return faces;
}

}  // namespace tendril
