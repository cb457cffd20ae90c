// Contact surfaces (model.contact, mortar rows) against exact gap pairs (gaps.method "exact", gap
// elements on the same node pairs) on MATCHING meshes: the same contact, two discretisations.
//
// What differs (docs/contact.md, "Surfaces and exact gap pairs on matching meshes"):
// - A gap pair is lumped: node a to node b, its gap n_i . (u_b - u_a) along one normal, its force
//   lambda_i spread over the gap elements' mean face area. A mortar row is an integral over side A:
//   g_j = int_A psi_j n(xi) . (x_B - x_A) dA, with the normal field n(xi) turning along each segment
//   and each side's chords bent to its smooth curve; its pressure is force per unit area of A's face.
// - On a straight interface under a uniform pressure the two coincide: n is constant, the dual
//   basis reproduces the lumped rows exactly (M_jk = D_j delta_jk on matching segments), and both
//   areas are A's face. So pressures and displacements agree to round-off.
// - On a curved interface the rows differ by the turn of n(xi) and the chords' bend within a
//   segment, of order (segment angle)^2 inside the interface: the displacements' difference falls
//   about fourfold per halving, the worst pressure's about twofold (at the open chains' end nodes,
//   whose normal is their one segment's, tilted by half its angle from the gap's). The gap's
//   face area is the mean of its two faces; on a ring fit of clearance delta at radius b1 the
//   matched chords make it (b1 + a2) / (2 b1) times A's, which converts one pressure to the other
//   before they are compared.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "solver/analysis/analysis.hpp"
#include "support/ring_fit.hpp"
#include "support/stacked_blocks.hpp"

