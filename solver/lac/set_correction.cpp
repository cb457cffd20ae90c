#include "solver/lac/set_correction.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace saasgaps {

Eigen::Map<const SetCorrection::Rows> SetCorrection::z() const {
  return {reach_.z.data(), static_cast<Eigen::Index>(reach_.positions.size()), reach_.columns};
}

void SetCorrection::set(SparseCholesky& cholesky, const SparseColumns& rows, std::span<const double> signed_penalties) {
  assert(rows.size() == signed_penalties.size());
  cholesky_ = &cholesky;
  reach_ = cholesky.forward_columns(rows);
  const auto d = static_cast<Eigen::Index>(rows.size());
  penalty_ = Eigen::Map<const Eigen::VectorXd>(signed_penalties.data(), d);
  const std::vector<double> gram = reach_.gram();
  const Eigen::Map<const Eigen::MatrixXd> t(gram.data(), d, d);
  const Eigen::MatrixXd m = Eigen::MatrixXd::Identity(d, d) + penalty_.asDiagonal() * t;
  // m_rr = 1 + s_r rho_r T_rr is the ratio of row r's flexibility with and without the change:
  // about 1 + rho_r f_r for a row added (f_r its flexibility without the penalty), 1 / (1 + rho_r f_r)
  // for one dropped. The correction cancels forces that much larger than the row's own, so it
  // loses that many digits.
  loss_ = 1.0;
  for (Eigen::Index i = 0; i < d; ++i) {
    const double ratio = std::abs(m(i, i));
    loss_ = std::max(loss_, std::max(ratio, 1.0 / ratio));
  }
  lu_.compute(m);
}

void SetCorrection::solve(std::span<const double> b, std::span<double> x) {
  assert(cholesky_ != nullptr && "set() before solve()");
  y_.resize(b.size());
  cholesky_->forward(b, y_);
  const std::vector<Index>& at = reach_.positions;
  Eigen::VectorXd yhat(static_cast<Eigen::Index>(at.size()));
  for (std::size_t k = 0; k < at.size(); ++k) yhat[static_cast<Eigen::Index>(k)] = y_[at[k]];
  const Eigen::VectorXd y = lu_.solve(-(penalty_.asDiagonal() * (z().transpose() * yhat)).eval());
  const Eigen::VectorXd zy = z() * y;
  for (std::size_t k = 0; k < at.size(); ++k) y_[at[k]] += zy[static_cast<Eigen::Index>(k)];
  cholesky_->backward(y_, x);
}

}  // namespace saasgaps
