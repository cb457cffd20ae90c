// Stresses at boundaries with known tractions (solver/recovery/boundary_stresses): which nodes take
// them, and that they are exact where the solution is (a uniform stress, a free thermal expansion).
// A 4 x 4 grid on [0, 4] x [0, 4] with rollers along its bottom (z = 0) and left (r = 0) sides.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <set>
#include <utility>

#include "solver/analysis/analysis.hpp"
#include "solver/recovery/boundary_stresses.hpp"
#include "solver/recovery/patch_recovery.hpp"
#include "solver/recovery/sampling_points.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

constexpr int cells = 4;
constexpr double E = 200.0e3, nu = 0.3, p = 50.0;

struct Block {
  Model model;
  testing::QuadraticGrid grid;
  [[nodiscard]] int at(int i, int j) const { return grid.corner(i, j); }
  /// The element of cell (i, j) that holds its top edge (tri6: the second triangle, (0, 2, 3)).
  [[nodiscard]] int top_element(int i, int j) const {
    const auto& c = grid.cells[static_cast<std::size_t>(i + cells * j)];
    return c[1] >= 0 ? c[1] : c[0];
  }
};

/// The grid held by rollers on its bottom and left sides and pressed by p on its top.
Block pressed(AnalysisType analysis, ElementType type, double alpha = 0.0) {
  Block b;
  b.model.analysis = analysis;
  b.model.materials.push_back(testing::isotropic_material(1, E, nu, alpha));
  b.grid = testing::add_quadratic_grid(b.model, type, cells, cells, [](double s, double t) { return Vec2(cells * s, cells * t); }, 0);
  // Every node of the sides, mid-side nodes included.
  for (int I = 1; I <= 2 * cells; ++I) {
    if (b.grid.at(I, 0) >= 0) testing::constrain(b.model, b.grid.at(I, 0), std::nullopt, 0.0);
  }
  for (int J = 1; J <= 2 * cells; ++J) {
    if (b.grid.at(0, J) >= 0) testing::constrain(b.model, b.grid.at(0, J), 0.0, std::nullopt);
  }
  testing::constrain(b.model, b.at(0, 0), 0.0, 0.0);
  for (int i = 0; i < cells; ++i) {
    b.model.loads.pressures.push_back({b.top_element(i, cells - 1), b.at(i + 1, cells), b.at(i, cells), p, 0.0});
  }
  testing::fill_temperatures(b.model, 0.0);
  return b;
}

/// The corners (i, j) whose side the traction boundary takes.
std::set<std::pair<int, int>> chosen_corners(const Block& b) {
  const SymmetryLines lines = stress_symmetry_lines(b.model);
  std::vector<ElementSamples> samples(b.model.elements.size());
  const RecoveredField field = recover_field(b.model, samples, &lines);
  const std::vector<bool> chosen = traction_boundary_sides(b.model, field, lines);
  std::set<std::pair<int, int>> out;
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      const auto n = static_cast<std::size_t>(b.at(i, j));
      if (chosen[field.first[n]]) out.insert({i, j});
    }
  }
  return out;
}

TEST(BoundaryStresses, SmoothEdgesWithKnownTractionsAndTheirMirrorImages) {
  Block b = pressed(AnalysisType::plane_stress, ElementType::saas);
  // A force at (4, 3): the traction of the right side's top two edges is not known.
  b.model.loads.nodal_forces.push_back({b.at(cells, 3), 1.0, 0.0});
  const std::set<std::pair<int, int>> expected{
      {4, 0},  // on the line z = 0, the free right side perpendicular to it: smooth in the mirrored body
      {4, 1},  // between two free edges
      {1, 4}, {2, 4}, {3, 4},  // between two pressed edges
      {0, 4},  // on the line r = 0, the pressed top perpendicular to it
  };
  // Not: (4, 2) and (4, 3) (an edge of unknown traction), (4, 4) (a right-angled corner), the nodes
  // along the lines (their only boundary edges lie along them), (0, 0) (pinned), interior nodes.
  EXPECT_EQ(chosen_corners(b), expected);

  // Unequal pressures on the two edges at (2, 4): no single traction there.
  b.model.loads.pressures[2].normal = 2.0 * p;
  auto fewer = expected;
  fewer.erase({2, 4});
  fewer.erase({3, 4});
  EXPECT_EQ(chosen_corners(b), fewer);

  // A contact surface along the top: its tractions are the contact's, unknown here.
  b.model.contact.emplace();
  b.model.contact->surfaces.push_back({"top", b.grid.row_edges(cells)});
  EXPECT_EQ(chosen_corners(b), (std::set<std::pair<int, int>>{{4, 0}, {4, 1}}));
}

