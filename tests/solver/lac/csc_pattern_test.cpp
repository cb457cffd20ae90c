// The sparsity pattern of a sum of cliques, and the CHOLMOD wrapper: solves, refactorizations with
// the same analysis, and singular or indefinite matrices reported by column.
#include "solver/lac/csc_pattern.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <set>
#include <thread>

#include "solver/base/index_ranges.hpp"
#include "solver/lac/sparse_cholesky.hpp"

namespace saasgaps {
namespace {

const std::vector<std::vector<Index>> cliques = {{0, 3, 5}, {1, 2}, {3, -1, 4}, {5, 2}};

CscPattern example_pattern() {
  return CscPattern::from_cliques(7, cliques.size(), [](std::size_t c) { return std::span<const Index>(cliques[c]); });
}

TEST(CscPattern, HoldsExactlyTheCoupledPairsAndTheDiagonal) {
  const CscPattern p = example_pattern();
  std::set<std::pair<Index, Index>> expected;
  for (Index i = 0; i < 7; ++i) expected.insert({i, i});  // 6 is in no clique: its diagonal is kept
  for (const auto& c : cliques) {
    for (Index a : c) {
      for (Index b : c) {
        if (a >= 0 && b >= 0) expected.insert({std::min(a, b), std::max(a, b)});
      }
    }
  }
  std::set<std::pair<Index, Index>> actual;
  for (Index j = 0; j < p.n; ++j) {
    for (Index k = p.colptr[j]; k < p.colptr[j + 1]; ++k) {
      EXPECT_LE(p.rowind[k], j);
      if (k > p.colptr[j]) {
        EXPECT_LT(p.rowind[k - 1], p.rowind[k]);
      }
      actual.insert({p.rowind[k], j});
      EXPECT_EQ(p.find(p.rowind[k], j), k);
      EXPECT_EQ(p.find(j, p.rowind[k]), k);
    }
  }
  EXPECT_EQ(actual, expected);
  EXPECT_EQ(p.find(0, 1), -1);
}

/// Columns go to the cores in ranges (index_ranges.hpp) when there are many: a pattern of 30,000
/// indices in random cliques (some skipping prescribed ones) is still exactly the pairs they couple.
TEST(CscPattern, ManyColumnsSplitAmongTheCoresGiveTheSamePattern) {
  constexpr Index n = 30000;
  std::vector<std::vector<Index>> random_cliques;
  unsigned state = 12345;
  const auto next = [&state] { return state = state * 1103515245U + 12345U; };
  for (int c = 0; c < 20000; ++c) {
    std::vector<Index> clique;
    const Index base = static_cast<Index>(next() % n);
    for (unsigned k = 0, size = 1 + next() % 8; k < size; ++k) {
      clique.push_back(next() % 10 == 0 ? -1 : std::min<Index>(n - 1, base + static_cast<Index>(next() % 40)));
    }
    random_cliques.push_back(clique);
  }
  ASSERT_GT(range_count(n), 1U) << "the machine has one core: the split is not exercised";
  const CscPattern p = CscPattern::from_cliques(n, random_cliques.size(), [&](std::size_t c) {
    return std::span<const Index>(random_cliques[c]);
  });
  std::vector<std::set<Index>> expected(n);
  for (Index j = 0; j < n; ++j) expected[j].insert(j);
  for (const auto& c : random_cliques) {
    for (Index a : c) {
      for (Index b : c) {
        if (a >= 0 && b >= 0) expected[std::max(a, b)].insert(std::min(a, b));
      }
    }
  }
  ASSERT_EQ(p.colptr.size(), static_cast<std::size_t>(n) + 1);
  for (Index j = 0; j < n; ++j) {
    const std::vector<Index> column(p.rowind.begin() + p.colptr[j], p.rowind.begin() + p.colptr[j + 1]);
    ASSERT_EQ(column, std::vector<Index>(expected[j].begin(), expected[j].end())) << "column " << j;
  }
}

TEST(IndexRanges, OneParallelThreadKeepsEveryRangeOnTheCallersThread) {
  // What a server with several workers sets: each job's passes stay on its own thread.
  const unsigned before = parallel_threads();
  set_parallel_threads(1);
  EXPECT_EQ(range_count(1000000), 1U);
  std::vector<std::thread::id> ran;
  for_each_range(1000000, [&ran](std::size_t, std::size_t, unsigned) { ran.push_back(std::this_thread::get_id()); });
  set_parallel_threads(before);
  EXPECT_EQ(ran, std::vector<std::thread::id>{std::this_thread::get_id()});
  set_parallel_threads(0);  // never below one
  EXPECT_EQ(parallel_threads(), 1U);
  set_parallel_threads(before);
}

/// Fills the pattern's values from a dense symmetric matrix.
std::vector<double> values_of(const CscPattern& p, const Eigen::MatrixXd& A) {
  std::vector<double> v(static_cast<std::size_t>(p.nnz()));
  for (Index j = 0; j < p.n; ++j) {
    for (Index k = p.colptr[j]; k < p.colptr[j + 1]; ++k) v[k] = A(p.rowind[k], j);
  }
  return v;
}

/// A symmetric positive-definite matrix on the pattern: a graph Laplacian plus a shift.
Eigen::MatrixXd spd_on(const CscPattern& p, double shift) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p.n, p.n);
  for (Index j = 0; j < p.n; ++j) {
    for (Index k = p.colptr[j]; k < p.colptr[j + 1]; ++k) {
      const Index i = p.rowind[k];
      if (i == j) continue;
      A(i, j) = A(j, i) = -1.0;
      A(i, i) += 1.0;
      A(j, j) += 1.0;
    }
  }
  A.diagonal().array() += shift;
  return A;
}

