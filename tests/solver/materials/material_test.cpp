// Material laws: tables, rotation, plane stress / strain reductions, bimodulus mixing, secant
// modulus and the bilinear curve.
#include "solver/materials/material.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include "solver/analysis/solid_materials.hpp"

namespace saasgaps {
namespace {

PropertyRow iso_row(double T, double E, double nu, double alpha) {
  PropertyRow r;
  r.T = T;
  r.E1 = r.E2 = r.E3 = E;
  r.nu12 = r.nu13 = r.nu23 = nu;
  r.alpha1 = r.alpha2 = r.alpha3 = alpha;
  return r;
}

TEST(Material, TablesInterpolateLinearlyAndClampAtTheEnds) {
  const std::vector<PropertyRow> table{iso_row(0.0, 10.0e6, 0.3, 1e-5), iso_row(1000.0, 6.0e6, 0.2, 2e-5)};
  EXPECT_DOUBLE_EQ(interpolate(table, 250.0, true).E1, 9.0e6);
  EXPECT_DOUBLE_EQ(interpolate(table, 250.0, true).nu12, 0.275);
  EXPECT_DOUBLE_EQ(interpolate(table, -500.0, true).E1, 10.0e6);
  EXPECT_DOUBLE_EQ(interpolate(table, 5000.0, true).alpha3, 2e-5);
  // Isotropic: G from the interpolated E and nu, not interpolated itself.
  const ElasticConstants c = interpolate(table, 500.0, true);
  EXPECT_DOUBLE_EQ(c.G12, c.E1 / (2.0 * (1.0 + c.nu12)));
}

TEST(Material, IsotropicPlaneLawsMatchTheTextbook) {
  const ElasticConstants c = interpolate({iso_row(0, 1.0e6, 0.25, 1e-5)}, 0.0, true);
  const Constitutive stress = constitutive(c, AnalysisType::plane_stress, 17.0);
  const double f = 1.0e6 / (1.0 - 0.25 * 0.25);
  EXPECT_NEAR(stress.D(0, 0), f, 1e-6);
  EXPECT_NEAR(stress.D(0, 1), 0.25 * f, 1e-6);
  EXPECT_NEAR(stress.D(2, 2), 1.0e6 / 2.5, 1e-6);
  EXPECT_NEAR(stress.D(3, 3), 0.0, 1e-9);
  // eps_th = -nu/E (s_rr + s_zz) out of plane.
  EXPECT_NEAR(stress.out_of_plane[0], -0.25e-6, 1e-18);
  const Constitutive strain = constitutive(c, AnalysisType::plane_strain, 0.0);
  const double g = 1.0e6 / (1.25 * 0.5);
  EXPECT_NEAR(strain.D(0, 0), g * 0.75, 1e-6);
  EXPECT_NEAR(strain.D(3, 0), g * 0.25, 1e-6);  // sigma_th = nu (s_rr + s_zz) under plane strain
  EXPECT_NEAR(strain.beta[0], 1.0e6 * 1e-5 / 0.5, 1e-9);  // E alpha / (1 - 2 nu)
}

/// A strongly orthotropic material (E1 / E2 = 4).
ElasticConstants orthotropic() {
  ElasticConstants c;
  c.E1 = 2.0e6;
  c.E2 = 0.5e6;
  c.E3 = 0.8e6;
  c.nu12 = 0.2;
  c.nu13 = 0.25;
  c.nu23 = 0.3;
  c.G12 = 0.3e6;
  c.alpha1 = 1e-6;
  c.alpha2 = 5e-6;
  c.alpha3 = 3e-6;
  return c;
}

TEST(Material, RotatedOrthotropicLawGivesTheRotatedStress) {
  const ElasticConstants c = orthotropic();
  for (AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::plane_strain, AnalysisType::axisymmetric}) {
    const double angle = 28.0;
    const Constitutive aligned = constitutive(c, analysis, 0.0);
    const Constitutive rotated = constitutive(c, analysis, angle);
    const Vec4 strain(1e-4, -3e-4, 2e-4, 0.5e-4);
    // Strain in material axes, through the aligned law, back to global axes.
    const Mat4 T = strain_rotation(angle);
    const Vec4 expected = T.transpose() * (aligned.D * (T * strain) - aligned.beta * 50.0);
    const Vec4 actual = rotated.D * strain - rotated.beta * 50.0;
    EXPECT_LT((actual - expected).norm(), 1e-9 * expected.norm());
    EXPECT_LT((stress_in_material_axes(actual, angle) - (aligned.D * (T * strain) - aligned.beta * 50.0)).norm(),
              1e-9 * expected.norm());
  }
}

TEST(Material, UniaxialStressAlongAxisOneStrainsByOneOverE1) {
  ElasticConstants c = orthotropic();
  const Mat4 S = compliance(c);
  const Vec4 strain = S * Vec4(1000.0, 0.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(strain[0], 1000.0 / 2.0e6);
  EXPECT_DOUBLE_EQ(strain[1], -0.2 * 1000.0 / 2.0e6);
  EXPECT_TRUE(positive_definite(c));
  c.nu12 = 2.5;  // nu12 nu21 > 1: no positive-definite stiffness
  EXPECT_FALSE(positive_definite(c));
}

TEST(Material, BimodulusTakesEachDirectionFromItsOwnTable) {
  ElasticConstants t, c;
  t.E1 = t.E2 = t.E3 = 1.0e6;
  t.nu12 = t.nu13 = t.nu23 = 0.2;
  t.G12 = 0.4e6;
  t.alpha1 = t.alpha2 = t.alpha3 = 1e-6;
  c = t;
  c.E1 = c.E2 = c.E3 = 3.0e6;
  c.G12 = 1.2e6;
  c.alpha1 = c.alpha2 = c.alpha3 = 2e-6;
  const ElasticConstants m = mix_bimodulus(t, c, 2U);  // only direction 2 compressive
  EXPECT_EQ(m.E1, 1.0e6);
  EXPECT_EQ(m.E2, 3.0e6);
  EXPECT_EQ(m.alpha2, 2e-6);
  EXPECT_EQ(m.G12, 0.8e6);
  EXPECT_EQ(mix_bimodulus(t, c, 1U | 2U | 4U).G12, 1.2e6);
  EXPECT_EQ(compression_directions(Vec4(-1.0, 2.0, -7.0, -3.0)), 1U | 4U);
}

TEST(Material, SecantModulusFollowsTheBilinearCurve) {
  const BilinearCurve curve{30.0e6, 30000.0, 1.0 / 3.0};
  EXPECT_DOUBLE_EQ(curve.stress(0.0005), 15000.0);
  EXPECT_DOUBLE_EQ(curve.stress(0.002), 30000.0 + 10.0e6 * 0.001);
  ElasticConstants c;
  c.E1 = c.E2 = c.E3 = 30.0e6;
  c.nu12 = c.nu13 = c.nu23 = 0.3;
  c.G12 = 30.0e6 / 2.6;
  const ElasticConstants s = secant(c, 0.5);
  EXPECT_DOUBLE_EQ(s.E1, 15.0e6);
  EXPECT_DOUBLE_EQ(s.nu12, 0.5 - 0.2 * 0.5);  // nu_s = 0.5 - (0.5 - nu) E_s / E
}

}  // namespace
}  // namespace saasgaps
