#include "geom/foot_point.hpp"

namespace gf {

std::vector<double> chord_length_parameters(std::span<const Vec2> points) {
  std::vector<double> u(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) u[i] = u[i - 1] + distance(points[i], points[i - 1]);
  if (!u.empty() && u.back() > 0.0)
    for (double& v : u) v /= u.back();
  return u;
}

FootStep foot_step(const Cubic& c, Vec2 p, double t) {
  const auto velocity = c.hodograph();
  const Vec2 off = c.point_at(t) - p, d1 = velocity.point_at(t), d2 = velocity.hodograph().point_at(t);
  return {dot(off, d1), dot(d1, d1) + dot(off, d2)};
}

}  // namespace gf
