// The uniform cubic B-spline bases against their defining properties: the basis values sum to
// one everywhere, and the Bézier spans meet C2 (clamped: interior knots; periodic: every knot,
// the seam included), so the spans are the spline and not four unrelated cubics.
#include "geom/bspline_basis.hpp"

#include <gtest/gtest.h>

#include <random>

namespace gf {
namespace {

std::vector<Vec2> random_controls(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-100.0, 100.0);
  std::vector<Vec2> c;
  for (int i = 0; i < n; ++i) c.push_back({u(rng), u(rng)});
  return c;
}

TEST(BSplineBasis, ValuesArePositiveAndSumToOne) {
  for (const bool periodic : {false, true}) {
    const BSplineBasis basis(7, periodic);
    for (int k = 0; k <= 700; ++k) {
      const BSplineBasis::Weights w = basis.at(k / 700.0);
      double sum = 0.0;
      for (const double v : w.w) {
        EXPECT_GE(v, -1e-15);
        sum += v;
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
    }
  }
}

TEST(BSplineBasis, SpansMeetC2IncludingThePeriodicSeam) {
  std::mt19937 rng(7);
  for (const bool periodic : {false, true}) {
    const BSplineBasis basis(6, periodic);
    const std::vector<Vec2> c = random_controls(basis.control_count(), rng);
    const int joins = periodic ? basis.spans() : basis.spans() - 1;
    for (int s = 0; s < joins; ++s) {
      const Cubic a = basis.span_cubic(c, s), b = basis.span_cubic(c, (s + 1) % basis.spans());
      // Position, and first and second derivatives in u (each span has the same width).
      EXPECT_NEAR(distance(a.p[3], b.p[0]), 0.0, 1e-9);
      EXPECT_NEAR(distance(a.p[3] - a.p[2], b.p[1] - b.p[0]), 0.0, 1e-9);
      EXPECT_NEAR(distance(a.p[3] - 2.0 * a.p[2] + a.p[1], b.p[2] - 2.0 * b.p[1] + b.p[0]), 0.0, 1e-9);
    }
    if (!periodic) {  // clamped: the curve starts and ends on its end controls
      EXPECT_NEAR(distance(basis.span_cubic(c, 0).p[0], c.front()), 0.0, 1e-12);
      EXPECT_NEAR(distance(basis.span_cubic(c, basis.spans() - 1).p[3], c.back()), 0.0, 1e-12);
    }
  }
}

}  // namespace
}  // namespace gf
