// Newton's step and method (geom/damped_newton.hpp): the sparse step is the dense one's least
// squares answer, above the size where it factors sparse too, and the method reaches a known
// root of a banded system of many unknowns.
#include "geom/damped_newton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace gf {
namespace {

// A tridiagonal, diagonally dominant n × n matrix with entries that vary along the diagonal.
Eigen::SparseMatrix<double> banded(Eigen::Index n) {
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 4.0 + std::sin(0.3 * static_cast<double>(i)));
    if (i > 0) entries.emplace_back(i, i - 1, -1.0 + 0.1 * std::cos(static_cast<double>(i)));
    if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0);
  }
  Eigen::SparseMatrix<double> m(n, n);
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

TEST(NewtonStep, SparseAndDenseAgreeOnASmallSystemAndAManyUnknownOne) {
  for (const Eigen::Index n : {Eigen::Index{12}, Eigen::Index{600}}) {
    const Eigen::SparseMatrix<double> jac = banded(n);
    Eigen::VectorXd f(n);
    for (Eigen::Index i = 0; i < n; ++i) f[i] = std::cos(0.7 * static_cast<double>(i));
    const Eigen::VectorXd sparse = newton_step(jac, f);
    const Eigen::VectorXd dense = newton_step(Eigen::MatrixXd(jac), f);
    EXPECT_LT((sparse - dense).cwiseAbs().maxCoeff(), 1e-12) << n << " unknowns";
    EXPECT_LT((jac * sparse + f).cwiseAbs().maxCoeff(), 1e-12) << n << " unknowns";  // J·δ = −f
  }
}

TEST(NewtonStep, ARankDeficientSparseSystemStillGivesTheLeastSquaresStep) {
  // Two equal columns: J·δ = −f has solutions, the step must be one of them.
  const Eigen::Index n = 400;
  Eigen::SparseMatrix<double> jac = banded(n);
  Eigen::MatrixXd d(jac);
  d.col(n - 1) = d.col(n - 2);
  jac = d.sparseView();
  const Eigen::VectorXd f = -d * Eigen::VectorXd::Ones(n);  // in J's range
  const Eigen::VectorXd step = newton_step(jac, f);
  ASSERT_TRUE(step.allFinite());
  EXPECT_LT((jac * step + f).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(DampedNewton, ReachesTheRootOfABandedSystemOfManyUnknowns) {
  // F_i(x) = x_i³ + x_i − x_{i−1} − x_{i+1} − c_i with the root x_i = 1 + 0.5 sin(i).
  const Eigen::Index n = 500;
  Eigen::VectorXd root(n), c(n);
  for (Eigen::Index i = 0; i < n; ++i) root[i] = 1.0 + 0.5 * std::sin(static_cast<double>(i));
  const auto neighbours = [&](const Eigen::VectorXd& x, Eigen::Index i) {
    return (i > 0 ? x[i - 1] : 0.0) + (i + 1 < n ? x[i + 1] : 0.0);
  };
  for (Eigen::Index i = 0; i < n; ++i) c[i] = std::pow(root[i], 3) + root[i] - neighbours(root, i);
  const auto residual = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd f(n);
    for (Eigen::Index i = 0; i < n; ++i) f[i] = std::pow(x[i], 3) + x[i] - neighbours(x, i) - c[i];
    return f;
  };
  const auto jacobian = [&](const Eigen::VectorXd& x, const Eigen::VectorXd&) {
    std::vector<Eigen::Triplet<double>> entries;
    for (Eigen::Index i = 0; i < n; ++i) {
      entries.emplace_back(i, i, 3.0 * x[i] * x[i] + 1.0);
      if (i > 0) entries.emplace_back(i, i - 1, -1.0);
      if (i + 1 < n) entries.emplace_back(i, i + 1, -1.0);
    }
    Eigen::SparseMatrix<double> j(n, n);
    j.setFromTriplets(entries.begin(), entries.end());
    return j;
  };
  Eigen::VectorXd x = Eigen::VectorXd::Constant(n, 2.0);
  const NewtonRun run = damped_newton(x, residual, jacobian, [](const Eigen::VectorXd&) { return true; }, 1e-12, 60);
  EXPECT_EQ(run.end, NewtonEnd::converged);
  EXPECT_LT((x - root).cwiseAbs().maxCoeff(), 1e-10);
}

}  // namespace
}  // namespace gf
