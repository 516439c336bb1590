// Shapes tests build by hand: a closed polygon of lines, and a node of an unrounded outline.
#pragma once

#include <optional>
#include <vector>

#include "fair/outline_nodes.hpp"
#include "geom/contour.hpp"

namespace gf::test {

/// The closed contour of lines through `corners`, in order, no node flagged.
inline Contour polygon(const std::vector<Vec2>& corners) {
  Contour c;
  for (std::size_t k = 0; k < corners.size(); ++k) c.segments.push_back(Line{{corners[k], corners[(k + 1) % corners.size()]}});
  c.nodes.assign(c.segments.size(), NodeFlags{});
  return c;
}

/// A node of an unrounded outline: its handles where it has them, a corner unless smooth.
inline OutlineNode node(Vec2 point, std::optional<Vec2> in, std::optional<Vec2> out, bool smooth = true,
                        std::optional<Vec2> grid_step = std::nullopt) {
  return OutlineNode{point, in, out, smooth, grid_step};
}

}  // namespace gf::test
