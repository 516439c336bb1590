// Newton's method with backtracking, for the nonlinear systems the fairing solves (a G3
// segment meeting its far end, a run's G3 junctions): each step is the least-squares solution
// of J·δ = −F (column-pivoted QR, so a rank-deficient J still gives a step), halved until ‖F‖₂
// falls at an admissible point (lac-math.md §7.1's recipe). A sparse J of many unknowns is
// factored sparse: dense QR costs n³, and a G3 run cut into 608 spirals (1,824 unknowns) took
// about two seconds a step (Leckerli's m: 173 s for the glyph, 4.7 s factored sparse).
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include <Eigen/Dense>
#include <Eigen/SparseCore>

namespace gf {

enum class NewtonEnd { converged, stalled, out_of_iterations, not_finite };

struct NewtonRun {
  NewtonEnd end = NewtonEnd::stalled;
  int iterations = 0;
  double residual = 0.0;  ///< max |F| at the point reached
};

/// J of `residual` at x by forward differences, f being F(x): column c from a step of
/// 1e-7·max(1, |x_c|). Dense; fixed-size where x and F are.
template <class Vector, class Residual>
auto forward_difference_jacobian(Residual& residual, const Vector& x, const std::invoke_result_t<Residual&, const Vector&>& f) {
  using F = std::invoke_result_t<Residual&, const Vector&>;
  Eigen::Matrix<double, F::RowsAtCompileTime, Vector::RowsAtCompileTime> jac(f.size(), x.size());
  for (Eigen::Index c = 0; c < x.size(); ++c) {
    Vector moved = x;
    const double h = 1e-7 * std::max(1.0, std::abs(x[c]));
    moved[c] += h;
    jac.col(c) = (residual(moved) - f) / h;
  }
  return jac;
}

/// The Newton step δ, least squares of J·δ = −f, for a dense J.
template <class Matrix, class Vector>
auto newton_step(const Eigen::MatrixBase<Matrix>& jac, const Vector& f) {
  return jac.colPivHouseholderQr().solve(-f).eval();
}

/// The same for a sparse J: dense QR up to 150 columns (as fast there, and the same step as a
/// dense J's); past it sparse LU where J is square and LU finds a finite step, else sparse QR
/// (COLAMD ordering, rank-revealing; ten times LU's time on a 1,152-unknown run).
Eigen::VectorXd newton_step(const Eigen::SparseMatrix<double>& jac, const Eigen::VectorXd& f);

/// From x until max |F(x)| ≤ tolerance; x is left at the last point reached. `jacobian(x, f)`
/// gives J at x, f being F(x); `admissible(x)` keeps iterates inside the problem's domain; a
/// step is halved at most 20 times.
template <class Vector, class Residual, class Jacobian, class Admissible>
NewtonRun damped_newton(Vector& x, Residual residual, Jacobian jacobian, Admissible admissible, double tolerance,
                        int max_iterations) {
  NewtonRun run;
  auto f = residual(x);
  for (;; ++run.iterations) {
    run.residual = f.cwiseAbs().maxCoeff();
    if (!std::isfinite(run.residual)) {
      run.end = NewtonEnd::not_finite;
      return run;
    }
    if (run.residual <= tolerance) {
      run.end = NewtonEnd::converged;
      return run;
    }
    if (run.iterations == max_iterations) {
      run.end = NewtonEnd::out_of_iterations;
      return run;
    }
    const Vector step = newton_step(jacobian(x, f), f);
    bool moved = false;
    for (double damping = 1.0; damping > 1e-6 && !moved; damping *= 0.5) {
      Vector q = x + damping * step;
      if (!admissible(q)) continue;
      auto fq = residual(q);
      if (fq.allFinite() && fq.norm() < f.norm()) x = std::move(q), f = std::move(fq), moved = true;
    }
    if (!moved) {
      run.end = NewtonEnd::stalled;
      return run;
    }
  }
}

}  // namespace gf
