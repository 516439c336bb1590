#include "geom/arc_length.hpp"

#include <cmath>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace gf {

ArcLength arc_length(const Segment& s, double t0, double t1, double relative_tolerance) {
  if (is_line(s)) {
    const double length = distance(point_at(s, t0), point_at(s, t1));
    return {length, 0.0, true};
  }
  const auto speed = [&s](double t) { return norm(derivative_at(s, t)); };
  double error = 0.0;
  // A cusp makes |C'| non-smooth; the adaptive rule subdivides around it.
  const double length = boost::math::quadrature::gauss_kronrod<double, 15>::integrate(
      speed, t0, t1, 20, relative_tolerance, &error);
  // The chord bounds the length from below, so it is a fair scale for the error.
  const double scale = std::max(length, distance(point_at(s, t0), point_at(s, t1)));
  const bool converged = std::isfinite(length) && error <= relative_tolerance * scale * 10.0 + 1e-300;
  return {std::isfinite(length) ? length : 0.0, std::isfinite(error) ? error : 0.0, converged};
}

double arc_length_estimate(const Segment& s, double t0, double t1) {
  if (is_line(s)) return distance(point_at(s, t0), point_at(s, t1));
  // The hodograph once, not the variant's and the higher derivatives at every node (the
  // rounding's extremum checks call this on every candidate cubic).
  return std::visit(
      [t0, t1](const auto& b) {
        const auto h = b.hodograph();
        return boost::math::quadrature::gauss<double, 16>::integrate([&h](double t) { return norm(h.point_at(t)); }, t0,
                                                                     t1);
      },
      s);
}

}  // namespace gf
