// Shapes tests build by hand: a closed polygon of lines, a node of an unrounded outline, and
// Comic Neue's i stem.
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

/// Comic Neue's i stem (1000 units per em): two lines 0.8° off the vertical, each meeting a
/// round cap tangentially.
inline Contour comic_neue_i_stem() {
  Contour c;
  c.segments = {Cubic{{{111, -6}, {128, -6}, {143, 9}, {143, 26}}}, Line{{{143, 26}, {149, 460}}},
                Cubic{{{149, 460}, {149, 478}, {135, 493}, {117, 493}}},
                Cubic{{{117, 493}, {100, 493}, {84, 478}, {84, 460}}}, Line{{{84, 460}, {78, 26}}},
                Cubic{{{78, 26}, {78, 9}, {93, -6}, {111, -6}}}};
  c.nodes.assign(6, NodeFlags{});
  return c;
}

}  // namespace gf::test
