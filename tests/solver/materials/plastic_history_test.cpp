// Elastic unloading (solver/plastic_history.hpp): the plastic strain of a peak makes the elastic
// branch meet the secant law at the peak, through the kernel's initial-strain load, in every
// analysis and for a rotated orthotropic material; and the branch rule switches where it says.
#include "solver/materials/plastic_history.hpp"

#include <gtest/gtest.h>

#include "solver/fe/element_kernel.hpp"
#include "support/graphite.hpp"

namespace saasgaps {
namespace {

using testing::graphite;  // orthotropic, not aligned with anything

ElementData quad(AnalysisType analysis, const Constitutive& law) {
  ElementData e;
  e.node_count = 4;
  e.x = {Vec2(1.0, 0.2), Vec2(2.3, 0.0), Vec2(2.0, 1.4), Vec2(1.2, 1.0)};
  e.analysis = analysis;
  e.thickness = 0.7;
  e.law = law;
  e.dT = {300.0, 300.0, 300.0, 300.0};
  return e;
}

/// Corner displacements of a uniform strain: u_r = a r + g z, u_z = b z.
Vec8 uniform_strain(const ElementData& e, double a, double b, double g) {
  Vec8 u;
  for (int i = 0; i < 4; ++i) {
    u[2 * i] = a * e.x[i].x() + g * e.x[i].y();
    u[2 * i + 1] = b * e.x[i].y();
  }
  return u;
}

struct Case {
  AnalysisType analysis;
  double shear;  // g above
};

class PeakContinuity : public ::testing::TestWithParam<Case> {};

TEST_P(PeakContinuity, ElasticBranchWithThePlasticStrainGivesTheSecantStateAtThePeak) {
  const auto [analysis, g] = GetParam();
  constexpr double angle = 30.0, ratio = 0.37;
  const ElasticConstants elastic = graphite();
  const ElasticConstants loaded = secant(elastic, ratio);
  const ElementData on_curve = quad(analysis, constitutive(loaded, analysis, angle));
  const Vec8 u = uniform_strain(on_curve, 0.004, -0.003, g);
  const ElementState peak = element_state(on_curve, std::span<const double>(u.data(), 8));

  Constitutive unloading = constitutive(elastic, analysis, angle);
  unloading.initial_strain = plastic_strain(elastic, loaded, angle, peak.stress);
  ASSERT_TRUE(unloading.has_initial_strain());
  const ElementData off_curve = quad(analysis, unloading);
  const ElementState back = element_state(off_curve, std::span<const double>(u.data(), 8));
  const double scale = peak.stress.cwiseAbs().maxCoeff();
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(back.stress[i], peak.stress[i], 1e-10 * scale) << "stress component " << i;
    EXPECT_NEAR(back.strain[i], peak.strain[i], 1e-12) << "strain component " << i;
  }
  // The same displacements are in equilibrium with the same nodal loads: K u - f agrees, so a solve
  // at the peak's displacements finds them on either branch.
  const ElementMatrices a = element_matrices(on_curve);
  const ElementMatrices b = element_matrices(off_curve);
  const Vec8 ra = a.K * u - a.f;
  const Vec8 rb = b.K * u - b.f;
  EXPECT_LT((ra - rb).cwiseAbs().maxCoeff(), 1e-9 * ra.cwiseAbs().maxCoeff());
}

// Plane analyses only: a uniform strain is an exact state of the SAAS quad there (its condensed
// centre node sits at the corners' mean on both branches). In an axisymmetric quad a uniform stress
// is not in equilibrium at the centre node (the hoop stress pulls it), so its triangles' strains
// differ and so do the two branches' averages; the law itself agrees (the next test).
INSTANTIATE_TEST_SUITE_P(Analyses, PeakContinuity,
                         ::testing::Values(Case{AnalysisType::plane_stress, 0.002},
                                           Case{AnalysisType::plane_strain, 0.002}));

TEST(PeakContinuity, LawsAgreeAtThePeakStrainInEveryAnalysis) {
  constexpr double angle = -50.0, ratio = 0.52, dT = 400.0;
  const ElasticConstants elastic = graphite();
  const ElasticConstants loaded = secant(elastic, ratio);
  const Vec4 eps(0.003, -0.0025, 0.0015, 0.001);
  for (AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::plane_strain, AnalysisType::axisymmetric}) {
    const Constitutive on_curve = constitutive(loaded, analysis, angle);
    const Vec4 peak = on_curve.D * eps - on_curve.beta * dT;
    Constitutive off_curve = constitutive(elastic, analysis, angle);
    off_curve.initial_strain = plastic_strain(elastic, loaded, angle, peak);
    const Vec4 back = off_curve.D * (eps - off_curve.initial_strain) - off_curve.beta * dT;
    EXPECT_LT((back - peak).cwiseAbs().maxCoeff(), 1e-10 * peak.cwiseAbs().maxCoeff())
        << "analysis " << static_cast<int>(analysis);
  }
}

