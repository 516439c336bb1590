#include "render/proof_layout.hpp"

#include <algorithm>

namespace gf {

PanelMap fit(const Box& content, const Box& panel) {
  const double w = std::max(content.width(), 1e-9), h = std::max(content.height(), 1e-9);
  const double scale = std::min(panel.width() / w, panel.height() / h);
  const double used_w = w * scale, used_h = h * scale;
  const double left = panel.x0 + 0.5 * (panel.width() - used_w);
  const double top = panel.y0 + 0.5 * (panel.height() - used_h);
  return {scale, left - content.x0 * scale, top + content.y1 * scale};
}

}  // namespace gf