TEST(BoundaryStresses, ACornerBeyondTwentyDegreesKeepsItsPatchValue) {
  // The right side bent outwards at (4, 2) by 15 degrees on each edge (30 in all) is a corner; by
  // 8 degrees (16 in all) it is a smooth boundary drawn with straight edges.
  for (const auto& [degrees, smooth] : {std::pair{15.0, false}, std::pair{8.0, true}}) {
    Block b = pressed(AnalysisType::plane_stress, ElementType::saas);
    const double shift = std::tan(degrees * std::numbers::pi / 180.0);  // the edges are 1 long
    b.model.nodes[static_cast<std::size_t>(b.at(cells, 2))].r += shift;
    EXPECT_EQ(chosen_corners(b).contains({4, 2}), smooth) << degrees;
  }
}

/// Held against rigid motion only, no load, a temperature linear in z (and in r in plane stress,
/// where any linear field expands freely; the axisymmetric block is a ring from r = 1 to 5): the
/// quadratic families hold the quadratic displacement exactly, so the boundary nodes must take
/// each node's own thermal strain to stay at zero.
void free_expansion(ElementType type, AnalysisType analysis) {
  const bool plane = analysis == AnalysisType::plane_stress;
  const double r0 = plane ? 0.0 : 1.0;
  Block b;
  b.model.analysis = analysis;
  b.model.materials.push_back(testing::isotropic_material(1, E, nu, 1.2e-5));
  b.grid = testing::add_quadratic_grid(b.model, type, cells, cells,
                                       [&](double s, double t) { return Vec2(r0 + cells * s, cells * t); }, 0);
  if (plane) testing::constrain(b.model, b.at(0, 0), 0.0, 0.0);
  testing::constrain(b.model, b.at(cells, 0), std::nullopt, 0.0);
  testing::fill_temperatures(b.model, 0.0);
  for (std::size_t n = 0; n < b.model.nodes.size(); ++n) {
    const Node& x = b.model.nodes[n];
    b.model.loads.node_temperature[n] = 100.0 * x.z + (plane ? 40.0 * x.r : 0.0);
  }
  const Solution s = solve(b.model);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  EXPECT_GE(chosen_corners(b).size(), 8U);
  const double scale = E * 1.2e-5 * 400.0;  // the thermal stress a held block would carry
  for (std::size_t n = 0; n < b.model.nodes.size(); ++n) {
    EXPECT_LT(s.recovered.mean(n).cwiseAbs().maxCoeff(), 1e-9 * scale) << n;
  }
}

TEST(BoundaryStresses, AFreeThermalExpansionIsStressFreeAtEveryBoundaryNode) {
  for (const ElementType type : {ElementType::quad8, ElementType::quad9, ElementType::tri6}) {
    for (const AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::axisymmetric}) {
      SCOPED_TRACE(std::string(element_type_names.name(type)) + " " + std::string(analysis_type_names.name(analysis)));
      free_expansion(type, analysis);
    }
  }
}

struct Analysis {
  AnalysisType type;
  ElementType family;
};

class BoundaryStressesExact : public ::testing::TestWithParam<Analysis> {};

TEST_P(BoundaryStressesExact, AUniformStressIsExactAtEveryBoundaryNode) {
  // Held on rollers and pressed on top: sigma_zz = -p everywhere, sigma_th = -nu p in plane strain.
  const Block b = pressed(GetParam().type, GetParam().family);
  const Solution s = solve(b.model);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  const double sigma_th = GetParam().type == AnalysisType::plane_strain ? -nu * p : 0.0;
  ASSERT_FALSE(chosen_corners(b).empty());
  for (std::size_t n = 0; n < b.model.nodes.size(); ++n) {
    const Vec4 sigma = s.recovered.mean(n);
    EXPECT_NEAR(sigma[rr], 0.0, 1e-10 * p) << n;
    EXPECT_NEAR(sigma[zz], -p, 1e-10 * p) << n;
    EXPECT_NEAR(sigma[rz], 0.0, 1e-10 * p) << n;
    EXPECT_NEAR(sigma[th], sigma_th, 1e-10 * p) << n;
  }
}

INSTANTIATE_TEST_SUITE_P(Families, BoundaryStressesExact,
                         ::testing::Values(Analysis{AnalysisType::plane_stress, ElementType::saas},
                                           Analysis{AnalysisType::plane_strain, ElementType::saas},
                                           Analysis{AnalysisType::axisymmetric, ElementType::saas},
                                           Analysis{AnalysisType::plane_stress, ElementType::quad8},
                                           Analysis{AnalysisType::plane_strain, ElementType::quad8},
                                           Analysis{AnalysisType::axisymmetric, ElementType::quad8},
                                           Analysis{AnalysisType::plane_stress, ElementType::tri6},
                                           Analysis{AnalysisType::axisymmetric, ElementType::quad9}),
                         [](const auto& info) {
                           return std::string(element_type_names.name(info.param.family)) + "_" +
                                  std::string(analysis_type_names.name(info.param.type));
                         });

}  // namespace
}  // namespace saasgaps