TEST(PlasticStrain, UniaxialIsTheStrainAtThePeakLessSigmaOverE) {
  ElasticConstants c;
  c.E1 = c.E2 = c.E3 = 30.0e6;
  c.nu12 = c.nu13 = c.nu23 = 0.3;
  c.G12 = c.E1 / 2.6;
  constexpr double ratio = 0.6, sigma = 45.0e3;
  const Vec4 eps_p = plastic_strain(c, secant(c, ratio), 0.0, Vec4(0.0, sigma, 0.0, 0.0));
  const double eps_max = sigma / (ratio * c.E1);
  EXPECT_NEAR(eps_p[1], eps_max - sigma / c.E1, 1e-15);
  // Across: the secant Poisson ratio less the elastic one, nu_s = 0.5 - 0.2 x 0.6 = 0.38.
  EXPECT_NEAR(eps_p[0], -0.38 * eps_max + 0.3 * sigma / c.E1, 1e-15);
  EXPECT_EQ(eps_p[2], 0.0);
}

TEST(NextBranch, SwitchesBeyondThePlasticToleranceOnly) {
  const BilinearCurve curve{30.0e6, 30.0e3, 0.5};
  const PlasticPeak peak{1.5e-3, 37.5e3, Vec4(0.0, 0.25e-3, 0.0, 0.0)};
  constexpr double tol = 0.01;
  const double ratio_at_peak = 37.5e3 / (30.0e6 * 1.5e-3);
  // On the loading branch: below (1 - tol) eps_max it unloads, else the secant update as ever.
  const PlasticBranch down = next_branch(peak, curve, false, ratio_at_peak, 0.9 * 37.5e3, tol);
  EXPECT_TRUE(down.unloading);
  EXPECT_TRUE(down.changed);
  EXPECT_EQ(down.secant_ratio, 1.0);
  const PlasticBranch near = next_branch(peak, curve, false, ratio_at_peak, 0.995 * 37.5e3, tol);
  EXPECT_FALSE(near.unloading);
  EXPECT_FALSE(near.changed);
  EXPECT_DOUBLE_EQ(near.secant_ratio, curve.stress(0.995 * 1.5e-3) / (30.0e6 * 0.995 * 1.5e-3));
  // On the unloading branch: elastic up to (1 + tol) sigma_max, then back on the curve.
  const PlasticBranch stays = next_branch(peak, curve, true, 1.0, 1.005 * 37.5e3, tol);
  EXPECT_TRUE(stays.unloading);
  EXPECT_FALSE(stays.changed);
  const PlasticBranch up = next_branch(peak, curve, true, 1.0, 40.5e3, tol);
  EXPECT_FALSE(up.unloading);
  EXPECT_TRUE(up.changed);
  const double eps = 1.5e-3 + 3.0e3 / 30.0e6;  // the elastic line continued past the peak
  EXPECT_DOUBLE_EQ(up.secant_ratio, curve.stress(eps) / (30.0e6 * eps));
  // An element with no peak is the report's update, whatever its strain.
  const PlasticBranch fresh = next_branch(PlasticPeak{}, curve, false, 1.0, 15.0e3, tol);
  EXPECT_FALSE(fresh.unloading);
  EXPECT_EQ(fresh.secant_ratio, 1.0);
}

}  // namespace
}  // namespace saasgaps
