// Symmetry lines (solver/recovery/symmetry_lines): which nodes lie on one, and what patch recovery
// does with them. A 4 x 4 grid of the report's element on [0, 4] x [0, 4] with rollers along its
// bottom (z = 0) and left (r = 0) sides.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/fe/element_family.hpp"
#include "solver/recovery/patch_recovery.hpp"
#include "solver/recovery/symmetry_lines.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

constexpr int cells = 4;

struct Grid {
  Model model;
  testing::QuadraticGrid grid;
  [[nodiscard]] std::size_t at(int i, int j) const { return static_cast<std::size_t>(grid.at(2 * i, 2 * j)); }
};

Grid rollers(AnalysisType analysis, ElementType type = ElementType::saas) {
  Grid g;
  g.model.analysis = analysis;
  g.model.materials.push_back(testing::isotropic_material(1, 200.0e3, 0.3));
  g.grid = testing::add_quadratic_grid(g.model, type, cells, cells, [](double s, double t) { return Vec2(cells * s, cells * t); }, 0);
  for (int i = 1; i <= cells; ++i) testing::constrain(g.model, static_cast<int>(g.at(i, 0)), std::nullopt, 0.0);
  for (int j = 1; j <= cells; ++j) testing::constrain(g.model, static_cast<int>(g.at(0, j)), 0.0, std::nullopt);
  testing::constrain(g.model, static_cast<int>(g.at(0, 0)), 0.0, 0.0);
  testing::fill_temperatures(g.model, 0.0);
  return g;
}

TEST(SymmetryLines, RollersOnStraightSidesAreLinesAndAPinnedCornerIsNot) {
  const Grid g = rollers(AnalysisType::plane_stress);
  const SymmetryLines lines = stress_symmetry_lines(g.model);
  EXPECT_EQ(lines.kind[g.at(2, 0)], MirrorKind::z_line);
  EXPECT_EQ(lines.kind[g.at(0, 3)], MirrorKind::r_line);
  EXPECT_EQ(lines.kind[g.at(0, 0)], MirrorKind::none);  // both components held
  EXPECT_EQ(lines.kind[g.at(2, 2)], MirrorKind::none);
  EXPECT_TRUE(lines.same_line(g.model, g.at(1, 0), g.at(4, 0)));
  EXPECT_FALSE(lines.same_line(g.model, g.at(1, 0), g.at(0, 1)));
  const Vec2 image = lines.mirror_point(g.model, g.at(2, 0), Vec2(2.5, 0.75));
  EXPECT_EQ(image, Vec2(2.5, -0.75));
  EXPECT_EQ(lines.mirror_value(g.at(0, 2), Vec4(1, 2, 3, 4)), Vec4(1, 2, -3, 4));
}

TEST(SymmetryLines, InAxisymmetryOnlyTheAxisMirrorsAlongR) {
  Grid g = rollers(AnalysisType::axisymmetric);
  testing::constrain(g.model, static_cast<int>(g.at(4, 2)), 0.0, std::nullopt);  // a roller at r = 4
  const SymmetryLines lines = stress_symmetry_lines(g.model);
  EXPECT_EQ(lines.kind[g.at(0, 2)], MirrorKind::r_line);  // r = 0
  EXPECT_EQ(lines.kind[g.at(4, 2)], MirrorKind::none);    // the hoop terms are not symmetric about r = 4
  EXPECT_EQ(lines.kind[g.at(3, 0)], MirrorKind::z_line);
}

TEST(SymmetryLines, DifferentValuesTangentialForcesAndStepsEndALine) {
  Grid g = rollers(AnalysisType::plane_strain);
  testing::constrain(g.model, static_cast<int>(g.at(4, 0)), std::nullopt, 0.01);  // moved: another line
  g.model.loads.nodal_forces.push_back({static_cast<int>(g.at(1, 0)), 5.0, 0.0});  // along the line
  g.model.loads.nodal_forces.push_back({static_cast<int>(g.at(2, 0)), 0.0, 5.0});  // across it: fine
  Step step;
  step.constraints.push_back({static_cast<int>(g.at(3, 0)), 0.0, std::nullopt});  // pinned by step 1
  g.model.steps.push_back(step);
  const SymmetryLines lines = stress_symmetry_lines(g.model);
  EXPECT_FALSE(lines.same_line(g.model, g.at(2, 0), g.at(4, 0)));
  EXPECT_EQ(lines.kind[g.at(1, 0)], MirrorKind::none);
  EXPECT_EQ(lines.kind[g.at(2, 0)], MirrorKind::z_line);
  EXPECT_EQ(lines.kind[g.at(3, 0)], MirrorKind::none);
}

/// Samples of a stress field symmetric about z = 0 (normal components linear in r, the shear odd and
/// cubic in z: beyond what a patch fits), at each element's four quarter points.
Vec4 field(const Vec2& x) { return Vec4(1.0 + 0.5 * x.x(), 2.0 - x.x(), 0.3 * x.y() * x.y() * x.y(), 4.0); }

