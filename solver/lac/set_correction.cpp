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
  const std::vector<double> gram = reach_.gram();
  prepare(signed_penalties, Eigen::Map<const Eigen::MatrixXd>(gram.data(), d, d));
}

void SetCorrection::set(SparseCholesky& cholesky, const SparseCholesky::Reach& window, std::span<const double> window_gram,
                        std::span<const std::size_t> subset, std::span<const double> signed_penalties) {
  assert(subset.size() == signed_penalties.size());
  cholesky_ = &cholesky;
  const auto d = static_cast<Eigen::Index>(subset.size());
  const std::size_t m = static_cast<std::size_t>(window.columns);
  reach_.positions = window.positions;
  reach_.columns = d;
  reach_.z.resize(window.positions.size() * subset.size());
  for (std::size_t k = 0; k < window.positions.size(); ++k) {
    for (std::size_t c = 0; c < subset.size(); ++c) reach_.z[k * subset.size() + c] = window.z[k * m + subset[c]];
  }
  const Eigen::Map<const Eigen::MatrixXd> gram(window_gram.data(), window.columns, window.columns);
  Eigen::MatrixXd t(d, d);
  for (Eigen::Index j = 0; j < d; ++j) {
    for (Eigen::Index i = 0; i < d; ++i) t(i, j) = gram(static_cast<Eigen::Index>(subset[i]), static_cast<Eigen::Index>(subset[j]));
  }
  prepare(signed_penalties, t);
}

void SetCorrection::prepare(std::span<const double> signed_penalties, const Eigen::MatrixXd& t) {
  const Eigen::Index d = t.rows();
  penalty_ = Eigen::Map<const Eigen::VectorXd>(signed_penalties.data(), d);
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