TEST(SparseCholesky, SolvesAndRefactorsWithTheSameAnalysis) {
  const CscPattern p = example_pattern();
  SparseCholesky cholesky(p);
  for (double shift : {0.5, 3.0}) {
    const Eigen::MatrixXd A = spd_on(p, shift);
    const std::vector<double> values = values_of(p, A);
    cholesky.factorize(values);
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(p.n, 1.0, 7.0);
    std::vector<double> x(static_cast<std::size_t>(p.n));
    cholesky.solve(std::span<const double>(b.data(), b.size()), x);
    const Eigen::VectorXd expected = A.ldlt().solve(b);
    for (Index i = 0; i < p.n; ++i) EXPECT_NEAR(x[i], expected[i], 1e-12);
  }
}

TEST(SparseCholesky, ReportsTheColumnOfASingularMatrix) {
  const CscPattern p = example_pattern();
  Eigen::MatrixXd A = spd_on(p, 1.0);
  A(6, 6) = 0.0;  // index 6 couples to nothing and has no stiffness: a free node
  SparseCholesky cholesky(p);
  try {
    cholesky.factorize(values_of(p, A));
    FAIL() << "a zero pivot was not reported";
  } catch (const NotPositiveDefinite& e) {
    EXPECT_EQ(e.columns(), std::vector<Index>{6});
  }
}

TEST(SparseCholesky, ReportsAMatrixWithARigidBodyMode) {
  // A pure graph Laplacian: constant vectors on each connected part are in its null space.
  const CscPattern p = example_pattern();
  Eigen::MatrixXd A = spd_on(p, 0.0);
  A(6, 6) = 1.0;
  SparseCholesky cholesky(p);
  EXPECT_THROW(cholesky.factorize(values_of(p, A)), NotPositiveDefinite);
}

TEST(SparseCholesky, ReportsAnIndefiniteMatrix) {
  const CscPattern p = example_pattern();
  Eigen::MatrixXd A = spd_on(p, 1.0);
  A(3, 3) = -5.0;
  SparseCholesky cholesky(p);
  EXPECT_THROW(cholesky.factorize(values_of(p, A)), NotPositiveDefinite);
}

}  // namespace
}  // namespace saasgaps
