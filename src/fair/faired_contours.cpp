#include "fair/faired_contours.hpp"

#include <variant>

#include "geom/value_hash.hpp"

namespace gf {

namespace {

// The source's points, node flags and closure, and the settings that vary between glyphs.
std::size_t hash_of(const Contour& c, const FairSettings& settings) {
  ValueHash h;
  for (const Segment& s : c.segments) {
    h.add(static_cast<double>(s.index()));
    std::visit([&](const auto& b) { for (const Vec2 p : b.p) h.add(p); }, s);
  }
  for (const NodeFlags& n : c.nodes) h.add(n.implied).add(n.smooth ? (*n.smooth ? 1.0 : 0.0) : -1.0);
  h.add(c.closed).add(static_cast<double>(settings.rounding)).add(settings.tolerance_units);
  return h.value();
}

}  // namespace

ContourFairing FairedContours::fair(const Contour& source, const FairSettings& settings) {
  const std::size_t hash = hash_of(source, settings);
  const auto find = [&]() -> const Entry* {
    const auto [first, last] = entries_.equal_range(hash);
    for (auto e = first; e != last; ++e)
      if (e->second.source == source && e->second.settings == settings) return &e->second;
    return nullptr;
  };
  {
    const std::lock_guard lock(mutex_);
    if (const Entry* known = find()) return known->result;
  }
  ContourFairing result = fair_contour(source, settings);  // unlocked: the other threads go on
  const std::lock_guard lock(mutex_);
  if (find()) return result;  // another thread faired it meanwhile
  if (capacity_ == 0) return result;
  if (order_.size() == capacity_) {
    const auto [oldest_hash, oldest_serial] = order_.front();
    order_.pop_front();
    const auto [first, last] = entries_.equal_range(oldest_hash);
    for (auto e = first; e != last; ++e)
      if (e->second.serial == oldest_serial) {
        entries_.erase(e);
        break;
      }
  }
  entries_.emplace(hash, Entry{serial_, source, settings, result});
  order_.emplace_back(hash, serial_++);
  return result;
}

std::size_t FairedContours::size() const {
  const std::lock_guard lock(mutex_);
  return entries_.size();
}

}  // namespace gf
