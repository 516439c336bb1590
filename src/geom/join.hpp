// How a contour's segments meet at its on-curve nodes: tangent angle, curvature and dκ/ds on
// both sides, and the kind of join that makes.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "geom/contour.hpp"

namespace gf {

enum class JoinKind {
  smooth,      ///< tangents agree (G1) to within JoinThresholds::smooth_max_deg
  kink,        ///< meant smooth but broken: a small angle, or flagged smooth by the source
  corner,      ///< a real corner
  degenerate,  ///< a neighbouring segment has no direction (all its points coincide)
};

struct JoinThresholds {
  double smooth_max_deg = 0.05;
  double kink_max_deg = 3.0;
};

struct Join {
  std::size_t node = 0;  ///< index of the node in its contour
  Vec2 point;
  JoinKind kind = JoinKind::corner;
  /// Signed turning from the incoming to the outgoing tangent, degrees in (-180, 180].
  double angle_deg = 0.0;
  std::optional<double> curvature_in, curvature_out;
  std::optional<double> curvature_derivative_in, curvature_derivative_out;
};

/// The rule a jump of curvature at a smooth join is judged by (the fairing issue's check):
/// relative to the larger side where that side's |κ|·UPM is at least `large_em`, else by
/// |Δκ|·UPM, a curve that flat having no curvature to compare by ratio.
struct CurvatureJumpRule {
  double relative = 0.05, absolute_em = 0.05, large_em = 0.5;
};

/// How far κ jumps at a join, as a CurvatureJumpRule measures it.
struct CurvatureJump {
  double value = 0.0;    ///< relative to the larger side, or |Δκ|·UPM
  bool relative = true;  ///< which of the two
  double limit = 0.0;    ///< what the rule allows
  bool exceeds() const { return value > limit; }
};

/// The jump from curvature `in` to `out`.
CurvatureJump curvature_jump(double in, double out, double units_per_em, const CurvatureJumpRule& rule = {});

/// None where a side of `j` has no curvature (a retracted handle: unbounded).
std::optional<CurvatureJump> curvature_jump(const Join& j, double units_per_em, const CurvatureJumpRule& rule = {});

/// The kind of a join turning by `angle_deg` (signed or not), `flagged_smooth` where the source
/// flags its node smooth (a kink however far it turns).
JoinKind join_kind(double angle_deg, bool flagged_smooth, const JoinThresholds& thresholds = {});

/// The joins of a contour: every node of a closed one, the interior nodes of an open one.
std::vector<Join> joins_of(const Contour& c, const JoinThresholds& thresholds = {});

const char* to_string(JoinKind kind);

}  // namespace gf
