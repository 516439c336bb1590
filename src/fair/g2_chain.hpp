// G2 continuity for a chain of log-aesthetic segments by rotating the tangents at the
// junctions (seed 000 [0074]–[0082], seed 001 §3.4–3.5; lac-math.md §6.1). The junction
// points stay fixed; segment i is the 3-point segment of slope α_i on (Q_i, P1_i, Q_{i+1}),
// P1_i where the tangent lines meet; the mismatch at interior junction j is
// D_j = κ_end(segment j−1) − κ_start(segment j), curvature signed along the chain.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "aesthetic/log_aesthetic_segment.hpp"

namespace gf {

struct LacChain {
  std::vector<Vec2> points;            ///< Q_0 … Q_n
  std::vector<double> tangent_angles;  ///< φ_0 … φ_n, radians
  std::vector<double> alphas;          ///< α_0 … α_{n−1}
};

struct ChainSegments {
  std::vector<LogAestheticSegment> segments;  ///< empty when some segment has no solution
  std::string reason;
  bool ok() const { return !segments.empty(); }
};

ChainSegments build_chain(const LacChain& chain);

/// D_1 … D_{n−1}.
std::vector<double> curvature_mismatch(const std::vector<LogAestheticSegment>& segments);

struct G2Result {
  LacChain chain;                             ///< with the solved interior tangents
  std::vector<LogAestheticSegment> segments;  ///< the last feasible chain
  double max_mismatch = 0.0;                  ///< max |D_j| reached
  int iterations = 0;
  bool converged = false;  ///< max |D_j| ≤ tolerance
  std::string reason;      ///< why not, when not
};

/// Newton on all interior angles at once with a finite-difference Jacobian (each D_j depends
/// on φ_{j−1}, φ_j, φ_{j+1}) and a backtracking line search that stays where every segment
/// exists (the feasible range is only about 0.1–0.4 rad per junction, §6.1). The end
/// tangents stay as given.
G2Result make_g2(LacChain chain, double tolerance = 1e-12, int max_iterations = 50);

}  // namespace gf
