#include "solver/mortar/dual_basis.hpp"

#include <Eigen/LU>

namespace saasgaps {

DualBasis dual_basis(const Vec2& x1, const Vec2& x2, std::span<const ParameterInterval> covered,
                     const SurfaceMeasure& measure) {
  // Biorthogonality int psi_i N_k dA = delta_ik d_i with psi = A N reads A Me = diag(d); Me is the
  // (weighted) mass matrix of the covered part, symmetric positive definite when that part has length,
  // and d = Me 1 (N_1 + N_2 = 1), which also gives sum_i psi_i = 1^T diag(d) Me^-1 N = 1^T N = 1.
  Eigen::Matrix2d me = Eigen::Matrix2d::Zero();
  for (const ParameterInterval& piece : covered) {
    integrate(x1, x2, piece, measure, [&](double xi, double w) {
      const Vec2 n(1.0 - xi, xi);
      me += w * n * n.transpose();
    });
  }
  DualBasis basis;
  basis.d = me.rowwise().sum();
  basis.A = basis.d.asDiagonal() * me.inverse();
  return basis;
}

}  // namespace saasgaps
