// The analysis loop as a whole: mechanisms are reported with their nodes, free thermal expansion is
// stress free, and a linear model takes one iteration.
#include "solver/analysis/analysis.hpp"

#include <gtest/gtest.h>

#include "solver/base/errors.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

Model block(AnalysisType analysis) {
  Model m;
  m.analysis = analysis;
  m.materials = {testing::isotropic_material(1, 10.0e6, 0.3, 1.2e-5)};
  testing::add_grid(m, 3, 2, [](double s, double t) { return Vec2(1.0 + 2.0 * s, t); }, 0);
  testing::fill_temperatures(m, 70.0);
  m.reference_temperature = 70.0;
  return m;
}

TEST(Analysis, AnUnrestrainedBodyIsReportedWithItsNodes) {
  Model m = block(AnalysisType::plane_stress);
  testing::constrain(m, 0, 0.0, std::nullopt);  // one component: the body still translates in z and rotates
  m.loads.nodal_forces.push_back({5, 0.0, -100.0});
  try {
    solve(m);
    FAIL() << "a free body was solved";
  } catch (const SingularModelError& e) {
    // Two mechanisms (translation along z, rotation): one degree of freedom named for each.
    EXPECT_EQ(e.dofs().size(), 2U) << e.what();
    EXPECT_NE(std::string(e.what()).find("not restrained"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("node "), std::string::npos) << e.what();
  }
}

TEST(Analysis, AnUnconnectedNodeIsReportedByItsId) {
  Model m = block(AnalysisType::plane_strain);
  testing::constrain(m, 0, 0.0, 0.0);
  testing::constrain(m, 3, std::nullopt, 0.0);
  m.nodes.push_back({777, 9.0, 9.0});  // in no element
  testing::fill_temperatures(m, 70.0);
  try {
    solve(m);
    FAIL() << "an unconnected node was solved";
  } catch (const SingularModelError& e) {
    ASSERT_EQ(e.dofs().size(), 2U);
    EXPECT_EQ(e.dofs()[0].node_id, 777);
    EXPECT_EQ(e.dofs()[0].direction, 'r');
    EXPECT_EQ(e.dofs()[1].direction, 'z');
  }
}

TEST(Analysis, FreeUniformThermalExpansionIsStressFree) {
  for (AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::plane_strain, AnalysisType::axisymmetric}) {
    Model m = block(analysis);
    // Held only against rigid motion: node (0,0) in z (and r in plane analyses), node (3,0) in z.
    testing::constrain(m, 0, analysis == AnalysisType::axisymmetric ? std::nullopt : std::optional(0.0), 0.0);
    testing::constrain(m, 3, std::nullopt, 0.0);
    std::fill(m.loads.node_temperature.begin(), m.loads.node_temperature.end(), 570.0);
    const Solution s = solve(m);
    ASSERT_EQ(s.status, RunStatus::converged);
    EXPECT_EQ(s.iterations, 1);
    EXPECT_EQ(s.message, "converged in 1 iteration");  // a count of one is singular
    const double scale = 10.0e6 * 1.2e-5 * 500.0;  // E alpha dT: the stress if fully restrained
    for (const ElementResult& e : s.elements) {
      // Plane strain holds the out-of-plane strain at zero: sigma_th = -E alpha dT there, nothing else.
      Vec4 expected = Vec4::Zero();
      if (analysis == AnalysisType::plane_strain) expected[th] = -scale;
      EXPECT_LT((e.stress - expected).norm(), 1e-9 * scale) << "element " << e.id;
    }
    // The free growth itself: u_r = alpha dT r (times 1 + nu in plane strain) at the right edge.
    const double growth = analysis == AnalysisType::plane_strain ? 1.3 : 1.0;
    const double u_expected = growth * 1.2e-5 * 500.0 * (analysis == AnalysisType::axisymmetric ? 3.0 : 2.0);
    EXPECT_NEAR(s.nodes[3].u_r - (analysis == AnalysisType::axisymmetric ? 0.0 : s.nodes[0].u_r), u_expected, 1e-12);
  }
}

}  // namespace
}  // namespace saasgaps
