// A faired chain read as pieces of one curve by arc length: what the writeback follows and the
// G3 solve re-expresses, whether the chain is log-aesthetic segments, G3 spirals or a stretch
// of the smoothing guide.
#pragma once

#include <functional>
#include <vector>

#include "aesthetic/log_aesthetic_segment.hpp"
#include "fair/faired_run.hpp"

namespace gf {

/// A stretch of the path that turns one way by less than a half turn: a log-aesthetic segment,
/// a G3 spiral, or a piece of a guide cut where its curvature changes sign and every quarter
/// turn.
struct PathPiece {
  double length;
  std::function<LacPoint(double)> at;                ///< by arc length from the piece's start
  std::function<std::vector<LacPoint>(int)> sample;  ///< n + 1 points uniform in arc length
  bool after_sign_change = false;  ///< a guide's piece that starts where its curvature changes sign
};

/// One piece per curve (log-aesthetic segments or spirals); the curves must outlive them.
template <class Curve>
std::vector<PathPiece> curve_pieces(const std::vector<Curve>& curves) {
  std::vector<PathPiece> out;
  for (const Curve& c : curves)
    out.push_back({c.length(), [&c](double s) { return c.at(s); }, [&c](int n) { return c.sample(n); }});
  return out;
}

/// The guide stretch in pieces, cut where its curvature changes sign and every quarter turn
/// and, given `at_curvature_extrema`, where κ turns back by a hundredth of the stretch's largest
/// |κ| (each piece's κ then monotone, as a log-aesthetic segment's is), its end frames in place
/// of the guide's own at its two ends (`whole_loop`: the stretch is a whole closed guide, whose
/// frames are its own throughout). A change of sign before |κ| first passes that hundredth or
/// after it last does, within a twentieth of the stretch of its end, is a nearly straight end's
/// wander: not cut, and that end's frame flat where its κ is the wander's. The guide must
/// outlive them.
std::vector<PathPiece> guide_pieces(const GuideStretch& g, bool whole_loop, bool at_curvature_extrema);

/// A chain's pieces: its guide's, its spirals' or its segments'.
std::vector<PathPiece> chain_pieces(const FairedChain& chain);

}  // namespace gf
