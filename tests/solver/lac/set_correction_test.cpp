// SetCorrection (solver/set_correction.hpp): a set near the factorized one, solved on that
// factorization, against a factorization of its own matrix.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "solver/contact/constraint_rows.hpp"
#include "solver/lac/set_correction.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "support/laplacian_grid.hpp"

namespace saasgaps {
namespace {

using testing::Grid;

/// K plus rho (u_i - u_{i+1})^2 for each i in rows: penalized gaps between neighbours.
std::vector<double> with_penalties(const Grid& grid, const std::vector<Index>& rows, double rho) {
  std::vector<double> values = grid.values;
  for (const Index i : rows) {
    values[grid.pattern.find(i, i)] += rho;
    values[grid.pattern.find(i + 1, i + 1)] += rho;
    values[grid.pattern.find(i, i + 1)] -= rho;
  }
  return values;
}

TEST(SetCorrection, SolvesTheNearbySetAsItsOwnFactorizationDoes) {
  const Grid grid(50, 0.001);
  const double rho = 1.0e4 * 8.0;  // the contact rows' penalty: 10^4 times c' diag(K) c
  // Factorized: rows 0..29 penalized. Wanted: rows 10..39 (drops 0..9, adds 30..39).
  std::vector<Index> factored, wanted;
  for (Index i = 0; i < 30; ++i) factored.push_back(i);
  for (Index i = 10; i < 40; ++i) wanted.push_back(i);
  SparseCholesky cholesky(grid.pattern);
  cholesky.factorize(with_penalties(grid, factored, rho));
  SparseColumns d;
  std::vector<double> signed_penalties;
  for (Index i = 0; i < 40; ++i) {
    const bool in_f = i < 30, in_w = i >= 10;
    if (in_f == in_w) continue;
    d.add(i, 1.0);
    d.add(i + 1, -1.0);
    d.end_column();
    signed_penalties.push_back(in_w ? rho : -rho);
  }
  SetCorrection correction;
  correction.set(cholesky, d, signed_penalties);
  EXPECT_EQ(correction.rank(), 20U);

  SparseCholesky own(grid.pattern);
  own.factorize(with_penalties(grid, wanted, rho));
  std::vector<double> b(static_cast<std::size_t>(grid.n()));
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = std::sin(0.37 * static_cast<double>(i)) + 0.5;
  std::vector<double> x(b.size()), expected(b.size());
  correction.solve(b, x);
  own.solve(b, expected);
  const double largest = std::abs(*std::max_element(expected.begin(), expected.end(), [](double a, double c) { return std::abs(a) < std::abs(c); }));
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(x[i] - expected[i]));
  std::printf("largest difference %.3e of %.3e, loss %.3e\n", worst, largest, correction.loss());
  // The dropped rows' penalties are cancelled by forces about rho f times their own: the loss,
  // here 1 + rho f of a grid row, a few times 10^4. Observed 1.6e-12 of the largest unknown.
  EXPECT_GT(correction.loss(), 1e4);
  EXPECT_LT(correction.loss(), 1e6);
  EXPECT_LT(worst, 3e-12 * largest);
  // The factorization itself still solves its own set.
  std::vector<double> again(b.size()), direct(b.size());
  SparseCholesky reference(grid.pattern);
  reference.factorize(with_penalties(grid, factored, rho));
  reference.solve(b, direct);
  cholesky.solve(b, again);
  EXPECT_EQ(again, direct);
}

// The same correction from the columns of a wider window's forward solves (the look-ahead's
// condensation, ConstraintRows::condense) solves as one that does its own.
TEST(SetCorrection, FromAWindowsForwardSolvesSolvesAsFromItsOwn) {
  const Grid grid(50, 0.001);
  const double rho = 1.0e4 * 8.0;
  std::vector<Index> factored;
  for (Index i = 0; i < 30; ++i) factored.push_back(i);
  SparseCholesky cholesky(grid.pattern);
  cholesky.factorize(with_penalties(grid, factored, rho));
  // The window: rows 5..44; the change: drops 5..9, adds 30..34 (window columns 0..4, 25..29).
  const auto gap_column = [](SparseColumns& c, Index i) {
    c.add(i, 1.0);
    c.add(i + 1, -1.0);
    c.end_column();
  };
  SparseColumns window, d;
  for (Index i = 5; i < 45; ++i) gap_column(window, i);
  std::vector<std::size_t> subset;
  std::vector<double> signed_penalties;
  for (Index i = 5; i < 35; ++i) {
    if (i >= 10 && i < 30) continue;
    gap_column(d, i);
    subset.push_back(static_cast<std::size_t>(i - 5));
    signed_penalties.push_back(i >= 30 ? rho : -rho);
  }
  const auto reach = std::make_shared<const SparseCholesky::Reach>(cholesky.forward_columns(window));
  const std::vector<double> gram = reach->gram();
  SetCorrection own, from_window;
  own.set(cholesky, d, signed_penalties);
  from_window.set(cholesky, reach, gram, subset, signed_penalties);
  EXPECT_EQ(from_window.rank(), 10U);
  EXPECT_DOUBLE_EQ(from_window.loss(), own.loss());
  std::vector<double> b(static_cast<std::size_t>(grid.n()));
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = std::cos(0.41 * static_cast<double>(i)) - 0.2;
  std::vector<double> x(b.size()), expected(b.size());
  from_window.solve(b, x);
  own.solve(b, expected);
  double largest = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    largest = std::max(largest, std::abs(expected[i]));
    worst = std::max(worst, std::abs(x[i] - expected[i]));
  }
  EXPECT_LT(worst, 1e-13 * largest);  // the same arithmetic but for the order of Z'Z's sums
}

TEST(SetCorrection, ReportsTheDigitsItWouldLoseWhereAPenaltyIsAllThatHolds) {
  // A free grid (each diagonal the sum of its couplings, plus 1e-9): a part nothing holds but a
  // weak spring. A penalty on one of its unknowns changes that unknown's flexibility by 1 + rho f,
  // f about 1 / (400 x 1e-9): 1 + 2e4 x 2.5e6 = 5e10, and its correction would cancel forces that
  // much larger than its own.
  Grid grid(20, 0.0);
  std::vector<double> degree(static_cast<std::size_t>(grid.n()), 0.0);
  for (Index j = 0; j < grid.n(); ++j) {
    for (Index p = grid.pattern.colptr[j]; p < grid.pattern.colptr[j + 1]; ++p) {
      if (grid.pattern.rowind[p] == j) continue;
      degree[j] += 1.0;
      degree[grid.pattern.rowind[p]] += 1.0;
    }
  }
  for (Index j = 0; j < grid.n(); ++j) grid.values[grid.pattern.find(j, j)] = degree[j] + 1.0e-9;
  SparseCholesky cholesky(grid.pattern);
  cholesky.factorize(grid.values);
  SparseColumns d;
  d.add(0, 1.0);
  d.end_column();
  SetCorrection correction;
  const std::vector<double> penalty{1.0e4 * 2.0};
  correction.set(cholesky, d, penalty);
  EXPECT_NEAR(correction.loss(), 5.0e10, 0.01 * 5.0e10);
  EXPECT_GT(correction.loss(), ConstraintRows::max_correction_loss);
}

}  // namespace
}  // namespace saasgaps
