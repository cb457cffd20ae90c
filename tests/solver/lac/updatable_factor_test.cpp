// UpdatableFactor (solver/updatable_factor.hpp): the supernodal factor converted to simplicial LDL' in
// its own memory gives CHOLMOD's own conversion to the last digit, takes rank-k updates, and leaves
// the SparseCholesky able to factorize (supernodally) again.

#include <gtest/gtest.h>

#include <cholmod.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "solver/lac/sparse_cholesky.hpp"
#include "solver/lac/updatable_factor.hpp"
#include "support/laplacian_grid.hpp"

namespace saasgaps {
namespace {

using testing::Grid;

std::vector<double> load(Index n) {
  std::vector<double> b(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) b[i] = std::sin(0.37 * static_cast<double>(i)) + 0.5;
  return b;
}

/// x = (L D L')^-1 b through CHOLMOD's own copy and conversion of `cholesky`'s supernodal factor.
std::vector<double> solve_with_cholmod_conversion(const SparseCholesky& cholesky, const std::vector<double>& b) {
  cholmod_common common;
  cholmod_l_start(&common);
  cholmod_factor* L = cholmod_l_copy_factor(const_cast<cholmod_factor*>(cholesky.factor()), &common);
  EXPECT_TRUE(cholmod_l_change_factor(CHOLMOD_REAL, false, false, true, true, L, &common));
  cholmod_dense* B = cholmod_l_allocate_dense(b.size(), 1, b.size(), CHOLMOD_REAL, &common);
  std::copy(b.begin(), b.end(), static_cast<double*>(B->x));
  cholmod_dense* X = cholmod_l_solve(CHOLMOD_A, L, B, &common);
  std::vector<double> x(static_cast<const double*>(X->x), static_cast<const double*>(X->x) + b.size());
  cholmod_l_free_dense(&X, &common);
  cholmod_l_free_dense(&B, &common);
  cholmod_l_free_factor(&L, &common);
  cholmod_l_finish(&common);
  return x;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

TEST(UpdatableFactor, ConvertedInPlaceItSolvesAsCholmodsOwnConversionToTheLastDigit) {
  const Grid grid(40, 0.01);
  SparseCholesky cholesky(grid.pattern);
  cholesky.factorize(grid.values);
  const std::vector<double> b = load(grid.n());
  const std::vector<double> expected = solve_with_cholmod_conversion(cholesky, b);
  std::vector<double> supernodal(b.size()), x(b.size());
  cholesky.solve(b, supernodal);

  UpdatableFactor updatable;
  updatable.convert(cholesky);
  updatable.solve(b, x);
  for (std::size_t i = 0; i < x.size(); ++i) ASSERT_EQ(x[i], expected[i]) << "unknown " << i;
  EXPECT_LT(largest_difference(x, supernodal), 1e-12 * *std::max_element(supernodal.begin(), supernodal.end()));
}

TEST(UpdatableFactor, UpdatesTheConvertedFactorAndTheCholeskyFactorizesSupernodallyAgain) {
  const Grid grid(40, 0.01);
  const std::vector<double> b = load(grid.n());
  SparseCholesky cholesky(grid.pattern);
  cholesky.factorize(grid.values);
  std::vector<double> before(b.size());
  cholesky.solve(b, before);

  // A + w w' with w on two coupled unknowns (a constraint row's clique): against a factorization.
  const Index i = 820, j = 821;
  ASSERT_GE(grid.pattern.find(i, j), 0);
  const double wi = 30.0, wj = -30.0;
  std::vector<double> stiffer = grid.values;
  stiffer[grid.pattern.find(i, i)] += wi * wi;
  stiffer[grid.pattern.find(j, j)] += wj * wj;
  stiffer[grid.pattern.find(i, j)] += wi * wj;
  SparseCholesky reference(grid.pattern);
  reference.factorize(stiffer);
  std::vector<double> expected(b.size()), x(b.size());
  reference.solve(b, expected);

  SparseColumns w;
  w.add(i, wi);
  w.add(j, wj);
  w.end_column();
  UpdatableFactor updatable;
  for (int round = 0; round < 2; ++round) {  // the second conversion reuses the derived pattern
    updatable.convert(cholesky);
    updatable.update(w, true);
    updatable.solve(b, x);
    EXPECT_LT(largest_difference(x, expected), 1e-11 * *std::max_element(expected.begin(), expected.end()));
    updatable.update(w, false);  // back to A
    updatable.solve(b, x);
    EXPECT_LT(largest_difference(x, before), 1e-11 * *std::max_element(before.begin(), before.end()));

    // The values were overwritten; the analysis was not: a factorization is supernodal and exact again.
    cholesky.factorize(grid.values);
    EXPECT_TRUE(cholesky.factor()->is_super);
    cholesky.solve(b, x);
    EXPECT_EQ(x, before);
  }

  // Another analysis (another pattern) through the same UpdatableFactor: its pattern is derived anew.
  const Grid other(25, 0.5);
  SparseCholesky second(other.pattern);
  second.factorize(other.values);
  const std::vector<double> c = load(other.n());
  std::vector<double> y(c.size());
  second.solve(c, y);
  std::vector<double> z(c.size());
  updatable.convert(second);
  updatable.solve(c, z);
  EXPECT_LT(largest_difference(y, z), 1e-12 * *std::max_element(y.begin(), y.end()));
}

TEST(UpdatableFactor, ACopyOfAConvertedFactorIsItsOwnAndOutlivesTheNextFactorization) {
  const Grid grid(40, 0.01);
  const std::vector<double> b = load(grid.n());
  SparseCholesky cholesky(grid.pattern);
  cholesky.factorize(grid.values);
  std::vector<double> expected(b.size()), x(b.size());

  UpdatableFactor converted, kept, working;
  converted.convert(cholesky);
  converted.solve(b, expected);  // the simplicial factor's digits, which its copies must keep
  kept.copy(converted);     // what ConstraintRows::hold_from keeps across solves
  working.copy(converted);  // memory of its own, then (below) a copy into it
  // The supernodal factorization's memory, which `converted` lends, is overwritten: the copies are not.
  std::vector<double> other = grid.values;
  for (Index j = 0; j < grid.n(); ++j) other[grid.pattern.find(j, j)] += 3.0;
  cholesky.factorize(other);
  kept.solve(b, x);
  EXPECT_EQ(x, expected);
  SparseColumns w;
  w.add(820, 30.0);
  w.add(821, -30.0);
  w.end_column();
  working.update(w, true);
  working.copy(kept);  // into the arrays it owns: the update is gone, the kept factor unchanged
  working.solve(b, x);
  EXPECT_EQ(x, expected);
  kept.solve(b, x);
  EXPECT_EQ(x, expected);

  // Converting into a factor that owns its values gives them up for the lent ones.
  working.convert(cholesky);
  std::vector<double> stiffer(b.size());
  working.solve(b, x);
  cholesky.factorize(other);
  cholesky.solve(b, stiffer);
  EXPECT_LT(largest_difference(x, stiffer), 1e-12 * *std::max_element(stiffer.begin(), stiffer.end()));

  // And a copy into a factor whose values are lent never writes the SparseCholesky's memory, which
  // holds a live factorization again.
  working.copy(kept);
  working.solve(b, x);
  EXPECT_EQ(x, expected);
  std::vector<double> again(b.size());
  cholesky.solve(b, again);
  EXPECT_EQ(again, stiffer);
}

}  // namespace
}  // namespace saasgaps
