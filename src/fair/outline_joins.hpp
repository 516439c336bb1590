// Which nodes of a rounded outline join two cubics, meet a line or are corners, and what
// curvature jumps there: what the choice of whole-step handles (fair/handle_steps) measures.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "fair/outline_nodes.hpp"

namespace gf {

/// Which nodes of an outline join two cubics, meet a line, or start a cubic.
struct OutlineJoins {
  const std::vector<OutlineNode>& nodes;
  bool closed;

  std::size_t size() const { return nodes.size(); }
  bool is_cubic(std::size_t i) const {
    const std::size_t n = size();
    return (closed || i + 1 < n) && nodes[i].out_handle && nodes[(i + 1) % n].in_handle;
  }
  bool interior(std::size_t i) const { return closed || (i > 0 && i + 1 < size()); }
  /// A smooth node between two cubics couples them.
  bool joins_cubics(std::size_t i) const {
    return interior(i) && nodes[i].smooth && is_cubic(i) && is_cubic((i + size() - 1) % size());
  }
  /// A smooth node between a cubic and a line wants κ = 0 on its cubic's side.
  bool meets_line(std::size_t i) const {
    return interior(i) && nodes[i].smooth && is_cubic(i) != is_cubic((i + size() - 1) % size());
  }
};

/// How far node k turns, radians (absolute), with its in-handle or out-handle replaced where
/// given; a side with no handle (a line) runs from or to the neighbouring node; π at an open
/// outline's ends and where a side has no length (its tangent comes from farther points).
double turn_at(const std::vector<OutlineNode>& nodes, bool closed, std::size_t k, std::optional<Vec2> in = {},
               std::optional<Vec2> out = {});

/// Whether node k of the unrounded outline is a corner rounding must not turn under the kink
/// limit (cubic_choices): the kink pass (fair/contour_fairing) would make it smooth, and the
/// corner the source drew would be lost. Any corner turning by the limit or more (a–z A–Z,
/// Lato's x at 3.0°, its Y at 3.2° and Carlito's v at 3.1° went so while only corners a degree
/// past the limit were kept: Lato lost 6, Carlito 9; then 2 and 3). Between two cubics only
/// from a degree past it until stop 73 (EB Garamond's W had found no rounding within the
/// tolerance, until the writeback cut its long strokes along longer grid directions): EB
/// Garamond lost 8 such corners of 3.3–3.5°, Comic Neue 2; now 2 and 0.
bool corner_to_keep(const std::vector<OutlineNode>& ideal, bool closed, std::size_t k);

/// Whether node k of `nodes` turns less than its unrounded self (`ideal`) did, or than the kink
/// limit where that turned more, beyond float noise (a smooth node where a curve meets a line
/// turns by 4e-16 radians unrounded and 0 on the grid: Carlito's x).
bool turns_less_than_it_did(const std::vector<OutlineNode>& nodes, const std::vector<OutlineNode>& ideal, bool closed,
                            std::size_t k);

/// The curvatures at node k of the cubic arriving there and the one leaving it.
std::pair<double, double> curvatures_at(const std::vector<OutlineNode>& nodes, std::size_t k);

/// The curvature jump at node k (relative_jump): between its two cubics, or from zero where it
/// meets a line; none elsewhere.
double join_jump(const OutlineJoins& joins, std::size_t k, double flat);

}  // namespace gf
