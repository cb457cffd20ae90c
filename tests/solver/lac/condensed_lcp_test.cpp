// solve_condensed_lcp (solver/condensed_lcp.hpp): the one solution of a positive-definite LCP,
// against every active set tried in turn.

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "solver/lac/condensed_lcp.hpp"

namespace saasgaps {
namespace {

/// The solution by enumeration: the set whose lambda_B = -S_BB^-1 q_B is >= 0 and whose other gaps
/// are >= 0 (one exists and is unique for positive-definite S).
std::vector<std::uint8_t> by_enumeration(const Eigen::MatrixXd& s, const Eigen::VectorXd& q) {
  const auto n = q.size();
  for (unsigned set = 0; set < (1U << n); ++set) {
    std::vector<Eigen::Index> b;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (set & (1U << i)) b.push_back(i);
    }
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(n);
    if (!b.empty()) {
      Eigen::MatrixXd sbb(b.size(), b.size());
      Eigen::VectorXd rhs(b.size());
      for (std::size_t j = 0; j < b.size(); ++j) {
        rhs[j] = -q[b[j]];
        for (std::size_t i = 0; i < b.size(); ++i) sbb(i, j) = s(b[i], b[j]);
      }
      const Eigen::VectorXd x = sbb.llt().solve(rhs);
      for (std::size_t j = 0; j < b.size(); ++j) lambda[b[j]] = x[j];
    }
    const Eigen::VectorXd g = q + s * lambda;
    bool ok = true;
    for (Eigen::Index i = 0; i < n && ok; ++i) ok = (set & (1U << i)) ? lambda[i] >= -1e-12 : g[i] >= -1e-12;
    if (!ok) continue;
    std::vector<std::uint8_t> active(n);
    for (Eigen::Index i = 0; i < n; ++i) active[i] = (set >> i) & 1U;
    return active;
  }
  return {};
}

TEST(CondensedLcp, FindsTheSolutionEnumerationFindsFromAnyStart) {
  std::mt19937 random(20261125);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Index n = 2 + trial % 9;
    // A contact-like S: a dominant diagonal and positive coupling of neighbours, or a random SPD one.
    Eigen::MatrixXd a(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = 0; j < n; ++j) a(i, j) = normal(random);
    }
    const Eigen::MatrixXd s = a * a.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
    Eigen::VectorXd q(n);
    for (Eigen::Index i = 0; i < n; ++i) q[i] = normal(random);
    std::vector<std::uint8_t> start(n);
    for (Eigen::Index i = 0; i < n; ++i) start[i] = (trial + i) % 3 == 0;
    const std::vector<double> stiffness(static_cast<std::size_t>(n), 1.0);
    const LcpSolution lcp = solve_condensed_lcp(s, q, start, stiffness, 1e-12);
    ASSERT_TRUE(lcp.settled) << "trial " << trial;
    EXPECT_EQ(lcp.active, by_enumeration(s, q)) << "trial " << trial;
    for (Eigen::Index i = 0; i < n; ++i) {
      EXPECT_GE(lcp.force[i], -1e-12);
      EXPECT_GE(lcp.gap[i], -1e-12);
      EXPECT_NEAR(lcp.force[i] * lcp.gap[i], 0.0, 1e-12);
    }
  }
}

TEST(CondensedLcp, ABeamOnUnilateralSupportsLiftsOffAtItsEnds) {
  // Springs coupled in a chain (S = inverse of a tridiagonal stiffness), pressed in the middle and
  // pulled at the ends: the middle rows press, the end rows open.
  const Eigen::Index n = 9;
  Eigen::MatrixXd k = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    k(i, i) = 3.0;
    if (i + 1 < n) k(i, i + 1) = k(i + 1, i) = -1.0;
  }
  const Eigen::MatrixXd s = k.inverse();
  Eigen::VectorXd q(n);
  for (Eigen::Index i = 0; i < n; ++i) q[i] = 0.2 * std::abs(static_cast<double>(i - 4)) - 0.5;
  const std::vector<double> stiffness(static_cast<std::size_t>(n), 3.0);
  const LcpSolution lcp = solve_condensed_lcp(s, q, std::vector<std::uint8_t>(n, 1), stiffness, 1e-14);
  ASSERT_TRUE(lcp.settled);
  EXPECT_EQ(lcp.active, by_enumeration(s, q));
  EXPECT_EQ(lcp.active[4], 1);
  EXPECT_EQ(lcp.active[0], 0);
  EXPECT_EQ(lcp.active[8], 0);
}

TEST(CondensedLcp, ANotPositiveDefiniteSubmatrixGivesNoAnswer) {
  Eigen::MatrixXd s(2, 2);
  s << 1.0, 1.0, 1.0, 1.0;  // singular: two rows that are one
  const Eigen::VectorXd q = -Eigen::VectorXd::Ones(2);
  const std::vector<double> stiffness(2, 1.0);
  EXPECT_FALSE(solve_condensed_lcp(s, q, {1, 1}, stiffness, 1e-12).settled);
}

}  // namespace
}  // namespace saasgaps