Vec4 samples_field_at(const Model& m, std::size_t n) { return field(Vec2(m.nodes[n].r, m.nodes[n].z)); }

std::vector<ElementSamples> symmetric_samples(const Model& m) {
  std::vector<ElementSamples> out(m.elements.size());
  for (std::size_t e = 0; e < m.elements.size(); ++e) {
    const Element& el = m.elements[e];
    ElementSamples& s = out[e];
    s.count = 4;
    for (int q = 0; q < 4; ++q) {
      const double xi = q % 2 == 0 ? -0.5 : 0.5, eta = q < 2 ? -0.5 : 0.5;
      ShapeValues v;
      family(ElementType::quad4i).shape(xi, eta, v);
      Vec2 x = Vec2::Zero();
      for (int a = 0; a < 4; ++a) x += v.N[static_cast<std::size_t>(a)] * Vec2(m.nodes[el.nodes[a]].r, m.nodes[el.nodes[a]].z);
      s.point[static_cast<std::size_t>(q)] = {x, field(x)};
    }
  }
  return out;
}

TEST(SymmetryLines, MirroredPatchesKeepTheShearZeroOnTheLineAndLinearEvenTermsExact) {
  const Grid g = rollers(AnalysisType::plane_stress);
  const std::vector<ElementSamples> samples = symmetric_samples(g.model);
  const SymmetryLines lines = stress_symmetry_lines(g.model);
  const RecoveredField plain = recover_field(g.model, samples);
  const RecoveredField mirrored = recover_field(g.model, samples, &lines);
  for (int i = 1; i <= cells; ++i) {
    const std::size_t n = g.at(i, 0);
    // The shear is odd about the line: zero there (round-off) once the patches hold their mirror
    // images; extrapolated from one side, the fit of z^3 misses zero.
    EXPECT_NEAR(mirrored.mean(n)[2], 0.0, 1e-12) << i;
    EXPECT_GT(std::abs(plain.mean(n)[2]), 1e-3) << i;
    // The normal components are linear and even: both recover them exactly (the mirror is consistent).
    for (const int c : {0, 1, 3}) {
      EXPECT_NEAR(mirrored.mean(n)[c], samples_field_at(g.model, n)[c], 1e-12) << i << " " << c;
    }
  }
  // Off the lines nothing changes.
  EXPECT_EQ(mirrored.mean(g.at(2, 2)), plain.mean(g.at(2, 2)));
}

TEST(SymmetryLines, InsulatedStraightEdgesAreHeatSymmetryLines) {
  // The grid with a temperature on its left side (r = 0), a film on its right (r = 4), the bottom
  // and the top insulated but for a flux on the top's last edge.
  Grid g;
  g.model.analysis = AnalysisType::plane_stress;
  g.model.materials.push_back(testing::isotropic_material(1, 200.0e3, 0.3));
  g.grid = testing::add_quadratic_grid(g.model, ElementType::saas, cells, cells, [](double s, double t) { return Vec2(cells * s, cells * t); }, 0);
  g.model.thermal.emplace();
  g.model.thermal->boundary.push_back({ThermalBoundary::Kind::temperature, testing::quadratic_grid_side(g.model, g.grid, 'l'), 100.0, 0.0});
  g.model.thermal->boundary.push_back({ThermalBoundary::Kind::film, testing::quadratic_grid_side(g.model, g.grid, 'r'), 5.0, 20.0});
  const std::vector<ThermalEdge> top = testing::quadratic_grid_side(g.model, g.grid, 't');
  g.model.thermal->boundary.push_back({ThermalBoundary::Kind::flux, {top.back()}, 1.0, 0.0});
  const SymmetryLines lines = heat_symmetry_lines(g.model);
  for (int i = 0; i <= cells; ++i) EXPECT_EQ(lines.kind[g.at(i, 0)], MirrorKind::z_line) << i;  // corners too: the conditioned sides cross it
  EXPECT_EQ(lines.kind[g.at(2, cells)], MirrorKind::z_line);
  EXPECT_EQ(lines.kind[g.at(3, cells)], MirrorKind::none);  // the flux edge lies along the top
  EXPECT_EQ(lines.kind[g.at(0, 2)], MirrorKind::none);      // a temperature edge is no line
  EXPECT_EQ(lines.kind[g.at(2, 2)], MirrorKind::none);
  EXPECT_EQ(lines.mirror_value(g.at(1, 0), Vec4(1, 2, 0, 0)), Vec4(1, -2, 0, 0));  // q_z changes sign
  // No thermal section: no lines.
  g.model.thermal.reset();
  EXPECT_TRUE(heat_symmetry_lines(g.model).empty());
}

}  // namespace
}  // namespace saasgaps
