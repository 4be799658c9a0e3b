#include "topology/gmap.hpp"

#include <algorithm>
#include <stdexcept>

namespace tendril {

GMap::GMap() {
  for (auto& a : alpha_) a.attach(&log_);
  alive_.attach(&log_);
  free_list_.attach(&log_);
}

Dart GMap::create_dart() {
  Dart d;
  if (!free_list_.empty()) {
    d = free_list_.back();
    free_list_.pop_back();
    for (auto& c : columns_) c->reset(d);
  } else {
    d = static_cast<Dart>(alive_.size());
    for (auto& a : alpha_) a.push_back(d);
    alive_.push_back(0);
    if (stamp_.size() < alive_.size()) stamp_.push_back(0);  // scratch: never shrinks
    for (auto& c : columns_) c->grow();
  }
  for (auto& a : alpha_) a[d] = d;
  alive_[d] = 1;
  log_.scalar(live_);
  ++live_;
  return d;
}

void GMap::delete_dart(Dart d) {
  if (!alive(d)) throw std::logic_error("delete_dart: dart is not alive");
  for (int i = 0; i < 3; ++i)
    if (!is_free(i, d)) throw std::logic_error("delete_dart: dart is still linked");
  alive_[d] = 0;
  free_list_.push_back(d);
  log_.scalar(live_);
  --live_;
}

void GMap::link(int i, Dart a, Dart b) {
  if (!alive(a) || !alive(b)) throw std::logic_error("link: dart is not alive");
  if (!is_free(i, a) || !is_free(i, b)) throw std::logic_error("link: dart is not free");
  alpha_[i][a] = b;
  alpha_[i][b] = a;
}

void GMap::unlink(int i, Dart d) {
  Dart e = alpha_[i][d];
  alpha_[i][d] = d;
  alpha_[i][e] = e;
}

bool GMap::visit_once(Dart y, std::uint32_t epoch, std::vector<Dart>* seen) const {
  if (!seen) {
    if (stamp_[y] == epoch) return false;
    stamp_[y] = epoch;
    return true;
  }
  auto it = std::lower_bound(seen->begin(), seen->end(), y);
  if (it != seen->end() && *it == y) return false;
  seen->insert(it, y);
  return true;
}

std::vector<Dart> GMap::orbit(unsigned mask, Dart d) const {
  std::vector<Dart> out;
  for_orbit(mask, d, [&](Dart x) {
    out.push_back(x);
    return true;
  });
  return out;
}

std::size_t GMap::orbit_size(unsigned mask, Dart d) const {
  std::size_t n = 0;
  for_orbit(mask, d, [&](Dart) {
    ++n;
    return true;
  });
  return n;
}

std::string GMap::check() const {
  for (Dart d = 0; d < alive_.size(); ++d) {
    if (!alive_[d]) continue;
    for (int i = 0; i < 3; ++i) {
      Dart e = alpha_[i][d];
      if (e >= alive_.size() || !alive_[e])
        return "dart " + std::to_string(d) + ": alpha" + std::to_string(i) + " points to a dead dart";
      if (alpha_[i][e] != d)
        return "dart " + std::to_string(d) + ": alpha" + std::to_string(i) + " is not an involution";
    }
    // Quasi-manifold: alpha0 o alpha2 must be an involution.
    Dart e = alpha_[2][alpha_[0][d]];
    if (alpha_[2][alpha_[0][e]] != d)
      return "dart " + std::to_string(d) + ": alpha0 o alpha2 is not an involution";
  }
  return {};
}

}  // namespace tendril
