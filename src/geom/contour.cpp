#include "geom/contour.hpp"

#include <cmath>
#include <variant>

#include "geom/arc_length.hpp"

namespace gf {

namespace {

// Green's theorem: A = 1/2 ∮ (x dy - y dx), integrated exactly on the power basis.
double area_contribution(const Segment& s) {
  const PolynomialCurve c = polynomial_of(s);
  const PolynomialCurve d = c.derivative();
  const Polynomial integrand = c.x * d.y - c.y * d.x;
  double integral = 0.0;
  for (int i = 0; i <= integrand.degree(); ++i) integral += integrand.coefficient(i) / (i + 1);
  return 0.5 * integral;
}

}  // namespace

double signed_area(const Contour& c) {
  double area = 0.0;
  for (const Segment& s : c.segments) area += area_contribution(s);
  return area;
}

double thickness(const Contour& c) {
  double perimeter = 0.0;
  for (const Segment& s : c.segments) perimeter += arc_length_estimate(s);
  return perimeter > 0.0 ? 2.0 * std::abs(signed_area(c)) / perimeter : 0.0;
}

bool on_integer_grid(const Contour& c) {
  const auto whole = [](Vec2 p) { return p.x == std::round(p.x) && p.y == std::round(p.y); };
  bool all = true;
  // Each segment's points but its end, which is the next one's start (an open end below).
  for (std::size_t i = 0; i < c.segments.size() && all; ++i)
    std::visit(
        [&](const auto& b) {
          for (std::size_t k = c.nodes[i].implied ? 1 : 0; k + 1 < b.p.size(); ++k) all = all && whole(b.p[k]);
        },
        c.segments[i]);
  return all && (c.closed || c.segments.empty() || c.nodes.back().implied || whole(end_point(c.segments.back())));
}

Contour with_cubics(const Contour& c) {
  Contour out = c;
  for (Segment& s : out.segments)
    if (const auto* q = std::get_if<Quad>(&s)) s = to_cubic(*q);
  for (NodeFlags& n : out.nodes) n.implied = false;
  return out;
}

}  // namespace gf
