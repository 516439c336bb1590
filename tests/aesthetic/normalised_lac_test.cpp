// The normalised curve against the reference values of lac-math.md §1.3 (mpmath, 30 digits)
// and the closed forms of its special cases.
#include "aesthetic/lac_position.hpp"
#include "aesthetic/normalised_lac.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

namespace gf {
namespace {

using cplx = std::complex<double>;

struct Reference {
  double alpha, s_end, kappa_end, dkappa_end, x_end, y_end;
};

// Λ = 0.2, θ_end = 1.0 (lac-math.md §1.3, check_01 §4).
const Reference table[] = {
    {-3, 1.1682170729262598, 0.66874030497642202, -0.44721359549995794, 0.96486898535916097, 0.56787380813626964},
    {-2, 1.1427911917025467, 0.73680629972807732, -0.27144176165949066, 0.94780772802379058, 0.54946443410204623},
    {-1, 1.1270166537925831, 0.77459666924148338, -0.2, 0.93693703415432668, 0.53836072931316133},
    {-0.5, 1.1209599825739929, 0.78837351631052428, -0.17758080034852014, 0.93270641570158096, 0.53416364217666728},
    {0, 1.1157177565710488, 0.8, -0.16, 0.92901948666578365, 0.53056114045380044},
    {0.5, 1.1111111111111111, 0.81, -0.1458, 0.9257603423462031, 0.52741883155821428},
    {1, 1.1070137908008492, 0.81873075307798186, -0.13406400920712786, 0.92284646834773873, 0.52464256704190218},
    {1.5, 1.1033333333333333, 0.82644628099173554, -0.12418426461183103, 0.92021697921238758, 0.52216387267465097},
    {2, 1.1, 0.83333333333333333, -0.11574074074074074, 0.91782564294310375, 0.51993142991981164},
    {3, 1.0941705654464875, 0.84515425472851658, -0.10204081632653061, 0.91362111837393351, 0.51605613178061763},
};

void expect_relative(double got, double want, double tol, const char* what, double alpha) {
  EXPECT_NEAR(got, want, tol * std::max(1.0, std::abs(want))) << what << " at α = " << alpha;
}

TEST(NormalisedLac, MatchesTheReferenceTable) {
  for (const Reference& r : table) {
    const NormalisedLac c{r.alpha, 0.2};
    expect_relative(c.s_of_theta(1.0), r.s_end, 1e-14, "s", r.alpha);
    expect_relative(c.theta_of_s(r.s_end), 1.0, 1e-14, "θ(s)", r.alpha);
    expect_relative(c.curvature_of_theta(1.0), r.kappa_end, 1e-14, "κ", r.alpha);
    expect_relative(*c.curvature_derivative_of_theta(1.0), r.dkappa_end, 1e-13, "dκ/ds", r.alpha);
    const cplx p = lac_position(c, 0.0, 1.0);
    // 1e-12 relative to the arc length (about 1.1 here).
    EXPECT_NEAR(p.real(), r.x_end, 1e-12 * r.s_end) << "x at α = " << r.alpha;
    EXPECT_NEAR(p.imag(), r.y_end, 1e-12 * r.s_end) << "y at α = " << r.alpha;
  }
}

TEST(NormalisedLac, CurvatureFollowsTheDefiningOde) {
  // dθ/ds = 1/ρ and dκ/ds = −Λ κ^{α+1}, by central differences of the closed forms.
  for (const double alpha : {-2.5, -1.0, 0.0, 0.4, 1.0, 2.0, 4.5}) {
    const NormalisedLac c{alpha, 0.37};
    for (const double s : {0.1, 0.5, 0.9}) {
      const double h = 1e-5, th = c.theta_of_s(s);
      const double dtheta = (c.theta_of_s(s + h) - c.theta_of_s(s - h)) / (2 * h);
      EXPECT_NEAR(dtheta, c.curvature_of_theta(th), 1e-8) << alpha;
      const double dk = (c.curvature_of_theta(c.theta_of_s(s + h)) - c.curvature_of_theta(c.theta_of_s(s - h))) / (2 * h);
      EXPECT_NEAR(dk, *c.curvature_derivative_of_theta(th), 1e-7) << alpha;
    }
  }
}

TEST(NormalisedLac, TinyLambdaIsTheCircleWithoutCancellation) {
  const NormalisedLac c{0.5, 1e-13};
  EXPECT_NEAR(c.s_of_theta(1.2), 1.2, 1e-12);
  const cplx p = lac_position(c, 0.0, 1.2);
  EXPECT_NEAR(p.real(), std::sin(1.2), 1e-12);
  EXPECT_NEAR(p.imag(), 1 - std::cos(1.2), 1e-12);
}

// Closed forms of lac-math.md §1.3, checked to 1e-12 relative.
TEST(SpecialCases, LogarithmicSpiralAndCircleInvolute) {
  for (const double L : {0.05, 0.3, 2.0})
    for (const double th : {0.4, 1.0, 2.5}) {
      const cplx z(L, 1.0);
      const cplx spiral = (std::exp(z * th) - 1.0) / z;  // α = 1
      const cplx got1 = lac_position(NormalisedLac{1.0, L}, 0.0, th);
      EXPECT_NEAR(std::abs(got1 - spiral), 0.0, 1e-12 * std::abs(spiral));
      const cplx i(0.0, 1.0);
      const cplx involute = -i * (1.0 + L * th) * std::exp(i * th) + L * std::exp(i * th) + i - L;  // α = 2
      const cplx got2 = lac_position(NormalisedLac{2.0, L}, 0.0, th);
      EXPECT_NEAR(std::abs(got2 - involute), 0.0, 1e-12 * std::abs(involute)) << L << " " << th;
    }
}

TEST(SpecialCases, ClothoidAndNielsenSpiralAtTheDocumentedPoint) {
  // (Λ, θ) = (0.3, 1.0), lac-math.md §1.3 "more oracles": Fresnel (α = −1), Si/Ci (α = 0).
  const cplx clothoid(1.008547810567332, 0.602041782184813);
  const cplx nielsen(0.983592456296735, 0.576522176970199);
  const cplx spiral(0.967584007395882, 0.560943375889033);
  const cplx involute(0.956002972010707, 0.550048297813787);
  EXPECT_NEAR(std::abs(lac_position(NormalisedLac{-1.0, 0.3}, 0.0, 1.0) - clothoid), 0.0, 1e-14);
  EXPECT_NEAR(std::abs(lac_position(NormalisedLac{0.0, 0.3}, 0.0, 1.0) - nielsen), 0.0, 1e-14);
  EXPECT_NEAR(std::abs(lac_position(NormalisedLac{1.0, 0.3}, 0.0, 1.0) - spiral), 0.0, 1e-14);
  EXPECT_NEAR(std::abs(lac_position(NormalisedLac{2.0, 0.3}, 0.0, 1.0) - involute), 0.0, 1e-14);
}

TEST(SpecialCases, ClothoidAgainstFresnelSeriesAlongTheCurve) {
  // α = −1: θ = s − Λs²/2, so C(s) = ∫ e^{i(u − Λu²/2)} du; its Taylor series in u converges
  // everywhere and is summed here in long double as an independent oracle.
  const double L = 0.45;
  const NormalisedLac c{-1.0, L};
  for (const double s : {0.3, 1.0, 1.8}) {
    long double re = 0, im = 0;
    const int n = 4000;
    for (int k = 0; k < n; ++k) {  // composite Simpson, h⁴ error far below 1e-14
      const long double a = (long double)s * k / n, b = (long double)s * (k + 1) / n, m = 0.5L * (a + b);
      const auto f = [&](long double u, bool im_part) {
        const long double th = u - 0.5L * L * u * u;
        return im_part ? std::sin(th) : std::cos(th);
      };
      re += (b - a) / 6 * (f(a, false) + 4 * f(m, false) + f(b, false));
      im += (b - a) / 6 * (f(a, true) + 4 * f(m, true) + f(b, true));
    }
    const cplx got = lac_position(c, 0.0, c.theta_of_s(s));
    EXPECT_NEAR(got.real(), (double)re, 1e-12 * s);
    EXPECT_NEAR(got.imag(), (double)im, 1e-12 * s);
  }
}

// Short steps take the 4- and 6-point panels (a segment's samples), long ones the 12-point
// panels graded toward ψ*: step by step they add up to the whole, to rounding, from far from
// the singular angle to within 0.01 rad of it.
TEST(LacPosition, ShortStepsAddUpToTheWhole) {
  for (const Reference& r : table) {
    const NormalisedLac c{r.alpha, 0.2};
    cplx sum = 0.0;
    for (int k = 0; k < 500; ++k) sum += lac_position(c, k / 500.0, (k + 1) / 500.0);
    EXPECT_NEAR(sum.real(), r.x_end, 1e-13) << r.alpha;
    EXPECT_NEAR(sum.imag(), r.y_end, 1e-13) << r.alpha;
  }
  for (const double alpha : {-2.0, -0.5, 0.5, 3.0}) {
    const NormalisedLac c{alpha, 0.4};
    const std::optional<double> singular = c.singular_theta();
    ASSERT_TRUE(singular) << alpha;
    const double end = *singular - 0.01;  // ψ* = 1/((1−α)Λ) ahead of θ = 0
    cplx sum = 0.0;
    for (int k = 0; k < 300; ++k) sum += lac_position(c, end * k / 300, end * (k + 1) / 300);
    const cplx whole = lac_position(c, 0.0, end);
    EXPECT_NEAR(std::abs(sum - whole), 0.0, 1e-13 * std::abs(whole)) << alpha;
  }
}

TEST(LacPosition, TouchingTheSingularAngleUsesTheExactSeries) {
  // α = −0.5 to its inflection: ψ* = 1/((1−α)Λ). Rounding ψ* and integrating to the float
  // would miss ∝ ε^{1+p} (§8.3 trap); the series with δ = 0 does not.
  const NormalisedLac c{-0.5, 0.4};
  const double psi = *c.singular_theta();
  const cplx exact = lac_position(c, 0.0, psi, 0.0);
  // By arc length, where the integrand e^{iθ(s)} is smooth: s* = 1/(|α|Λ).
  const double s_star = 1.0 / (0.5 * 0.4);
  long double re = 0, im = 0;
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const long double a = (long double)s_star * k / n, b = (long double)s_star * (k + 1) / n, m = 0.5L * (a + b);
    for (const auto& [u, w] : {std::pair<long double, long double>{a, 1}, {m, 4}, {b, 1}}) {
      const double th = c.theta_of_s(static_cast<double>(u));
      re += (b - a) / 6 * w * std::cos((long double)th);
      im += (b - a) / 6 * w * std::sin((long double)th);
    }
  }
  EXPECT_NEAR(exact.real(), (double)re, 1e-9 * s_star);
  EXPECT_NEAR(exact.imag(), (double)im, 1e-9 * s_star);
}

}  // namespace
}  // namespace gf
