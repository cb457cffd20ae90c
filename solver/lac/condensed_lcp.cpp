#include "solver/lac/condensed_lcp.hpp"

#include <algorithm>
#include <cassert>

namespace saasgaps {

LcpSolution solve_condensed_lcp(const Eigen::MatrixXd& s, const Eigen::VectorXd& q, std::vector<std::uint8_t> start,
                                std::span<const double> stiffness, double tolerance) {
  const auto n = static_cast<Eigen::Index>(q.size());
  assert(s.rows() == n && s.cols() == n && static_cast<Eigen::Index>(start.size()) == n);
  assert(static_cast<Eigen::Index>(stiffness.size()) == n);
  LcpSolution out;
  out.active = std::move(start);
  // Murty's rule visits at most 2^n sets in theory; a bound of a few times n keeps a guess cheap.
  const int max_steps = pdas_steps + 4 * static_cast<int>(n) + 10;
  std::vector<Eigen::Index> b;
  for (out.steps = 1; out.steps <= max_steps; ++out.steps) {
    b.clear();
    for (Eigen::Index i = 0; i < n; ++i) {
      if (out.active[i]) b.push_back(i);
    }
    out.force = Eigen::VectorXd::Zero(n);
    if (!b.empty()) {
      const auto m = static_cast<Eigen::Index>(b.size());
      Eigen::MatrixXd sbb(m, m);
      Eigen::VectorXd rhs(m);
      for (Eigen::Index j = 0; j < m; ++j) {
        rhs[j] = -q[b[j]];
        for (Eigen::Index i = 0; i < m; ++i) sbb(i, j) = s(b[i], b[j]);
      }
      const Eigen::LLT<Eigen::MatrixXd> llt(sbb);
      if (llt.info() != Eigen::Success) return out;  // not positive definite: no answer to give
      const Eigen::VectorXd lambda = llt.solve(rhs);
      for (Eigen::Index j = 0; j < m; ++j) out.force[b[j]] = lambda[j];
    }
    out.gap = q + s * out.force;
    // Violations in lengths: a pulling force over its row's stiffness, or a penetration.
    std::vector<Eigen::Index> violating;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double violation = out.active[i] ? -out.force[i] / stiffness[i] : -out.gap[i];
      if (violation > tolerance) violating.push_back(i);
    }
    if (violating.empty()) {
      out.settled = true;
      return out;
    }
    if (out.steps < pdas_steps) {
      for (const Eigen::Index i : violating) out.active[i] = out.active[i] ? 0 : 1;
    } else {
      const Eigen::Index i = violating.front();
      out.active[i] = out.active[i] ? 0 : 1;
    }
  }
  out.steps = max_steps;
  return out;
}

}  // namespace saasgaps
