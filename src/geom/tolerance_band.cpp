#include "geom/tolerance_band.hpp"

#include <algorithm>

namespace gf {

namespace {

// The source polyline along the indices `at` (sorted) and `pad` units of it either way: on a
// closed source, the way round that leaves out the largest gap between them.
std::vector<Vec2> stretch_around(std::span<const std::size_t> at, std::span<const Vec2> source, double pad) {
  const bool closed = source.size() > 2 && source.front() == source.back();
  const std::size_t n = closed ? source.size() - 1 : source.size();  // distinct points
  std::size_t first = at.front(), last = at.back();
  if (closed) {
    // The gap after at[k] runs to at[k + 1]; the last gap wraps round to at.front().
    std::size_t widest = n - at.back() + at.front(), after = at.size() - 1;
    for (std::size_t k = 0; k + 1 < at.size(); ++k)
      if (at[k + 1] - at[k] > widest) widest = at[k + 1] - at[k], after = k;
    first = at[(after + 1) % at.size()] % n, last = at[after] % n;
  }
  // Points from `first` to `last` (round the seam on a closed source), then `pad` more either way.
  std::size_t count = closed ? (last + n - first) % n + 1 : last - first + 1;
  const auto step_back = [&](std::size_t k) { return closed ? (k + n - 1) % n : k - 1; };
  for (double back = 0.0; back < pad && count < n && (closed || first > 0); ++count) {
    back += distance(source[first], source[step_back(first)]);
    first = step_back(first);
  }
  for (double ahead = 0.0; ahead < pad && count < n && (closed || last + 1 < n); ++count) {
    ahead += distance(source[last], source[(last + 1) % n]);
    last = (last + 1) % n;
  }
  if (closed && count >= n) return {source.begin(), source.end()};
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < count; ++k) out.push_back(source[(first + k) % n]);
  return out;
}

}  // namespace

ToleranceBand::ToleranceBand(std::span<const Vec2> source, std::span<const NearestPiece> answers, double bound)
    : bound_(bound) {
  if (source.empty() || answers.size() != source.size()) return;
  std::size_t pieces = 0;
  for (const NearestPiece& a : answers) pieces = std::max(pieces, a.piece + 1);
  answering_.resize(pieces);
  stretch_.resize(pieces);
  std::vector<std::vector<std::size_t>> at(pieces);
  for (std::size_t k = 0; k < source.size(); ++k) {
    answering_[answers[k].piece].push_back(source[k]);
    at[answers[k].piece].push_back(k);
  }
  for (std::size_t p = 0; p < pieces; ++p)
    if (!at[p].empty()) stretch_[p] = stretch_around(at[p], source, stretch_pad * bound);
}

bool ToleranceBand::holds(std::size_t piece, std::span<const Vec2> replacement) const {
  return holds_along(piece, replacement, replacement);
}

bool ToleranceBand::holds_along(std::size_t piece, std::span<const Vec2> replacement, std::span<const Vec2> along) const {
  if (replacement.empty() || along.empty() || piece >= stretch_.size() || stretch_[piece].empty()) return false;
  return directed_hausdorff(answering_[piece], along, bound_) <= bound_ &&
         directed_hausdorff(replacement, stretch_[piece], bound_) <= bound_;
}

}  // namespace gf
