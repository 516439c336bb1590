#include "geom/tolerance_band.hpp"

#include <algorithm>

namespace gf {

ToleranceBand::ToleranceBand(const PolylineGrid& faired, std::span<const std::size_t> piece_of,
                             const PolylineGrid& source, double bound)
    : source_(&source), bound_(bound) {
  if (piece_of.empty() || faired.points().empty()) return;
  answering_.resize(*std::max_element(piece_of.begin(), piece_of.end()) + 1);
  for (const Vec2 p : source.points()) answering_[piece_of[faired.nearest(p).segment]].push_back(p);
}

bool ToleranceBand::holds(std::size_t piece, std::span<const Vec2> replacement) const {
  if (replacement.empty()) return false;
  // The middle first: where a piece moved too far shows most.
  if (source_->distance_to(replacement[replacement.size() / 2]) > bound_) return false;
  for (const Vec2 p : replacement)
    if (source_->distance_to(p) > bound_) return false;
  if (piece >= answering_.size() || answering_[piece].empty()) return true;
  return directed_hausdorff(answering_[piece], replacement, bound_) <= bound_;
}

}  // namespace gf
