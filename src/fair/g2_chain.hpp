// G2 continuity for a chain of log-aesthetic segments by rotating the tangents at the
// junctions (seed 000 [0074]–[0082], seed 001 §3.4–3.5; lac-math.md §6.1). The junction
// points stay fixed; segment i is the 3-point segment of slope α_i on (Q_i, P1_i, Q_{i+1}),
// P1_i where the tangent lines meet; the mismatch at junction j is
// D_j = κ_end(segment j−1) − κ_start(segment j), curvature signed along the chain.
// An open chain may end in κ = 0 (an inflection, or a curve meeting a line tangentially):
// that end segment is the inflection-end segment of §3, its α solved rather than given.
// A closed chain wraps around: segment n−1 runs from Q_{n−1} back to Q_0.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "aesthetic/log_aesthetic_segment.hpp"
#include "aesthetic/segment_fit.hpp"

namespace gf {

struct LacChain {
  std::vector<Vec2> points;            ///< Q_0 … Q_n (open) or Q_0 … Q_{n−1} (closed)
  std::vector<double> tangent_angles;  ///< φ per point, radians
  std::vector<double> alphas;          ///< α per segment (ignored for a κ = 0 end segment)
  bool closed = false;
  bool zero_curvature_start = false;  ///< open chains: κ = 0 at Q_0
  bool zero_curvature_end = false;    ///< open chains: κ = 0 at Q_n

  std::size_t segment_count() const { return closed ? points.size() : points.size() - 1; }
  /// The junctions whose tangents the G2 solve rotates: all of a closed chain, the interior
  /// ones of an open chain.
  std::size_t first_free_junction() const { return closed ? 0 : 1; }
  std::size_t free_junction_count() const { return closed ? points.size() : points.size() - 2; }
};

struct ChainSegments {
  std::vector<LogAestheticSegment> segments;  ///< empty when some segment has no solution
  std::string reason;
  std::size_t failed_segment = 0;  ///< the segment found without a solution, when not ok()
  bool ok() const { return !segments.empty(); }
};

/// Whether segment i's end tangents meet in front of both its ends (its control triangle exists).
bool tangents_meet_in_front(const LacChain& chain, std::size_t i);

/// Segment i of the chain alone; `near_log_end_ratio` as fit_three_point's (that of the
/// segment's fit to nearly the same points, where the solve starts).
SegmentFit build_chain_segment(const LacChain& chain, std::size_t i,
                               std::optional<double> near_log_end_ratio = std::nullopt);

/// Every segment, or none when one has no solution. Whether all tangent triangles exist is
/// checked before any fit, and the fits start at `first_to_fit` (cyclically): a line search
/// whose step failed at some segment tries that segment first with the next, shorter step.
ChainSegments build_chain(const LacChain& chain, std::size_t first_to_fit = 0);

/// D_j at the free junctions, in the order of LacChain::first_free_junction().
std::vector<double> curvature_mismatch(const LacChain& chain, const std::vector<LogAestheticSegment>& segments);

/// What max |D_j| must reach: the larger of an absolute bound and a bound relative to the
/// largest end curvature of the starting chain (so one setting serves every font size).
struct G2Tolerance {
  double absolute = 1e-12;
  double relative = 0.0;
  G2Tolerance() = default;
  G2Tolerance(double absolute_tolerance) : absolute(absolute_tolerance) {}  // NOLINT: a bare number is absolute
  G2Tolerance(double absolute_tolerance, double relative_tolerance)
      : absolute(absolute_tolerance), relative(relative_tolerance) {}
};

struct G2Result {
  LacChain chain;                             ///< with the solved junction tangents
  std::vector<LogAestheticSegment> segments;  ///< the last feasible chain (empty: none was)
  std::vector<double> mismatches;             ///< D_j of `segments`, as curvature_mismatch gives them
  double max_mismatch = 0.0;                  ///< max |D_j| reached
  double curvature_scale = 0.0;               ///< max |κ| at the segment ends of the starting chain
  int iterations = 0;
  bool converged = false;  ///< max |D_j| ≤ tolerance
  std::string reason;      ///< why not, when not
};

/// Newton on all free angles at once with a finite-difference Jacobian (each D_j depends on
/// φ_{j−1}, φ_j, φ_{j+1}) and a backtracking line search that stays where every segment
/// exists (the feasible range is only about 0.1–0.4 rad per junction, §6.1); where Newton
/// stalls, one sweep of the seeds' junction-by-junction bisection. The end tangents of an
/// open chain stay as given.
G2Result make_g2(LacChain chain, G2Tolerance tolerance = {}, int max_iterations = 50);

}  // namespace gf
