#pragma once
/// The linear complementarity problem of a few contact rows condensed onto their multipliers:
///   g = q + S lambda,   lambda >= 0,   g >= 0,   lambda_i g_i = 0   (every row i),
/// S symmetric positive definite (S = C K^-1 C' for the rows C of the window, lengths per force),
/// q the gaps at lambda = 0 (lengths). With S positive definite it has exactly one solution, the
/// minimizer of lambda'S lambda / 2 + q'lambda over lambda >= 0.
///
/// Solved by the primal-dual active-set method on the dense S (each step: a Cholesky factorization
/// of S_BB and lambda_B = -S_BB^-1 q_B, lambda = 0 off B; then B <- {lambda_i > tol} U {g_i < -tol}).
/// After `pdas_steps` steps without settling, Murty's least-index rule (change only the first row
/// that violates), which settles on any P-matrix; the count of steps stays bounded either way.
/// Rows of S are a window of ExactContact's rows: the answer is its guess of where the contact
/// boundary lies (constraint_rows.hpp, ConstraintRows::condense).

#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Dense>

namespace saasgaps {

struct LcpSolution {
  std::vector<std::uint8_t> active;  ///< 1: lambda_i > 0 allowed, g_i = 0
  Eigen::VectorXd force;             ///< lambda
  Eigen::VectorXd gap;               ///< g = q + S lambda
  int steps = 0;                     ///< active sets tried
  bool settled = false;              ///< no row violates its set by more than the tolerance
};

/// PDAS steps before the least-index rule takes over.
inline constexpr int pdas_steps = 25;

/// start: the first set (one flag per row). stiffness: per row, the force per length that turns a
/// force into a length for the tolerance test (lambda_i / k_i); tolerance: lengths.
LcpSolution solve_condensed_lcp(const Eigen::MatrixXd& s, const Eigen::VectorXd& q, std::vector<std::uint8_t> start,
                                std::span<const double> stiffness, double tolerance);

}  // namespace saasgaps
