#include "geom/polynomial.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace gf {
namespace {

Polynomial from_roots(std::vector<double> roots, double lead = 1.0) {
  Polynomial p(std::vector<double>{lead});
  for (const double r : roots) p = p * Polynomial(std::vector<double>{-r, 1.0});
  return p;
}

std::vector<double> ts(const std::vector<SignChange>& v) {
  std::vector<double> out;
  for (const auto& s : v) out.push_back(s.t);
  return out;
}

TEST(Polynomial, EvaluatesAndDifferentiates) {
  const Polynomial p(std::vector<double>{1.0, -3.0, 2.0});  // 1 - 3t + 2t²
  EXPECT_DOUBLE_EQ(p(0.5), 0.0);
  EXPECT_DOUBLE_EQ(p.derivative()(1.0), 1.0);
}

TEST(Polynomial, FindsSimpleRootsToDoublePrecision) {
  const auto r = ts(sign_changes_in_unit_interval(from_roots({0.1, 0.37, 0.9, 1.7, -2.0}), 0.0));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], 0.1, 1e-15);
  EXPECT_NEAR(r[1], 0.37, 1e-15);
  EXPECT_NEAR(r[2], 0.9, 1e-15);
}

TEST(Polynomial, RootExactlyAtTheSubdivisionPointIsFound) {
  const auto r = ts(sign_changes_in_unit_interval(from_roots({0.25, 0.5, 0.75}), 0.0));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_DOUBLE_EQ(r[1], 0.5);
}

TEST(Polynomial, EvenMultiplicityIsNotASignChange) {
  EXPECT_TRUE(sign_changes_in_unit_interval(from_roots({0.5, 0.5}), 0.0).empty());
  const auto triple = ts(sign_changes_in_unit_interval(from_roots({0.3, 0.3, 0.3}), 0.0));
  ASSERT_EQ(triple.size(), 1u);
  EXPECT_NEAR(triple[0], 0.3, 1e-5);  // a triple root is ill-conditioned: t ± eps^(1/3)
}

TEST(Polynomial, CloseRootsAreSeparated) {
  // Roots 1e-7 apart are conditioned to about eps / 1e-7: a few 1e-9.
  const auto r = ts(sign_changes_in_unit_interval(from_roots({0.5, 0.5 + 1e-7, 0.9}), 0.0));
  ASSERT_EQ(r.size(), 3u);
  EXPECT_NEAR(r[0], 0.5, 1e-8);
  EXPECT_NEAR(r[1], 0.5 + 1e-7, 1e-8);
}

TEST(Polynomial, NegligiblePolynomialHasNoRoots) {
  const Polynomial noise(std::vector<double>{1e-17, -3e-17, 2e-17});
  EXPECT_TRUE(sign_changes_in_unit_interval(noise, 1e-15).empty());
  EXPECT_TRUE(sign_changes_in_unit_interval(Polynomial(), 0.0).empty());
}

TEST(Polynomial, AntiderivativeUndoesTheDerivativeAndStartsAtZero) {
  const Polynomial p(std::vector<double>{2.0, -1.0, 0.5, 3.0});
  const Polynomial a = p.antiderivative();
  EXPECT_EQ(a.degree(), 4);
  EXPECT_EQ(a(0.0), 0.0);
  for (const double t : {-1.0, 0.3, 2.0}) EXPECT_NEAR(a.derivative()(t), p(t), 1e-14);
  // ∫₀¹ p = 2 − 1/2 + 1/6 + 3/4
  EXPECT_NEAR(a(1.0), 2.0 - 0.5 + 0.5 / 3.0 + 0.75, 1e-15);
}

}  // namespace
}  // namespace gf
