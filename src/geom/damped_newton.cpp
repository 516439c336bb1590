#include "geom/damped_newton.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseLU>
#include <Eigen/SparseQR>

namespace gf {

Eigen::VectorXd newton_step(const Eigen::SparseMatrix<double>& jac, const Eigen::VectorXd& f) {
  constexpr Eigen::Index dense_unknowns = 150;
  if (jac.cols() <= dense_unknowns) return newton_step(Eigen::MatrixXd(jac), f);
  if (jac.rows() == jac.cols()) {
    const Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu(jac);
    if (lu.info() == Eigen::Success) {
      Eigen::VectorXd step = lu.solve(-f);
      if (step.allFinite()) return step;
    }
  }
  const Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr(jac);
  if (qr.info() != Eigen::Success) return newton_step(Eigen::MatrixXd(jac), f);
  return qr.solve(-f);
}

}  // namespace gf
