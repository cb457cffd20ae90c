// SparseCholesky::inverse_form (solver/sparse_cholesky.hpp): C A^-1 C' from forward solves over the
// columns' reach equals the same product from whole solves.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

#include "solver/lac/sparse_cholesky.hpp"
#include "support/laplacian_grid.hpp"

namespace saasgaps {
namespace {

using testing::Grid;

/// C A^-1 C' column by column from whole solves: the reference.
std::vector<double> by_whole_solves(SparseCholesky& cholesky, const SparseColumns& c, Index n) {
  const std::size_t m = c.size();
  std::vector<double> form(m * m), b(static_cast<std::size_t>(n)), x(static_cast<std::size_t>(n));
  for (std::size_t j = 0; j < m; ++j) {
    std::fill(b.begin(), b.end(), 0.0);
    for (Index k = c.start[j]; k < c.start[j + 1]; ++k) b[c.row[k]] += c.value[k];
    cholesky.solve(b, x);
    for (std::size_t i = 0; i < m; ++i) {
      double sum = 0.0;
      for (Index k = c.start[i]; k < c.start[i + 1]; ++k) sum += c.value[k] * x[c.row[k]];
      form[i + j * m] = sum;
    }
  }
  return form;
}

TEST(SparseCholesky, InverseFormOverTheReachEqualsWholeSolves) {
  const Grid grid(60, 0.01);
  SparseCholesky cholesky(grid.pattern);
  cholesky.factorize(grid.values);
  // Rows along one edge of the grid (a contact surface's), each over two neighbours with
  // weights of both signs, and one row far away whose reach is another branch of the tree.
  SparseColumns c;
  for (Index k = 0; k < 12; ++k) {
    c.add(5 + k, 1.0 + 0.1 * static_cast<double>(k));
    c.add(6 + k, -0.5);
    c.end_column();
  }
  c.add(59 * 60 + 30, 2.0);
  c.end_column();
  const std::vector<double> form = cholesky.inverse_form(c);
  const std::vector<double> expected = by_whole_solves(cholesky, c, grid.n());
  ASSERT_EQ(form.size(), expected.size());
  const double largest = *std::max_element(expected.begin(), expected.end());
  for (std::size_t i = 0; i < form.size(); ++i) EXPECT_NEAR(form[i], expected[i], 1e-13 * largest) << "entry " << i;
  // Symmetric to the last bit, and the far row couples to the edge's rows only weakly.
  const std::size_t m = c.size();
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < m; ++j) EXPECT_EQ(form[i + j * m], form[j + i * m]);
  }
}

TEST(SparseCholesky, ForwardColumnsKeepOnlyEachSupernodesBandAndEqualWholeForwardSolves) {
  // Forty rows along one edge, in chain order: nearby rows' paths meet low in the elimination tree,
  // all of them near the root, so most supernodes need a narrow band of the forty columns.
  const Grid grid(60, 0.01);
  SparseCholesky cholesky(grid.pattern);
  cholesky.factorize(grid.values);
  SparseColumns c;
  for (Index k = 0; k < 40; ++k) {
    c.add(60 * k + 3, 1.0);
    c.add(60 * (k + 1) + 3, -0.7);
    c.end_column();
  }
  const SparseCholesky::Reach reach = cholesky.forward_columns(c);
  const auto m = static_cast<std::size_t>(reach.columns);
  std::size_t stored = 0;
  Index next_row = 0;
  for (const SparseCholesky::Reach::Block& b : reach.blocks) {
    EXPECT_EQ(b.first_row, next_row);
    EXPECT_EQ(b.offset, stored);
    next_row += b.rows;
    stored += static_cast<std::size_t>(b.rows * b.columns);
  }
  EXPECT_EQ(static_cast<std::size_t>(next_row), reach.positions.size());
  EXPECT_EQ(stored, reach.z.size());
  EXPECT_LT(stored, reach.positions.size() * m / 2) << "the bands hold most of the dense Z";
  // Column j of Z, read from the bands (zero outside them), against L^-1 P c_j from a whole forward solve.
  std::vector<double> b(static_cast<std::size_t>(grid.n())), y(b.size());
  double worst = 0.0, largest = 0.0;
  for (std::size_t j = 0; j < m; ++j) {
    std::fill(b.begin(), b.end(), 0.0);
    for (Index k = c.start[j]; k < c.start[j + 1]; ++k) b[c.row[k]] += c.value[k];
    cholesky.forward(b, y);
    std::vector<double> from_reach(y.size(), 0.0);
    for (const SparseCholesky::Reach::Block& blk : reach.blocks) {
      const auto column = static_cast<Index>(j);
      if (column < blk.first_column || column >= blk.first_column + blk.columns) continue;
      for (Index r = 0; r < blk.rows; ++r) {
        from_reach[reach.positions[static_cast<std::size_t>(blk.first_row + r)]] =
            reach.z[blk.offset + static_cast<std::size_t>(r * blk.columns + column - blk.first_column)];
      }
    }
    for (std::size_t i = 0; i < y.size(); ++i) {
      largest = std::max(largest, std::abs(y[i]));
      worst = std::max(worst, std::abs(from_reach[i] - y[i]));
    }
  }
  EXPECT_LT(worst, 1e-13 * largest);
}

/// x = A^-1 b for a grid whose ordering is METIS's on its unknowns (each its own group).
std::vector<double> solved_with_metis(const Grid& grid) {
  std::vector<Index> groups(static_cast<std::size_t>(grid.n()));
  for (std::size_t k = 0; k < groups.size(); ++k) groups[k] = static_cast<Index>(k);
  SparseCholesky cholesky(grid.pattern, groups);
  cholesky.factorize(grid.values);
  std::vector<double> b(groups.size()), x(groups.size());
  for (std::size_t k = 0; k < b.size(); ++k) b[k] = std::sin(0.37 * static_cast<double>(k)) + 0.1;
  cholesky.solve(b, x);
  return x;
}

TEST(SparseCholesky, OrderingsComputedSideBySideGiveTheDigitsOfOrderingsComputedAlone) {
  // METIS keeps its random state in a static of GKlib: two orderings at once (a server's two
  // workers) interleaved its draws and gave other permutations, so other last digits, than alone.
  const Grid a(40, 0.01), b(33, 0.02);
  const std::vector<double> alone_a = solved_with_metis(a), alone_b = solved_with_metis(b);
  int differing = 0;
  std::thread other([&] {
    for (int k = 0; k < 30; ++k) differing += solved_with_metis(b) != alone_b;
  });
  int differing_here = 0;
  for (int k = 0; k < 30; ++k) differing_here += solved_with_metis(a) != alone_a;
  other.join();
  EXPECT_EQ(differing + differing_here, 0);
}

TEST(SparseCholesky, InverseFormOfNoColumnsIsEmptyAndTheFactorStillSolves) {
  const Grid grid(10, 0.5);
  SparseCholesky cholesky(grid.pattern);
  cholesky.factorize(grid.values);
  EXPECT_TRUE(cholesky.inverse_form(SparseColumns{}).empty());
  std::vector<double> b(static_cast<std::size_t>(grid.n()), 1.0), x(b.size());
  cholesky.solve(b, x);
  EXPECT_GT(x[0], 0.0);
}

}  // namespace
}  // namespace saasgaps
