// The report's sample problems (section III), run from schemas/examples, against its Tables I-III
// and its beam check (p. 17). Each tolerance is the deviation from the report observed when it was
// set (given in the comment, relative unless said otherwise) plus a margin of about 10-20 %, with a
// floor of 1e-8 where the observed deviation is round-off: a change of our numbers by a fraction of
// a percent fails here. Where our numbers differ from the report's, the reason is written next to
// the assertion. (Our own values, as the README quotes them, are pinned in report_figures_test.cpp.)
#include <gtest/gtest.h>

#include <cmath>

#include "solver/analysis/analysis.hpp"
#include "support/by_id.hpp"
#include "support/examples.hpp"

namespace saasgaps {
namespace {

using testing::example_model;

// A missing id throws (support/by_id.hpp): the test fails naming it, never reads past the end.
const WatchedGap& watched_gap(const IterationRecord& row, int id) { return testing::by_id(row.watch_gaps, id); }

const WatchedElement& watched_element(const IterationRecord& row, int id) {
  return testing::by_id(row.watch_elements, id);
}

double relative(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

const NodeResult& node(const Solution& s, int id) { return testing::by_id(s.nodes, id); }

const ElementResult& element(const Solution& s, int id) { return testing::by_id(s.elements, id); }

TEST(ReportTableI, UniformLoadOnAnUnrestrainedBodyIterationByIteration) {
  const Solution s = solve(example_model("report-problem1.json"));
  // The report lists 4 iterations and its third and fourth closures (99.01, 99.00 %) pass the test.
  ASSERT_EQ(s.status, RunStatus::converged);
  ASSERT_EQ(s.iterations, 4);
  const double modulus[] = {100.0, 1111.1, 1010.1, 1010.1};
  // Observed 0 (the initial modulus), 1.0e-5, 1.0e-6, 1.0e-6: the report's rounding to 5 digits.
  const double modulus_tolerance[] = {1e-8, 1.2e-5, 1.2e-6, 1.2e-6};
  const double closure[] = {1000.0, 90.0, 99.01, 99.00};
  // Observed 7.2e-9, 1.7e-9, 1.01e-4 (the report's 99.01 against our 99.000), 3.3e-9.
  const double closure_tolerance[] = {1e-8, 1e-8, 1.2e-4, 1e-8};
  for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE("iteration " + std::to_string(k + 1));
    const IterationRecord& row = s.history[k];
    EXPECT_LT(relative(watched_gap(row, 15).modulus, modulus[k]), modulus_tolerance[k]);
    EXPECT_LT(relative(watched_gap(row, 15).closure, closure[k]), closure_tolerance[k]);
    // "a compressive stress of 1000 psi exists in the structural elements": observed 3.6e-9 at most.
    EXPECT_LT(relative(watched_element(row, 5).sigma_z, -1000.0), 1e-8);
  }
  // Every gap under the body carries the load at 99 % closure: uniform contact with the wall.
  // Observed: closures within 1.1e-6 (%) of 99, stresses within 4.9e-5 psi of -1000.
  for (const GapResult& g : s.gaps) {
    if (g.id >= 11 && g.id <= 19) {
      EXPECT_NEAR(g.closure, 99.0, 1.5e-6) << "gap " << g.id;
      EXPECT_NEAR(g.sigma_m, -1000.0, 6e-5) << "gap " << g.id;
    }
  }
}

TEST(ReportTableII, ThermalGrowthAcrossAGapIterationByIteration) {
  const Solution s = solve(example_model("report-problem2.json"));
  ASSERT_EQ(s.status, RunStatus::converged);
  ASSERT_EQ(s.iterations, 5);
  const double modulus[] = {100.0, 1111.3, 6432.9, 9616.8, 10064.4};
  // Observed 0 (the initial modulus), 1.70e-4, 2.39e-5, 5.98e-5, 9.4e-6.
  const double modulus_tolerance[] = {1e-8, 2.0e-4, 2.8e-5, 7.0e-5, 1.1e-5};
  const double sigma_r[] = {-1000.0, -5790.0, -9520.0, -9964.0, -10006.0};
  // Observed 3.0e-6, 9.09e-5, 6.6e-6, 1.50e-5, 1.71e-5.
  const double sigma_r_tolerance[] = {3.6e-6, 1.05e-4, 7.8e-6, 1.8e-5, 2.0e-5};
  const double closure[] = {1000.2, 521.0, 148.0, 103.6, 99.4};
  // Observed 2.00e-4, 1.01e-4, 4.23e-5, 1.45e-4, 1.72e-4.
  const double closure_tolerance[] = {2.3e-4, 1.2e-4, 5.0e-5, 1.7e-4, 2.0e-4};
  for (int k = 0; k < 5; ++k) {
    SCOPED_TRACE("iteration " + std::to_string(k + 1));
    const IterationRecord& row = s.history[k];
    EXPECT_LT(relative(watched_gap(row, 20).modulus, modulus[k]), modulus_tolerance[k]);
    EXPECT_LT(relative(watched_element(row, 9).sigma_r, sigma_r[k]), sigma_r_tolerance[k]);
    EXPECT_LT(relative(watched_gap(row, 20).closure, closure[k]), closure_tolerance[k]);
  }
  // Closed form with the given clearance: the body grows alpha T L = 0.099 in, the 0.009 in gap takes
  // 0.009 in of it, the rest is squeezed out of the 9 in body: sigma_R = -E (alpha T L - delta) / L
  // = -10000 psi. The classic iteration stops at 99.4 % closure, so the body takes a little more:
  // observed 5.83e-4 (-10005.8 psi).
  const GapResult& gap_20 = s.gaps.back();
  ASSERT_EQ(gap_20.id, 20);
  EXPECT_LT(relative(element(s, 5).stress[rr], -1.0e6 * (1.0e-5 * 1100.0 * 9.0 - 0.009) / 9.0), 6.5e-4);
  // docs/algorithm.md: the body stress equals the gap stress (to 0.02 % in the report's table); here
  // every element's within 4.5e-8 of gap 20's.
  for (const ElementResult& e : s.elements) EXPECT_LT(relative(e.stress[rr], gap_20.sigma_m), 6e-8) << "element " << e.id;
}

/// Problem 3 with one change to the example's solver settings.
Solution problem3(int case_number, int max_iterations = 0) {
  ResumeOptions options;
  if (max_iterations > 0) options.max_iterations = max_iterations;
  return solve(example_model("report-problem3-case" + std::to_string(case_number) + ".json"), nullptr, nullptr,
               options);
}

TEST(ReportTableIIIa, FirstIterationAndConvergedAnswer) {
  const Solution s = problem3(1);
  const IterationRecord& first = s.history.front();
  // Our reading of the boundary conditions gives 200.6 % / 20862 psi against the report's 201.4 % /
  // 20937 psi: within 0.4 %, the difference between our decoded mesh and the 1976 deck.
  // Observed 3.73e-3 and 3.58e-3.
  EXPECT_LT(relative(first.average_closure, 201.4), 4.1e-3);
  EXPECT_EQ(first.closed_gaps, 14);
  EXPECT_LT(relative(watched_element(first, 62).sigma_r, 20937.0), 3.9e-3);

  ASSERT_EQ(s.status, RunStatus::converged);
  const IterationRecord& last = s.history.back();
  EXPECT_EQ(last.closed_gaps, 4);  // the report's 4
  // Observed 9.20e-3 (6976.6 against 6913): the first iteration's 0.4 % grown over the iterations.
  EXPECT_LT(relative(watched_element(last, 62).sigma_r, 6913.0), 9.6e-3);
  EXPECT_EQ(last.nonconverged_gaps, 0);
  // "The peak bending stress is 7700 psi and occurs ... near the point of separation" (bottom row).
  // Observed 7.04e-3 (7754.2).
  double peak = 0.0;
  for (const ElementResult& e : s.elements) peak = std::max(peak, e.effective);
  EXPECT_LT(relative(peak, 7700.0), 7.5e-3);
}

TEST(ReportTableIIIb, YieldingOnTheWayConvergesToTheElasticAnswer) {
  const Solution s = problem3(2);
  ASSERT_EQ(s.status, RunStatus::converged);
  // Elements yield in the early iterations ...
  EXPECT_GT(s.history[1].yielded_elements, 0);
  // ... but "the final result for Case 2 should be a duplicate of Case 1 with no structural elements
  // above the yield stress".
  EXPECT_EQ(s.history.back().yielded_elements, 0);
  for (const ElementResult& e : s.elements) EXPECT_FALSE(e.yielded) << "element " << e.id;
  // Observed 7.25e-3 (7108.1 against 7160).
  EXPECT_LT(relative(watched_element(s.history.back(), 62).sigma_r, 7160.0), 7.8e-3);
  // Observed 1.89e-2: both runs stop within the closure tolerance of contact, by different paths.
  const Solution elastic = problem3(1);
  EXPECT_LT(relative(watched_element(s.history.back(), 62).sigma_r, watched_element(elastic.history.back(), 62).sigma_r),
            2.05e-2);
}

TEST(ReportTableIIIc, ConvergesWithYieldedElements) {
  const Solution s = problem3(3);
  ASSERT_EQ(s.status, RunStatus::converged);
  EXPECT_GT(s.history.back().yielded_elements, 0);
  // Against the report's last printed row (iteration 13): ours goes on to converge at 15, 6393.9 psi.
  // Observed 1.45e-2.
  EXPECT_LT(relative(watched_element(s.history.back(), 62).sigma_r, 6488.0), 1.6e-2);
}

TEST(ReportTableIIIc, StoppedAtThirteenIterationsLikeTheReport) {
  // The report's run stopped after 13 iterations (NOPCEO + 1) with one element, 65, failing the
  // elastic-plastic test. Stopped there, ours fails on element 65 alone, and rows 9-13 match the table.
  const Solution s = problem3(3, 13);
  ASSERT_EQ(s.status, RunStatus::not_converged);
  std::vector<int> unconverged;
  for (const ElementResult& e : s.elements) {
    if (!e.plastic_converged) unconverged.push_back(e.id);
  }
  EXPECT_EQ(unconverged, std::vector<int>{65});
  EXPECT_NE(s.message.find("element 65"), std::string::npos) << s.message;
  const double sigma_r[] = {6747.0, 6705.0, 6629.0, 6554.0, 6488.0};
  // Observed 3.10e-3, 2.06e-4, 6.5e-5, 5.30e-4, 1.21e-3.
  const double tolerance[] = {3.4e-3, 2.4e-4, 7.8e-5, 6.1e-4, 1.35e-3};
  for (int k = 9; k <= 13; ++k) {
    EXPECT_LT(relative(watched_element(s.history[k - 1], 62).sigma_r, sigma_r[k - 9]), tolerance[k - 9]) << "iteration " << k;
    EXPECT_EQ(s.history[k - 1].nonconverged_gaps, 0) << "iteration " << k;
  }
  // "the peak stress (7367 psi) occurs in the region of greatest curvature": observed 2.0e-4 (7365.5).
  double peak = 0.0;
  for (const ElementResult& e : s.elements) peak = std::max(peak, e.effective);
  EXPECT_LT(relative(peak, 7367.0), 2.4e-4);
}

TEST(ReportBeamCheck, ConstantStrainTrianglesCannotBend) {
  // p. 17: the centre deflects to 59 % (Model A) and 87 % (Model B) of the exact 0.009 in.
  const Solution a = solve(example_model("report-beam-model-a.json"));
  const Solution b = solve(example_model("report-beam-model-b.json"));
  // Observed 0.58889 (1.9e-3 below 59 %) and 0.87921 (1.06e-2 above 87 %).
  const double ratio_a = -node(a, 14).u_z / 0.009;
  const double ratio_b = -node(b, 86).u_z / 0.009;
  EXPECT_LT(relative(ratio_a, 0.59), 2.1e-3);
  EXPECT_LT(relative(ratio_b, 0.87), 1.15e-2);
}

}  // namespace
}  // namespace saasgaps
