// A point of an aesthetic curve as JSON, the same in every output that reports one (`glyphfair
// curve`'s samples, `fair --segments`' piece ends): point, tangent angle, κ and dκ/ds (null
// where unbounded or not known), in that order.
#pragma once

#include <nlohmann/json.hpp>

#include "aesthetic/log_aesthetic_segment.hpp"

namespace gf {

inline nlohmann::ordered_json lac_point_json(const LacPoint& p) {
  using json = nlohmann::ordered_json;
  return {{"point", {p.point.x, p.point.y}},
          {"tangent_angle", angle_of(p.tangent)},
          {"curvature", p.curvature},
          {"dcurvature_ds", p.curvature_derivative ? json(*p.curvature_derivative) : json(nullptr)}};
}

}  // namespace gf
