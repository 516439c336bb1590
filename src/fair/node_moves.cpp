#include "fair/node_moves.hpp"

#include <algorithm>
#include <vector>

#include "fair/contour_plan.hpp"

namespace gf {

Segment with_end_moved(const Segment& s, SegmentEnd end, Vec2 v, std::optional<Vec2> along) {
  const bool at_start = end == SegmentEnd::start;
  if (is_straight_segment(s)) {
    const Vec2 a = start_point(s), b = end_point(s);
    return Line{at_start ? a + v : a, at_start ? b : b + v};
  }
  Cubic c = std::get<Cubic>(s);
  const int node = at_start ? 0 : 3, handle = at_start ? 1 : 2;
  const double reach = distance(c.p[node], c.p[handle]);
  c.p[node] = c.p[node] + v;
  c.p[handle] = along && reach > 0.0 ? c.p[node] + (at_start ? reach : -reach) * *along : c.p[handle] + v;
  return c;
}

double largest_move(const Segment& was, const Segment& now) {
  std::vector<Vec2> a, b;
  for_each_point(was, [&](Vec2 q) { a.push_back(q); });
  for_each_point(now, [&](Vec2 q) { b.push_back(q); });
  if (a.size() != b.size()) a = {a.front(), a.back()};
  double out = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) out = std::max(out, distance(a[k], b[k]));
  return out;
}

}  // namespace gf
