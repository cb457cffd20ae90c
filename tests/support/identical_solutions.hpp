#pragma once
/// Two solutions equal in every computed number, to the last digit (wall times aside): what an exact
/// restart, or a run with a cached ordering, must give.

#include <gtest/gtest.h>

#include "solver/state/solution.hpp"

namespace saasgaps::testing {

inline void expect_identical(const Solution& a, const Solution& b) {
  ASSERT_EQ(a.status, b.status);
  ASSERT_EQ(a.iterations, b.iterations);
  ASSERT_EQ(a.history.size(), b.history.size());
  for (std::size_t k = 0; k < a.history.size(); ++k) {
    EXPECT_TRUE(a.history[k].same_numbers(b.history[k])) << "history row " << k + 1;
  }
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t n = 0; n < a.nodes.size(); ++n) {
    EXPECT_EQ(a.nodes[n].u_r, b.nodes[n].u_r);
    EXPECT_EQ(a.nodes[n].u_z, b.nodes[n].u_z);
  }
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t e = 0; e < a.elements.size(); ++e) {
    EXPECT_EQ(a.elements[e].stress, b.elements[e].stress) << "element " << a.elements[e].id;
    EXPECT_EQ(a.elements[e].strain, b.elements[e].strain);
    EXPECT_EQ(a.elements[e].effective, b.elements[e].effective);
    EXPECT_EQ(a.elements[e].yielded, b.elements[e].yielded);
    EXPECT_EQ(a.elements[e].plastic_converged, b.elements[e].plastic_converged);
  }
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t k = 0; k < a.steps.size(); ++k) EXPECT_EQ(a.steps[k].status, b.steps[k].status) << "step " << k + 1;
  ASSERT_EQ(a.gaps.size(), b.gaps.size());
  for (std::size_t g = 0; g < a.gaps.size(); ++g) {
    EXPECT_EQ(a.gaps[g].eps_m, b.gaps[g].eps_m) << "gap " << a.gaps[g].id;
    EXPECT_EQ(a.gaps[g].modulus, b.gaps[g].modulus);
    EXPECT_EQ(a.gaps[g].sigma_m, b.gaps[g].sigma_m);
    EXPECT_EQ(a.gaps[g].converged, b.gaps[g].converged);
  }
}

}  // namespace saasgaps::testing
