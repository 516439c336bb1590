#include "geom/curvature_profile.hpp"

#include "geom/arc_length.hpp"
#include "geom/curvature.hpp"

namespace gf {

CurvatureProfile curvature_profile(const Contour& c, int samples_per_segment) {
  CurvatureProfile profile;
  std::vector<double> node_s;
  double s = 0.0;
  for (const Segment& seg : c.segments) {
    node_s.push_back(s);
    SegmentProfile sp;
    sp.straight = is_line(seg);
    const int n = sp.straight ? 1 : samples_per_segment;
    double t_prev = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double t = double(i) / n;
      if (i > 0) s += arc_length(seg, t_prev, t, 1e-9).length;
      t_prev = t;
      const Derivatives d = derivatives_at(seg, t);
      const double speed = norm(d.d1);
      const Vec2 normal = speed > 0.0 ? perpendicular(d.d1) / speed : Vec2{};
      sp.samples.push_back({s, curvature(d), d.point, normal});
    }
    profile.segments.push_back(std::move(sp));
  }
  profile.length = s;
  for (const Join& j : joins_of(c)) profile.joins.push_back({node_s[j.node], j});
  return profile;
}

}  // namespace gf
