// The thresholds and severities of the contour checks. Lengths and curvatures are relative to
// units per em (UPM), so a check means the same at any em size; lengths given "in units" are
// for 1000 UPM and scale with it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "check/finding.hpp"
#include "geom/join.hpp"

namespace gf {

struct CheckProfile {
  std::string name;
  // kink: a join meant smooth but broken (lac-math-independent; the definition)
  double kink_min_deg = 0.05, kink_max_deg = 3.0;
  // g2-jump at smooth joins: relative jump above 5% where max|κ|·UPM ≥ 0.5, else |Δκ|·UPM > 0.05
  CurvatureJumpRule g2;
  // missing-extremum: farther than 1% of the segment's length from its ends, no node within 0.5 units
  double extremum_end_fraction = 0.01, extremum_node_distance_em = 0.0005;
  // short-segment (fontbakery outline_short_segments): below 3 units or 0.6% of the contour
  double short_segment_em = 0.003, short_segment_contour_fraction = 0.006;
  // semi-horizontal / semi-vertical lines (fontbakery outline_semi_vertical): within 0.5°, not exact
  double semi_hv_max_deg = 0.5;
  // collinear-handles: a curve whose control points lie within 0.1% of its chord's length from
  // it: a straight line drawn as a curve (the bend would be invisible)
  double collinear_handles_ratio = 0.001;
  // Curvature radius below 1/1000 em counts as 1/1000 em in the fairness figures (a corner-like
  // retracted handle would otherwise make the total variation infinite).
  double fairness_curvature_cap_em = 1000.0;

  std::map<std::string, Severity> severity;
  std::vector<std::string> relaxed;  ///< what this profile relaxes, said in every report

  Severity severity_of(const std::string& check) const;
};

/// "text" (professional text fonts) or "handwriting" (fonts traced from scans and pens, where
/// fontbakery itself warns extrema fixes can do harm); nullopt for any other name.
std::optional<CheckProfile> check_profile(const std::string& name);

/// Every check id, in report order.
const std::vector<std::string>& check_ids();

}  // namespace gf