namespace saasgaps {
namespace {

constexpr double pressure = 250.0;
constexpr int layers = 3;

/// Largest difference of two solutions' displacements, relative to the largest displacement.
double displacement_difference(const Solution& a, const Solution& b) {
  double difference = 0.0, scale = 0.0;
  for (std::size_t n = 0; n < a.nodes.size(); ++n) {
    difference = std::max({difference, std::abs(a.nodes[n].u_r - b.nodes[n].u_r), std::abs(a.nodes[n].u_z - b.nodes[n].u_z)});
    scale = std::max({scale, std::abs(b.nodes[n].u_r), std::abs(b.nodes[n].u_z)});
  }
  return difference / scale;
}

/// The surface pressure at each gap element's side-A face (nodes 2 and 3 of the gap, on A), the mean
/// of its two points' (found by position), against the gap's own pressure -sigma_m times
/// `area_ratio` (its mean face area over A's): the largest difference relative to `scale`.
double pressure_difference(const Model& gaps_model, const Solution& with_gaps, const Solution& with_surfaces,
                           double area_ratio, double scale) {
  const std::vector<ContactPointResult>& points = with_surfaces.contact.at(0).points;
  const auto pressure_at = [&](int node) {
    const Node& x = gaps_model.nodes[static_cast<std::size_t>(node)];
    const auto nearest = std::min_element(points.begin(), points.end(), [&](const auto& p, const auto& q) {
      return std::hypot(p.r - x.r, p.z - x.z) < std::hypot(q.r - x.r, q.z - x.z);
    });
    EXPECT_LT(std::hypot(nearest->r - x.r, nearest->z - x.z), 1e-12) << "node " << x.id << " is no point of A";
    EXPECT_EQ(nearest->state, ContactPointState::stick) << "node " << x.id;
    return nearest->pressure;
  };
  double worst = 0.0;
  for (std::size_t g = 0; g < with_gaps.gaps.size(); ++g) {
    const GapElement& gap = gaps_model.gaps->elements[g];
    EXPECT_EQ(with_gaps.gaps[g].state, GapState::closed) << "gap " << gap.id;
    const double surface = 0.5 * (pressure_at(gap.nodes[2]) + pressure_at(gap.nodes[3]));
    worst = std::max(worst, std::abs(surface + with_gaps.gaps[g].sigma_m * area_ratio) / scale);
  }
  return worst;
}

/// The gap elements' faces as contact surfaces: gap (a_k, a_k+1, b_k+1, b_k) gives edge [b_k, b_k+1]
/// to side A and [a_k, a_k+1] to side B; the gaps are removed.
Model with_surfaces_instead_of_gaps(Model m) {
  ContactSettings& contact = m.contact.emplace();
  contact.surfaces = {{"A", {}}, {"B", {}}};
  for (const GapElement& g : m.gaps->elements) {
    contact.surfaces[0].edges.push_back({g.nodes[3], g.nodes[2]});
    contact.surfaces[1].edges.push_back({g.nodes[0], g.nodes[1]});
  }
  contact.pairs.emplace_back().surfaces = {0, 1};
  m.gaps.reset();
  return m;
}

/// Two blocks 0.001 apart with matching faces (6 graded segments each), the lower one's bottom held
/// in z, one node of each held in r, a uniform pressure on top, and exact gap elements joining the
/// faces node to node (M along z). Floor modulus 1e-6 (against E 1e6 and 3e6): its springs' shear
/// stiffness, which surfaces lack, resists the blocks' unequal Poisson expansion (a slip of about
/// 1e-4 across the 0.001 gap) by a shear stress of order 1e-7, 1e-9 of the pressure; a smaller floor
/// would leave the upper block's pivot near SparseCholesky's singular ratio before contact holds it.
Model stacked_with_gap_pairs(AnalysisType analysis) {
  testing::StackedBlocks b =
      testing::stacked_blocks(analysis, 1.0, 2.0, 1.0, 0.001, testing::BlockFace{6, 1.3}, testing::BlockFace{6, 1.3}, layers);
  Model& m = b.model;
  std::vector<int> top, bottom;
  for (int i = 0; i <= b.lower.ni; ++i) {
    top.push_back(b.lower.at(i, b.lower.nj));
    bottom.push_back(b.upper.at(i, 0));
    testing::constrain(m, b.lower.at(i, 0), std::nullopt, 0.0);
  }
  testing::add_gap_row(m, top, bottom, [](int) { return 90.0; });  // A = the upper block's bottom
  m.gaps->method = GapMethod::exact;
  m.gaps->initial_modulus = 1.0e-6;
  m.gaps->tensile_schedule = {1.0e-6};
  testing::add_traction(m, testing::row_edges(b.upper, layers), Vec2(0.0, -pressure));
  if (analysis != AnalysisType::axisymmetric) {
    testing::constrain(m, b.lower.at(0, 0), 0.0, std::nullopt);
    testing::constrain(m, b.upper.at(0, layers), 0.0, std::nullopt);
  }
  return std::move(b.model);
}

TEST(SurfacesVersusGapPairs, AStraightInterfaceUnderUniformPressureAgreesToRoundOff) {
  for (const AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::plane_strain, AnalysisType::axisymmetric}) {
    SCOPED_TRACE(static_cast<int>(analysis));
    const Model gaps = stacked_with_gap_pairs(analysis);
    const Model surfaces = with_surfaces_instead_of_gaps(gaps);
    const Solution by_gaps = solve(gaps), by_surfaces = solve(surfaces);
    ASSERT_EQ(by_gaps.status, RunStatus::converged) << by_gaps.message;
    ASSERT_EQ(by_surfaces.status, RunStatus::converged) << by_surfaces.message;
    // Both faces are A's (straight, matched): no area conversion.
    const double pressures = pressure_difference(gaps, by_gaps, by_surfaces, 1.0, pressure);
    const double displacements = displacement_difference(by_surfaces, by_gaps);
    std::printf("straight interface: pressures differ by %.2g of p, displacements by %.2g\n", pressures, displacements);
    EXPECT_LT(pressures, 1e-8);
    EXPECT_LT(displacements, 1e-8);
  }
}

/// Surfaces against exact gap pairs on the quarter ring fit (support/ring_fit.hpp: a heated ring in
/// a cold one across a radial clearance, plane strain), `hoop` matched segments round.
struct RingDifference {
  double pressure = 0.0;      ///< relative to the mean gap pressure
  double displacement = 0.0;  ///< relative to the largest displacement
};

RingDifference ring_difference(int radial, int hoop) {
  Model gaps = testing::quarter_ring_fit(AnalysisType::plane_strain, radial, hoop);
  testing::use_exact_contact(gaps);
  const Model surfaces = with_surfaces_instead_of_gaps(gaps);
  const Solution by_gaps = solve(gaps), by_surfaces = solve(surfaces);
  EXPECT_EQ(by_gaps.status, RunStatus::converged) << by_gaps.message;
  EXPECT_EQ(by_surfaces.status, RunStatus::converged) << by_surfaces.message;
  using F = testing::RingFit;
  // Gap quad (outer_k, outer_k+1, inner_k+1, inner_k): A is the inner ring's face at b1; the gap's
  // area is the mean of the faces at b1 and a2.
  const double area_ratio = (F::b1 + F::a2) / (2.0 * F::b1);
  double mean = 0.0;
  for (const GapResult& g : by_gaps.gaps) mean -= g.sigma_m / static_cast<double>(by_gaps.gaps.size());
  return {pressure_difference(gaps, by_gaps, by_surfaces, area_ratio, mean), displacement_difference(by_surfaces, by_gaps)};
}

TEST(SurfacesVersusGapPairs, ACurvedFitAgreesToTheDiscretisationDifferenceFallingWithRefinement) {
  const RingDifference coarse = ring_difference(2, 12), medium = ring_difference(4, 24), fine = ring_difference(8, 48);
  std::printf("curved fit, surfaces against gap pairs: pressure %.3g / %.3g / %.3g %%, displacement %.3g / %.3g / %.3g %%\n",
              100 * coarse.pressure, 100 * medium.pressure, 100 * fine.pressure, 100 * coarse.displacement,
              100 * medium.displacement, 100 * fine.displacement);
  EXPECT_LT(coarse.pressure, 0.01);
  EXPECT_LT(coarse.displacement, 0.01);
  EXPECT_LT(fine.pressure, medium.pressure);
  EXPECT_LT(medium.pressure, coarse.pressure);
  EXPECT_LT(fine.displacement, medium.displacement);
  EXPECT_LT(medium.displacement, coarse.displacement);
}

}  // namespace
}  // namespace saasgaps
