#include "solver/lac/set_correction.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numeric>

namespace saasgaps {

void SetCorrection::set(SparseCholesky& cholesky, const SparseColumns& rows, std::span<const double> signed_penalties) {
  assert(rows.size() == signed_penalties.size());
  cholesky_ = &cholesky;
  reach_ = std::make_shared<const SparseCholesky::Reach>(cholesky.forward_columns(rows));
  const auto d = static_cast<Eigen::Index>(rows.size());
  subset_.resize(static_cast<std::size_t>(d));
  std::iota(subset_.begin(), subset_.end(), Eigen::Index{0});  // D is the reach's every column
  const std::vector<double> gram = reach_->gram();
  prepare(signed_penalties, Eigen::Map<const Eigen::MatrixXd>(gram.data(), d, d));
}

void SetCorrection::set(SparseCholesky& cholesky, std::shared_ptr<const SparseCholesky::Reach> window,
                        std::span<const double> window_gram, std::span<const std::size_t> subset,
                        std::span<const double> signed_penalties) {
  assert(subset.size() == signed_penalties.size());
  cholesky_ = &cholesky;
  reach_ = std::move(window);
  const auto d = static_cast<Eigen::Index>(subset.size());
  subset_.assign(subset.begin(), subset.end());
  const Eigen::Map<const Eigen::MatrixXd> gram(window_gram.data(), reach_->columns, reach_->columns);
  Eigen::MatrixXd t(d, d);
  for (Eigen::Index j = 0; j < d; ++j) {
    for (Eigen::Index i = 0; i < d; ++i) t(i, j) = gram(subset_[static_cast<std::size_t>(i)], subset_[static_cast<std::size_t>(j)]);
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
  const std::vector<Index>& at = reach_->positions;
  // Z_D' yhat and Z_D y band by band through the whole window's Z (its other columns read with zeros).
  using Band = Eigen::Map<const Rows>;
  const auto band = [&](const SparseCholesky::Reach::Block& b) {
    return Band(reach_->z.data() + b.offset, static_cast<Eigen::Index>(b.rows), static_cast<Eigen::Index>(b.columns));
  };
  Eigen::VectorXd zt_yhat = Eigen::VectorXd::Zero(reach_->columns);
  Eigen::VectorXd yhat;
  for (const SparseCholesky::Reach::Block& b : reach_->blocks) {
    yhat.resize(static_cast<Eigen::Index>(b.rows));
    for (Index k = 0; k < b.rows; ++k) yhat[static_cast<Eigen::Index>(k)] = y_[at[static_cast<std::size_t>(b.first_row + k)]];
    zt_yhat.segment(b.first_column, b.columns).noalias() += band(b).transpose() * yhat;
  }
  const Eigen::VectorXd y = lu_.solve(-(penalty_.asDiagonal() * zt_yhat(subset_)).eval());
  Eigen::VectorXd y_all = Eigen::VectorXd::Zero(reach_->columns);
  y_all(subset_) = y;
  Eigen::VectorXd zy;
  for (const SparseCholesky::Reach::Block& b : reach_->blocks) {
    zy.noalias() = band(b) * y_all.segment(b.first_column, b.columns);
    for (Index k = 0; k < b.rows; ++k) y_[at[static_cast<std::size_t>(b.first_row + k)]] += zy[static_cast<Eigen::Index>(k)];
  }
  cholesky_->backward(y_, x);
}

}  // namespace saasgaps
