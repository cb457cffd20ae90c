// The conduction kernel of tri6, quad8, quad9 and quad4i on its own: constants in the null space of
// K, the capacity and source weights summing to the volume (plane t A; axisymmetric 2 pi r_c A), the
// film and flux of a straight 3-node edge against their closed forms h t L / 30 [4 2 -1; 2 16 2;
// -1 2 4] and q t L (1, 4, 1) / 6, and bilinear quad4i against the SAAS quad on a rectangle's
// constant-gradient field.
#include "solver/thermal/isoparametric_conduction.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace saasgaps {
namespace {

/// A parallelogram (1, 0), (3, 0.5), (3.5, 2), (1.5, 1.5) of area 2.75 and centroid r = 2.25, with
/// the nodes of each family on it (mid-sides at the middle of the edges, a centre at the centroid).
IsoConductionData parallelogram(ElementType type, AnalysisType analysis) {
  const std::array<Vec2, 4> c{Vec2(1.0, 0.0), Vec2(3.0, 0.5), Vec2(3.5, 2.0), Vec2(1.5, 1.5)};
  IsoConductionData d;
  d.type = type;
  d.analysis = analysis;
  d.thickness = 0.3;
  d.k = {2.0, 0.5, 20.0};
  if (type == ElementType::tri6) {
    d.node_count = 6;
    d.x = {c[0], c[1], c[2], 0.5 * (c[0] + c[1]), 0.5 * (c[1] + c[2]), 0.5 * (c[2] + c[0])};
    return d;
  }
  d.node_count = family(type).node_count;
  for (int a = 0; a < 4; ++a) d.x[static_cast<std::size_t>(a)] = c[static_cast<std::size_t>(a)];
  for (int a = 0; a < 4 && d.node_count > 4; ++a) d.x[static_cast<std::size_t>(4 + a)] = 0.5 * (c[static_cast<std::size_t>(a)] + c[static_cast<std::size_t>((a + 1) % 4)]);
  if (d.node_count == 9) d.x[8] = 0.25 * (c[0] + c[1] + c[2] + c[3]);
  return d;
}

TEST(IsoparametricConduction, ConstantsConductNothingAndCapacityAndSourceSumToTheVolume) {
  for (const ElementType type : {ElementType::tri6, ElementType::quad8, ElementType::quad9, ElementType::quad4i}) {
    for (const AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::axisymmetric}) {
      const IsoConductionData d = parallelogram(type, analysis);
      const IsoConductionParts p = isoparametric_conduction_parts(d);
      const bool triangle = type == ElementType::tri6;
      // Triangle (1,0), (3,0.5), (3.5,2): area 1.375, centroid r = 2.5; the parallelogram: 2.75, 2.25.
      const double area = triangle ? 1.375 : 2.75;
      const double r_c = triangle ? 2.5 : 2.25;
      const double volume = analysis == AnalysisType::axisymmetric ? 2.0 * std::numbers::pi * r_c * area : 0.3 * area;
      EXPECT_LT((p.K * ConductionVector::Ones(d.node_count)).norm(), 1e-13 * p.K.norm()) << d.node_count;
      EXPECT_NEAR(p.C.sum(), volume, 1e-13 * volume) << d.node_count;
      EXPECT_NEAR(p.source.sum(), volume, 1e-13 * volume) << d.node_count;
      EXPECT_LT((p.C - p.C.transpose()).norm(), 1e-15 * p.C.norm());
      EXPECT_LT((p.K - p.K.transpose()).norm(), 1e-14 * p.K.norm());
    }
  }
}

TEST(IsoparametricConduction, AStraightThreeNodeEdgeHasTheClosedFormFilmAndFlux) {
  const std::array<Vec2, max_edge_nodes> edge{Vec2(1.0, 1.0), Vec2(2.5, 3.0), Vec2(4.0, 5.0)};  // L = 5
  const double h = 3.0, Ta = 40.0, t = 0.2;
  const CurvedEdgeBlock film = curved_film_block(edge, 3, AnalysisType::plane_stress, t, h, Ta);
  Eigen::Matrix3d expected;
  expected << 4, 2, -1, 2, 16, 2, -1, 2, 4;
  expected *= h * t * 5.0 / 30.0;
  EXPECT_LT((film.K - expected).norm(), 1e-14 * expected.norm());
  const auto w = edge_flux_weights(edge, 3, AnalysisType::plane_stress, t);
  for (int a = 0; a < 3; ++a) {
    const double share = (a == 1 ? 4.0 : 1.0) / 6.0 * t * 5.0;
    EXPECT_NEAR(w[static_cast<std::size_t>(a)], share, 1e-15);
    EXPECT_NEAR(film.f[a], h * Ta * share, 1e-12);
  }
  // Axisymmetric: sum N_a dS = 2 pi integral N_a r ds; in all 2 pi r_mid L.
  const auto ring = edge_flux_weights(edge, 3, AnalysisType::axisymmetric, t);
  EXPECT_NEAR(ring[0] + ring[1] + ring[2], 2.0 * std::numbers::pi * 2.5 * 5.0, 1e-12);
}

TEST(IsoparametricConduction, Quad4iConductsAsTheBilinearQuadrilateral) {
  // A rectangle a x b = 2 x 1 (plane, t = 1, k = 1), corners (0,0), (a,0), (a,b), (0,b): the bilinear
  // element's K = b / (6 a) Mr + a / (6 b) Mz, Mr and Mz the patterns below.
  IsoConductionData d;
  d.type = ElementType::quad4i;
  d.node_count = 4;
  d.x = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1)};
  d.k = {1.0, 1.0, 0.0};
  const IsoConductionParts p = isoparametric_conduction_parts(d);
  Eigen::Matrix4d along_r, along_z;  // integral dNa/dr dNb/dr dA and the same along z
  along_r << 2, -2, -1, 1, -2, 2, 1, -1, -1, 1, 2, -2, 1, -1, -2, 2;
  along_z << 2, 1, -1, -2, 1, 2, -2, -1, -1, -2, 2, 1, -2, -1, 1, 2;
  const Eigen::Matrix4d exact = (1.0 / (6.0 * 2.0)) * along_r + (2.0 / 6.0) * along_z;
  EXPECT_LT((p.K - exact).norm(), 1e-14 * exact.norm());
}

}  // namespace
}  // namespace saasgaps
