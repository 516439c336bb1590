#include "geom/contour.hpp"


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

Contour with_cubics(const Contour& c) {
  Contour out = c;
  for (Segment& s : out.segments)
    if (const auto* q = std::get_if<Quad>(&s)) s = to_cubic(*q);
  for (NodeFlags& n : out.nodes) n.implied = false;
  return out;
}

}  // namespace gf
