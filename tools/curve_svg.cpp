#include "curve_svg.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "io/number_format.hpp"

namespace gf {

std::string curve_svg(std::span<const LacPoint> curve, std::span<const Vec2> guide) {
  double max_k = 0.0;
  for (const auto& p : curve) max_k = std::max(max_k, std::abs(p.curvature));
  double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
  const auto grow = [&](Vec2 v) {
    lo_x = std::min(lo_x, v.x), lo_y = std::min(lo_y, v.y), hi_x = std::max(hi_x, v.x), hi_y = std::max(hi_y, v.y);
  };
  for (const Vec2 g : guide) grow(g);
  for (const auto& p : curve) grow(p.point);
  // The comb's longest tooth is 15% of the picture.
  const double size = std::max(hi_x - lo_x, hi_y - lo_y);
  const double gain = max_k > 0.0 ? 0.15 * size / max_k : 0.0;
  std::vector<Vec2> tips;
  for (const auto& p : curve) {
    tips.push_back(p.point - perpendicular(p.tangent) * (gain * p.curvature));
    grow(tips.back());
  }
  const double margin = 0.05 * size;
  std::ostringstream o;
  const auto xy = [&](Vec2 v) { return shortest_decimal(v.x) + "," + shortest_decimal(v.y); };
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << shortest_decimal(lo_x - margin) << " "
    << shortest_decimal(-hi_y - margin) << " " << shortest_decimal(hi_x - lo_x + 2 * margin) << " "
    << shortest_decimal(hi_y - lo_y + 2 * margin) << "\" width=\"600\" height=\""
    << static_cast<int>(600 * (hi_y - lo_y + 2 * margin) / (hi_x - lo_x + 2 * margin)) << "\">\n"
    << "<g transform=\"scale(1 -1)\" fill=\"none\" stroke-width=\"" << shortest_decimal(size / 400) << "\">\n";
  o << "<polyline stroke=\"#999\" stroke-dasharray=\"" << shortest_decimal(size / 100) << "\" points=\"";
  for (std::size_t k = 0; k < guide.size(); ++k) o << (k ? " " : "") << xy(guide[k]);
  o << "\"/>\n";
  for (std::size_t k = 0; k < curve.size(); ++k)
    o << "<line stroke=\"#2a6bd1\" stroke-opacity=\"0.6\" x1=\"" << shortest_decimal(curve[k].point.x) << "\" y1=\""
      << shortest_decimal(curve[k].point.y) << "\" x2=\"" << shortest_decimal(tips[k].x) << "\" y2=\""
      << shortest_decimal(tips[k].y) << "\"/>\n";
  o << "<polyline stroke=\"#2a6bd1\" points=\"";
  for (const Vec2 t : tips) o << xy(t) << " ";
  o << "\"/>\n<polyline stroke=\"#111\" stroke-width=\"" << shortest_decimal(size / 200) << "\" points=\"";
  for (const auto& p : curve) o << xy(p.point) << " ";
  o << "\"/>\n</g>\n</svg>\n";
  return o.str();
}

}  // namespace gf
