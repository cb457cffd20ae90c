// Constant-strain patch tests through the whole pipeline (assembly, prescribed displacements,
// CHOLMOD, stress recovery): a distorted patch of SAAS quads and triangles, its boundary moved by
// a linear displacement field, must reproduce the field inside and a constant stress to round-off,
// in all three analyses, isotropic and rotated orthotropic.
#include <gtest/gtest.h>

#include <numbers>

#include "solver/analysis/analysis.hpp"
#include "solver/analysis/solid_materials.hpp"
#include "solver/materials/material.hpp"
#include "support/mesh_builder.hpp"

namespace saasgaps {
namespace {

using testing::add_grid;
using testing::fill_temperatures;

Material rotated_graphite() {
  Material m;
  m.id = 2;
  m.isotropic = false;
  PropertyRow r;
  r.E1 = 1.6e6;
  r.E2 = 1.1e6;
  r.E3 = 1.3e6;
  r.nu12 = 0.12;
  r.nu13 = 0.1;
  r.nu23 = 0.15;
  r.G12 = 0.45e6;
  r.alpha1 = 2e-6;
  r.alpha2 = 3e-6;
  r.alpha3 = 2.5e-6;
  m.table.push_back(r);
  return m;
}

/// A 3 x 3 patch on [1, 3] x [0, 2], interior nodes pushed off the grid, the top-right quad split into
/// two triangles.
Model distorted_patch(AnalysisType analysis, int material, double angle) {
  Model m;
  m.analysis = analysis;
  m.thickness = 0.7;
  m.materials = {testing::isotropic_material(1, 1.0e6, 0.3, 1e-5), rotated_graphite()};
  const testing::Grid g = add_grid(m, 3, 3, [](double s, double t) { return Vec2(1.0 + 2.0 * s, 2.0 * t); },
                                   material, angle);
  const std::vector<Vec2> shift = {Vec2(0.13, 0.07), Vec2(-0.11, 0.12), Vec2(0.05, -0.14), Vec2(-0.08, -0.06)};
  int k = 0;
  for (int j = 1; j <= 2; ++j) {
    for (int i = 1; i <= 2; ++i) {
      Node& n = m.nodes[g.at(i, j)];
      n.r += shift[k].x();
      n.z += shift[k++].y();
    }
  }
  Element& corner = m.elements.back();
  Element second = corner;
  second.id = 100;
  second.node_count = 3;
  second.nodes = {corner.nodes[0], corner.nodes[2], corner.nodes[3], -1};
  corner.node_count = 3;
  corner.nodes = {corner.nodes[0], corner.nodes[1], corner.nodes[2], -1};
  m.elements.push_back(second);
  fill_temperatures(m, 0.0);
  return m;
}

struct LinearField {
  double a0, a1, a2, b0, b1, b2;  // u_r = a0 + a1 r + a2 z, u_z = b0 + b1 r + b2 z
  [[nodiscard]] Vec2 at(double r, double z) const { return {a0 + a1 * r + a2 * z, b0 + b1 * r + b2 * z}; }
  [[nodiscard]] Vec4 strain(AnalysisType analysis) const {
    // Axisymmetric constant strain needs u_r proportional to r (then u/r = a1).
    return {a1, b2, a2 + b1, analysis == AnalysisType::axisymmetric ? a1 : 0.0};
  }
};

void run_patch(AnalysisType analysis, int material, double angle, double dT) {
  Model m = distorted_patch(analysis, material, angle);
  // In axisymmetry a constant stress is in equilibrium only with tau_rz = 0 and sigma_r = sigma_theta
  // (d sigma_r/dr + d tau/dz + (sigma_r - sigma_theta)/r = 0, d tau/dr + d sigma_z/dz + tau/r = 0):
  // u_r proportional to r, no shear, and a material isotropic in the r-theta plane.
  const LinearField field = analysis == AnalysisType::axisymmetric ? LinearField{0, 2e-4, 0, 1e-3, 0, -1e-4}
                                                                   : LinearField{1e-3, 2e-4, -3e-4, 5e-4, 1e-4, -1e-4};
  for (int n = 0; n < static_cast<int>(m.nodes.size()); ++n) {
    m.loads.node_temperature[n] = dT;
    const Node& node = m.nodes[n];
    const bool boundary = node.r == 1.0 || node.r == 3.0 || node.z == 0.0 || node.z == 2.0;
    if (boundary) {
      const Vec2 u = field.at(node.r, node.z);
      testing::constrain(m, n, u.x(), u.y());
    }
  }
  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged);
  for (std::size_t n = 0; n < m.nodes.size(); ++n) {
    const Vec2 u = field.at(m.nodes[n].r, m.nodes[n].z);
    EXPECT_NEAR(s.nodes[n].u_r, u.x(), 1e-14) << "node " << m.nodes[n].id;
    EXPECT_NEAR(s.nodes[n].u_z, u.y(), 1e-14) << "node " << m.nodes[n].id;
  }
  const Material& mat = m.materials[material];
  const Constitutive law = constitutive(interpolate(mat.table, dT, mat.isotropic), analysis, angle);
  Vec4 strain = field.strain(analysis);
  const Vec4 stress = law.D * strain - law.beta * dT;
  if (analysis == AnalysisType::plane_stress) strain[th] = law.out_of_plane.dot(stress) + law.alpha3 * dT;
  for (const ElementResult& e : s.elements) {
    EXPECT_LT((e.stress - stress).norm(), 1e-9 * stress.norm()) << "element " << e.id;
    EXPECT_LT((e.strain - strain).norm(), 1e-12) << "element " << e.id;
  }
}

TEST(PatchTest, PlaneStressIsotropic) { run_patch(AnalysisType::plane_stress, 0, 0.0, 0.0); }
TEST(PatchTest, PlaneStrainIsotropicWithTemperature) { run_patch(AnalysisType::plane_strain, 0, 0.0, 150.0); }
TEST(PatchTest, AxisymmetricIsotropicWithTemperature) { run_patch(AnalysisType::axisymmetric, 0, 0.0, 150.0); }
TEST(PatchTest, PlaneStressRotatedOrthotropic) { run_patch(AnalysisType::plane_stress, 1, 33.0, 80.0); }
TEST(PatchTest, PlaneStrainRotatedOrthotropic) { run_patch(AnalysisType::plane_strain, 1, -20.0, 80.0); }

/// A unit square turned by `degrees`, material axis 1 turned along, pulled by `stress` across the
/// two faces normal to axis 1; held only against rigid motion (3 components).
Solution pulled_turned_block(double degrees, double stress) {
  const double t = degrees * std::numbers::pi / 180.0;
  const Eigen::Matrix2d R = (Eigen::Matrix2d() << std::cos(t), -std::sin(t), std::sin(t), std::cos(t)).finished();
  Model m;
  m.analysis = AnalysisType::plane_stress;
  m.materials = {rotated_graphite()};
  const testing::Grid g = add_grid(m, 4, 4, [&](double s, double u) { return Vec2(R * Vec2(s, u)); }, 0, degrees);
  fill_temperatures(m, 0.0);
  for (int j = 0; j < 4; ++j) {
    // Pressures pull (negative normal) on the faces s = 0 and s = 1: the bottom/top edges of columns.
    m.loads.pressures.push_back({j * 4, g.at(0, j + 1), g.at(0, j), -stress, 0.0});
    m.loads.pressures.push_back({j * 4 + 3, g.at(4, j), g.at(4, j + 1), -stress, 0.0});
  }
  testing::constrain(m, g.at(0, 0), 0.0, 0.0);
  // Holding node (4, 0) in the direction normal to the block's side blocks rotation without
  // restraining the stretch; for the turned block that is r or z, whichever the side is not along.
  if (std::abs(std::sin(t)) > 0.5) {
    testing::constrain(m, g.at(4, 0), 0.0, std::nullopt);
  } else {
    testing::constrain(m, g.at(4, 0), std::nullopt, 0.0);
  }
  return solve(m);
}

TEST(PatchTest, RotatedOrthotropicBlockUnderRotatedLoadGivesTheRotatedAnswer) {
  const Solution aligned = pulled_turned_block(0.0, 1000.0);
  ASSERT_EQ(aligned.status, RunStatus::converged);
  for (double degrees : {30.0, 75.0, 135.0}) {
    const Solution turned = pulled_turned_block(degrees, 1000.0);
    ASSERT_EQ(turned.status, RunStatus::converged);
    for (std::size_t e = 0; e < turned.elements.size(); ++e) {
      const Vec4 material_stress = stress_in_material_axes(turned.elements[e].stress, degrees);
      EXPECT_NEAR(material_stress[0], 1000.0, 1e-7);
      EXPECT_NEAR(material_stress[1], 0.0, 1e-7);
      EXPECT_NEAR(material_stress[2], 0.0, 1e-7);
      // Strains in material axes equal those of the aligned block: (1000 / E1, -nu12 1000 / E1, 0).
      const Mat4 T = strain_rotation(degrees);
      const Vec4 material_strain = T * turned.elements[e].strain;
      EXPECT_NEAR(material_strain[0], aligned.elements[e].strain[0], 1e-13);
      EXPECT_NEAR(material_strain[1], aligned.elements[e].strain[1], 1e-13);
      EXPECT_NEAR(material_strain[2], 0.0, 1e-13);
    }
  }
  EXPECT_NEAR(aligned.elements[0].strain[0], 1000.0 / 1.6e6, 1e-13);
}

}  // namespace
}  // namespace saasgaps
