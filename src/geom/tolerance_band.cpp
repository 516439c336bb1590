#include "geom/tolerance_band.hpp"

#include <algorithm>

namespace gf {

namespace {

// The source polyline along the indices `at` (sorted) and `pad` points either way: on a closed
// source, the way round that leaves out the largest gap between them.
std::vector<Vec2> stretch_around(std::span<const std::size_t> at, std::span<const Vec2> source, std::size_t pad) {
  const bool closed = source.size() > 2 && source.front() == source.back();
  const std::size_t n = closed ? source.size() - 1 : source.size();  // distinct points
  std::size_t first = at.front(), last = at.back();
  if (closed) {
    // The gap after at[k] runs to at[k + 1]; the last gap wraps round to at.front().
    std::size_t widest = n - at.back() + at.front(), after = at.size() - 1;
    for (std::size_t k = 0; k + 1 < at.size(); ++k)
      if (at[k + 1] - at[k] > widest) widest = at[k + 1] - at[k], after = k;
    first = at[(after + 1) % at.size()], last = at[after];
    const std::size_t span = (last + n - first) % n + 1;
    if (span + 2 * pad >= n) return {source.begin(), source.end()};
    std::vector<Vec2> out;
    for (std::size_t k = 0; k < span + 2 * pad; ++k) out.push_back(source[(first + n - pad + k) % n]);
    return out;
  }
  first = first > pad ? first - pad : 0;
  last = std::min(last + pad, n - 1);
  return {source.begin() + static_cast<std::ptrdiff_t>(first), source.begin() + static_cast<std::ptrdiff_t>(last) + 1};
}

}  // namespace

ToleranceBand::ToleranceBand(const PolylineGrid& faired, std::span<const std::size_t> piece_of,
                             std::span<const Vec2> source, double bound)
    : bound_(bound) {
  if (piece_of.empty() || faired.points().empty() || source.empty()) return;
  const std::size_t pieces = *std::max_element(piece_of.begin(), piece_of.end()) + 1;
  answering_.resize(pieces);
  stretch_.resize(pieces);
  std::vector<std::vector<std::size_t>> at(pieces);
  for (std::size_t k = 0; k < source.size(); ++k) {
    const std::size_t piece = piece_of[faired.nearest(source[k]).segment];
    answering_[piece].push_back(source[k]);
    at[piece].push_back(k);
  }
  for (std::size_t p = 0; p < pieces; ++p)
    if (!at[p].empty()) stretch_[p] = stretch_around(at[p], source, stretch_pad);
}

bool ToleranceBand::holds(std::size_t piece, std::span<const Vec2> replacement) const {
  if (replacement.empty() || piece >= stretch_.size() || stretch_[piece].empty()) return false;
  return directed_hausdorff(answering_[piece], replacement, bound_) <= bound_ &&
         directed_hausdorff(replacement, stretch_[piece], bound_) <= bound_;
}

}  // namespace gf
