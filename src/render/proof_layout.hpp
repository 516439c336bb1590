// Page geometry of a proof page (A4 portrait, points) and the map from font units to a panel.
#pragma once

#include "geom/vec2.hpp"

namespace gf {

struct Box {
  double x0, y0, x1, y1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

namespace page {
inline constexpr double width = 595.28;
inline constexpr double height = 841.89;
inline constexpr Box header{36, 28, 559.28, 62};
inline constexpr Box glyph_panel{36, 70, 559.28, 560};
inline constexpr Box plot_panel{36, 580, 559.28, 790};
inline constexpr Box legend{36, 800, 559.28, 826};
}  // namespace page

/// Font units (y up) to page points (y down), uniform scale.
struct PanelMap {
  double scale = 1.0;
  double origin_x = 0.0;  ///< page x of font x = 0
  double origin_y = 0.0;  ///< page y of font y = 0
  Vec2 operator()(Vec2 p) const { return {origin_x + p.x * scale, origin_y - p.y * scale}; }
};

/// The largest map that shows `content` (font units) inside `panel`, centred.
PanelMap fit(const Box& content, const Box& panel);

}  // namespace gf
