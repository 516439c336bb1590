// The shifted form and the generalised Cornu spiral (lac-math.md §5).
#include "aesthetic/shifted_lac.hpp"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>

#include "aesthetic/lac_position.hpp"
#include "aesthetic/normalised_lac.hpp"

namespace gf {
namespace {

template <typename Curve>
double integral_of_curvature(const Curve& c, double s) {
  return c.theta0 + boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
                        [&](double u) { return c.curvature(u); }, 0.0, s, 15, 1e-15);
}

TEST(ShiftedLac, CorrectedThetaIsTheIntegralOfCurvature) {
  for (const double alpha : {-2.0, -0.5, 0.0, 0.5, 1.0, 2.0, 3.0}) {
    const ShiftedLac c{alpha, 0.8, 2.0, 0.1, 0.3};
    for (const double s : {0.2, 1.0, 1.9}) EXPECT_NEAR(c.theta(s), integral_of_curvature(c, s), 1e-12) << alpha;
  }
}

TEST(ShiftedLac, DocumentedExample) {
  // α = −0.5, c = 0.8, d = 2, e = 0.1, s = 1.9: 15.029253333333 (the patent's formula: 0.1804).
  EXPECT_NEAR((ShiftedLac{-0.5, 0.8, 2.0, 0.1, 0.0}.theta(1.9)), 15.029253333333, 1e-10);
}

TEST(ShiftedLac, WithoutShiftItIsTheLogAestheticCurve) {
  // e = 0: ρ^α = cs + d is Miura's form; normalised by ρ₀ = d^{1/α}, Λ = c ρ₀^{1−α}/α
  // (lac-math.md §1.2), positions scale by ρ₀.
  const double alpha = 1.7, c = 0.6, d = 1.5;
  const ShiftedLac shifted{alpha, c, d, 0.0, 0.0};
  const double rho0 = std::pow(d, 1.0 / alpha);
  const NormalisedLac lac{alpha, c * std::pow(rho0, 1.0 - alpha) / alpha};
  for (const double s : {0.5, 2.0, 4.0}) {
    const std::complex<double> a = position_by_arc_length(shifted, s);
    const std::complex<double> b = rho0 * lac_position(lac, 0.0, lac.theta_of_s(s / rho0));
    EXPECT_NEAR(std::abs(a - b), 0.0, 1e-12 * s);
  }
}

TEST(GeneralisedCornuSpiral, ThetaAndItsRhoShiftedForm) {
  const GeneralisedCornuSpiral g{2.0, 0.7, 0.4, 0.3, 0.1};
  for (const double s : {0.5, 1.5, 3.0}) {
    EXPECT_NEAR(g.theta(s), integral_of_curvature(g, s), 1e-12);
    const auto [e, c, d] = g.rho_shifted();
    EXPECT_NEAR(1.0 / g.curvature(s), e + 1.0 / (c * s + d), 1e-12);
  }
  // r = 0 makes curvature linear in s: a clothoid.
  const GeneralisedCornuSpiral clothoid{2.0, 0.0, 0.4, 0.3, 0.0};
  EXPECT_NEAR(clothoid.theta(1.2), integral_of_curvature(clothoid, 1.2), 1e-13);
}

}  // namespace
}  // namespace gf
