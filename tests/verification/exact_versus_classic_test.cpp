// docs/contact.md's "Table IIIa in exact mode" (the report's Problem 3, case 1, solved by the classic
// iteration and by the exact contact mode) and docs/contact.md's statements about the classic-mode
// warning, each figure pinned to the digits quoted (support/quoted_figure.hpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "solver/analysis/analysis.hpp"
#include "support/by_id.hpp"
#include "support/examples.hpp"
#include "support/quoted_figure.hpp"

namespace saasgaps {
namespace {

using testing::by_id;
using testing::example_model;
using testing::rounds_to;

/// The element with the largest sigma_R.
const ElementResult& largest_sigma_r(const Solution& s) {
  return *std::max_element(s.elements.begin(), s.elements.end(),
                           [](const ElementResult& a, const ElementResult& b) { return a.stress[rr] < b.stress[rr]; });
}

TEST(ExactVersusClassic, Problem3Case1Classic) {
  const Solution s = solve(example_model("report-problem3-case1.json"));
  ASSERT_EQ(s.status, RunStatus::converged);
  EXPECT_EQ(s.iterations, 10);
  // "81-84 at 100.3-104.1 %, 85-86 at 97.7 %, 94.4 % carrying 94 and 65 psi"
  EXPECT_TRUE(rounds_to(by_id(s.gaps, 84).closure, "100.3"));
  EXPECT_TRUE(rounds_to(by_id(s.gaps, 81).closure, "104.1"));
  for (int id = 81; id <= 84; ++id) EXPECT_GT(by_id(s.gaps, id).closure, 100.0) << "gap " << id;
  EXPECT_TRUE(rounds_to(by_id(s.gaps, 85).closure, "97.7"));
  EXPECT_TRUE(rounds_to(by_id(s.gaps, 86).closure, "94.4"));
  EXPECT_TRUE(rounds_to(-by_id(s.gaps, 85).sigma_m, "94"));
  EXPECT_TRUE(rounds_to(-by_id(s.gaps, 86).sigma_m, "65"));
  // "0.00939 in (4 % past the foundation)"
  const double centre = -by_id(s.nodes, 86).u_z;
  EXPECT_TRUE(rounds_to(centre, "0.00939"));
  EXPECT_TRUE(rounds_to(100.0 * (centre / 0.009 - 1.0), "4"));
  EXPECT_TRUE(rounds_to(by_id(s.elements, 62).stress[rr], "6977"));
  // "7731 psi (element 68)"
  EXPECT_TRUE(rounds_to(largest_sigma_r(s).stress[rr], "7731"));
  EXPECT_EQ(largest_sigma_r(s).id, 68);
}

TEST(ExactVersusClassic, Problem3Case1Exact) {
  const Solution s = solve(example_model("report-problem3-case1-exact.json"));
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  // "1 (2 active sets)"; "the centre only: node 86 (gap 81's pair at R = 0)".
  EXPECT_EQ(s.iterations, 1);
  EXPECT_EQ(s.history.back().active_set_iterations, 2);
  EXPECT_EQ(s.history.back().contact_pairs, 1);
  for (const GapResult& g : s.gaps) EXPECT_EQ(g.state, g.id == 81 ? GapState::closed : GapState::open) << "gap " << g.id;
  // "0.00900 in (touching)"
  EXPECT_TRUE(rounds_to(-by_id(s.nodes, 86).u_z, "0.00900"));
  // "5161 psi"; "7935 psi (element 68)".
  const double centre = by_id(s.elements, 62).stress[rr];
  EXPECT_TRUE(rounds_to(centre, "5161"));
  EXPECT_TRUE(rounds_to(largest_sigma_r(s).stress[rr], "7935"));
  EXPECT_EQ(largest_sigma_r(s).id, 68);
  // "the centre stress drops to 5161 psi (the classic value is 35 % above it)"
  const double classic = by_id(solve(example_model("report-problem3-case1.json")).elements, 62).stress[rr];
  EXPECT_TRUE(rounds_to(100.0 * (classic / centre - 1.0), "35"));
}

TEST(ExactVersusClassic, Problem3Case3ExactTakesFiveSecantIterationsOneActiveSetEachAfterTheFirst) {
  const Solution s = solve(example_model("report-problem3-case3-exact.json"));
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  ASSERT_EQ(s.iterations, 5);
  for (std::size_t k = 1; k < s.history.size(); ++k) EXPECT_EQ(s.history[k].active_set_iterations, 1) << "iteration " << k + 1;
}

TEST(ClassicWarning, TableIIIaTriggersItTablesIAndIIDoNot) {
  // docs/contact.md: "Table IIIa triggers it (gap 86 at 94.4 % carrying 65 psi); Tables I and II do not."
  const Solution beam = solve(example_model("report-problem3-case1.json"));
  EXPECT_NE(beam.message.find("warning"), std::string::npos) << beam.message;
  EXPECT_NE(beam.message.find("gap 86: closure 94.4 %"), std::string::npos) << beam.message;
  for (const char* name : {"report-problem1.json", "report-problem2.json"}) {
    const Solution s = solve(example_model(name));
    EXPECT_EQ(s.message.find("warning"), std::string::npos) << name << ": " << s.message;
  }
}

}  // namespace
}  // namespace saasgaps
