// Node pairs of the exact contact mode: quadrilateral faces, shared pairs, node-to-edge pairs of
// 3-node gaps, and an exact solve through a strip of triangle gaps.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/analysis/analysis.hpp"
#include "solver/gaps/contact_pairs.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

/// A unit square body (plane stress, E = 1e6) 0.01 above a fixed wall, joined to it by two
/// triangle gaps: (wall 0, wall 1, body 0) and (wall 1, body 1, body 0).
Model block_on_triangles() {
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.materials = {testing::isotropic_material(1, 1.0e6, 0.3)};
  m.nodes = {{1, 0.0, -0.01}, {2, 1.0, -0.01}, {3, 0.0, 0.0}, {4, 1.0, 0.0}, {5, 1.0, 1.0}, {6, 0.0, 1.0}};
  Element body;
  body.id = 1;
  body.nodes = {2, 3, 4, 5};
  m.elements = {body};
  m.gaps.emplace();
  m.gaps->method = GapMethod::exact;
  m.gaps->tensile_schedule = {1.0};
  m.gaps->elements.push_back({11, {0, 1, 2, -1}, 3, 90.0});
  m.gaps->elements.push_back({12, {1, 3, 2, -1}, 3, 90.0});
  testing::fill_temperatures(m, 0.0);
  testing::constrain(m, 0, 0.0, 0.0);
  testing::constrain(m, 1, 0.0, 0.0);
  testing::constrain(m, 2, 0.0, std::nullopt);
  m.loads.pressures.push_back({0, 4, 5, 1000.0, 0.0});
  return m;
}

TEST(ContactPairs, AdjacentQuadsShareTheirMiddlePairWithTheMeanNormal) {
  Model m;
  m.analysis = AnalysisType::plane_strain;
  // Wall nodes 0-2 on z = 0, body nodes 3-5 on z = 0.1; the two gaps' M axes lean +-10 degrees.
  m.nodes = {{1, 0, 0}, {2, 1, 0}, {3, 2, 0}, {4, 0, 0.1}, {5, 1, 0.1}, {6, 2, 0.1}};
  m.gaps.emplace();
  m.gaps->tensile_schedule = {1.0};
  m.gaps->elements.push_back({7, {0, 1, 4, 3}, 4, 80.0});
  m.gaps->elements.push_back({8, {1, 2, 5, 4}, 4, 100.0});
  const ContactPairs p = contact_pairs(m);
  ASSERT_EQ(p.pairs.size(), 3U);
  const ContactPair& shared = p.pairs[p.of_gap[0][1].pair];
  EXPECT_EQ(p.of_gap[1][0].pair, p.of_gap[0][1].pair);
  EXPECT_NEAR(shared.normal.x(), 0.0, 1e-15);
  EXPECT_NEAR(shared.normal.y(), 1.0, 1e-15);
  EXPECT_NEAR(shared.g0, 0.1, 1e-15);
  EXPECT_EQ(shared.node[0], 1);  // side a: the wall
  EXPECT_EQ(shared.node[1], 4);
  // Face areas: half of each adjacent face (length 1, thickness 1) from both gaps.
  EXPECT_NEAR(shared.area, 1.0, 1e-15);
  EXPECT_NEAR(p.pairs[p.of_gap[0][0].pair].area, 0.5, 1e-15);
  // The outer pairs keep their gap's leaning normal: g0 = 0.1 sin(80 degrees).
  EXPECT_NEAR(p.pairs[p.of_gap[0][0].pair].g0, 0.1 * std::sin(80.0 * std::numbers::pi / 180.0), 1e-15);
}

TEST(ContactPairs, ATriangleGapPairsItsLoneNodeWithThePointOfTheEdgeFacingIt) {
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.nodes = {{1, 0, 0}, {2, 2, 0}, {3, 0.5, 0.05}};
  m.gaps.emplace();
  m.gaps->tensile_schedule = {1.0};
  m.gaps->elements.push_back({9, {0, 1, 2, -1}, 3, 90.0});
  const ContactPairs p = contact_pairs(m);
  ASSERT_EQ(p.pairs.size(), 1U);
  const ContactPair& pair = p.pairs[0];
  ASSERT_EQ(pair.node.size(), 3U);
  EXPECT_EQ(pair.node[0], 2);  // the lone node, side b (above)
  EXPECT_DOUBLE_EQ(pair.weight[0], 1.0);
  EXPECT_DOUBLE_EQ(pair.weight[1], -0.75);  // the edge point at s = 0.25
  EXPECT_DOUBLE_EQ(pair.weight[2], -0.25);
  EXPECT_NEAR(pair.g0, 0.05, 1e-15);
  EXPECT_NEAR(pair.area, 1.0, 1e-15);  // half the edge (length 2, thickness 1)
}

TEST(ContactPairs, ABlockOnAStripOfTriangleGapsCarriesAUniformPressureExactly) {
  const Model m = block_on_triangles();
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  for (const GapResult& g : s.gaps) {
    EXPECT_EQ(g.state, GapState::closed) << g.id;
    EXPECT_NEAR(g.sigma_m, -1000.0, 1e-6) << g.id;
    EXPECT_NEAR(g.closure, 100.0, 1e-9) << g.id;
  }
  EXPECT_NEAR(s.elements[0].stress[zz], -1000.0, 1e-6);
  EXPECT_NEAR(s.nodes[2].u_z, -0.01, 1e-15);  // body node 3 rests on the wall
}

}  // namespace
}  // namespace saasgaps
