// The corners of a faired contour that came out turning by less than the kink limit: noise the
// fairing straightened (or a scan's few degrees at a line), which the contour fairing makes
// smooth and fairs again (fair/contour_fairing.cpp).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "geom/contour.hpp"

namespace gf {

/// A corner of the plan: the source node and where the faired pieces meet there.
struct CornerJoin {
  std::size_t source_node;
  Vec2 point;
};

/// The source nodes of `corners` whose faired corner turns by less than the kink limit. Each
/// is found at the faired node nearest where its pieces met (rounding may have moved it a
/// unit); where that node is smooth and the end of a line no longer than 8 units whose other
/// end is a corner, at that corner (dkg Bold under G3: p's corner before a 1-unit line went to
/// (328, 227) and the line's smooth end to the corner's (329, 228), and a 2.1° kink was kept;
/// j's, 6 units along its line, kept 0.8°). An open contour's ends are no corners here.
std::vector<std::size_t> kinked_corners(const Contour& faired, std::span<const CornerJoin> corners);

}  // namespace gf
