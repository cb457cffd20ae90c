// The report's sample problems (section III), run from schemas/examples, against its Tables I-III
// and its beam check (p. 17). Each tolerance is the acceptance band; where our numbers differ
// from the report's, the reason is written next to the assertion.
#include <gtest/gtest.h>

#include <algorithm>

#include "analysis.hpp"
#include "support/examples.hpp"

namespace saasgaps {
namespace {

using testing::example_model;

const WatchedGap& watched_gap(const IterationRecord& row, int id) {
  const auto it = std::find_if(row.watch_gaps.begin(), row.watch_gaps.end(), [id](const auto& g) { return g.id == id; });
  EXPECT_NE(it, row.watch_gaps.end()) << "gap " << id << " not watched";
  return *it;
}

const WatchedElement& watched_element(const IterationRecord& row, int id) {
  const auto it =
      std::find_if(row.watch_elements.begin(), row.watch_elements.end(), [id](const auto& e) { return e.id == id; });
  EXPECT_NE(it, row.watch_elements.end()) << "element " << id << " not watched";
  return *it;
}

double relative(double actual, double expected) { return std::abs(actual - expected) / std::abs(expected); }

const NodeResult& node(const Solution& s, int id) {
  return *std::find_if(s.nodes.begin(), s.nodes.end(), [id](const NodeResult& n) { return n.id == id; });
}

const ElementResult& element(const Solution& s, int id) {
  return *std::find_if(s.elements.begin(), s.elements.end(), [id](const ElementResult& e) { return e.id == id; });
}

TEST(ReportTableI, UniformLoadOnAnUnrestrainedBodyIterationByIteration) {
  const Solution s = solve(example_model("report-problem1.json"));
  // The report lists 4 iterations and its third and fourth closures (99.01, 99.00 %) pass the test.
  ASSERT_EQ(s.status, RunStatus::converged);
  ASSERT_EQ(s.iterations, 4);
  const double modulus[] = {100.0, 1111.1, 1010.1, 1010.1};
  const double closure[] = {1000.0, 90.0, 99.01, 99.00};
  for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE("iteration " + std::to_string(k + 1));
    const IterationRecord& row = s.history[k];
    EXPECT_LT(relative(watched_gap(row, 15).modulus, modulus[k]), 0.005);
    EXPECT_LT(relative(watched_gap(row, 15).closure, closure[k]), 0.005);
    // "a compressive stress of 1000 psi exists in the structural elements"
    EXPECT_LT(relative(watched_element(row, 5).sigma_z, -1000.0), 0.005);
  }
  // Every gap under the body carries the load at 99 % closure: uniform contact with the wall.
  for (const GapResult& g : s.gaps) {
    if (g.id >= 11 && g.id <= 19) {
      EXPECT_NEAR(g.closure, 99.0, 0.05);
      EXPECT_NEAR(g.sigma_m, -1000.0, 1.0);
    }
  }
}

TEST(ReportTableII, ThermalGrowthAcrossAGapIterationByIteration) {
  const Solution s = solve(example_model("report-problem2.json"));
  ASSERT_EQ(s.status, RunStatus::converged);
  ASSERT_EQ(s.iterations, 5);
  const double modulus[] = {100.0, 1111.3, 6432.9, 9616.8, 10064.4};
  const double sigma_r[] = {-1000.0, -5790.0, -9520.0, -9964.0, -10006.0};
  const double closure[] = {1000.2, 521.0, 148.0, 103.6, 99.4};
  for (int k = 0; k < 5; ++k) {
    SCOPED_TRACE("iteration " + std::to_string(k + 1));
    const IterationRecord& row = s.history[k];
    EXPECT_LT(relative(watched_gap(row, 20).modulus, modulus[k]), 0.005);
    EXPECT_LT(relative(watched_element(row, 9).sigma_r, sigma_r[k]), 0.005);
    EXPECT_LT(relative(watched_gap(row, 20).closure, closure[k]), 0.005);
  }
  // Closed form: the body grows alpha T L = 0.099 in, the gap takes closure * 0.009 in of it, the rest
  // is squeezed out of the 9 in body: sigma_R = -E (alpha T L - closure delta) / L (about 10006 psi).
  const double closure_20 = s.gaps.back().closure / 100.0;
  ASSERT_EQ(s.gaps.back().id, 20);
  EXPECT_NEAR(element(s, 5).stress[rr], -1.0e6 * (1.0e-5 * 1100.0 * 9.0 - closure_20 * 0.009) / 9.0, 1.0);
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
  EXPECT_LT(relative(first.average_closure, 201.4), 0.02);
  EXPECT_EQ(first.closed_gaps, 14);
  EXPECT_LT(relative(watched_element(first, 62).sigma_r, 20937.0), 0.02);

  ASSERT_EQ(s.status, RunStatus::converged);
  const IterationRecord& last = s.history.back();
  EXPECT_GE(last.closed_gaps, 3);
  EXPECT_LE(last.closed_gaps, 5);
  EXPECT_LT(relative(watched_element(last, 62).sigma_r, 6913.0), 0.05);
  EXPECT_EQ(last.nonconverged_gaps, 0);
  // "The peak bending stress is 7700 psi and occurs ... near the point of separation" (bottom row).
  double peak = 0.0;
  for (const ElementResult& e : s.elements) peak = std::max(peak, e.effective);
  EXPECT_LT(relative(peak, 7700.0), 0.02);
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
  EXPECT_LT(relative(watched_element(s.history.back(), 62).sigma_r, 7160.0), 0.05);
  const Solution elastic = problem3(1);
  EXPECT_LT(relative(watched_element(s.history.back(), 62).sigma_r, watched_element(elastic.history.back(), 62).sigma_r),
            0.05);
}

TEST(ReportTableIIIc, ConvergesWithYieldedElements) {
  const Solution s = problem3(3);
  ASSERT_EQ(s.status, RunStatus::converged);
  EXPECT_GT(s.history.back().yielded_elements, 0);
  EXPECT_LT(relative(watched_element(s.history.back(), 62).sigma_r, 6488.0), 0.08);
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
  for (int k = 9; k <= 13; ++k) {
    EXPECT_LT(relative(watched_element(s.history[k - 1], 62).sigma_r, sigma_r[k - 9]), 0.005) << "iteration " << k;
    EXPECT_EQ(s.history[k - 1].nonconverged_gaps, 0) << "iteration " << k;
  }
  // "the peak stress (7367 psi) occurs in the region of greatest curvature"
  double peak = 0.0;
  for (const ElementResult& e : s.elements) peak = std::max(peak, e.effective);
  EXPECT_LT(relative(peak, 7367.0), 0.01);
}

TEST(ReportBeamCheck, ConstantStrainTrianglesCannotBend) {
  // p. 17: the centre deflects to 59 % (Model A) and 87 % (Model B) of the exact 0.009 in.
  const Solution a = solve(example_model("report-beam-model-a.json"));
  const Solution b = solve(example_model("report-beam-model-b.json"));
  const double ratio_a = -node(a, 14).u_z / 0.009;
  const double ratio_b = -node(b, 86).u_z / 0.009;
  EXPECT_GE(ratio_a, 0.58);
  EXPECT_LE(ratio_a, 0.60);
  EXPECT_GE(ratio_b, 0.86);
  EXPECT_LE(ratio_b, 0.89);
}

}  // namespace
}  // namespace saasgaps
