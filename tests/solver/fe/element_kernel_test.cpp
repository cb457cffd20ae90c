// Element kernels: symmetry, positive semi-definiteness, exactly the rigid-body null space, and
// invariance of the plane element under rotation of geometry and material together.
#include "solver/fe/edge_loads.hpp"
#include "solver/fe/element_kernel.hpp"
#include "solver/fe/element_geometry.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <numbers>

#include "support/graphite.hpp"

namespace saasgaps {
namespace {

ElasticConstants steel() {
  ElasticConstants c;
  c.E1 = c.E2 = c.E3 = 30.0e6;
  c.nu12 = c.nu13 = c.nu23 = 0.3;
  c.G12 = c.E1 / 2.6;
  c.alpha1 = c.alpha2 = c.alpha3 = 6.5e-6;
  return c;
}

using testing::graphite;  // orthotropic, not aligned with anything

ElementData distorted_quad(AnalysisType analysis, const ElasticConstants& c, double angle = 0.0) {
  ElementData e;
  e.node_count = 4;
  e.x = {Vec2(1.0, 0.2), Vec2(2.3, 0.0), Vec2(2.0, 1.4), Vec2(1.2, 1.0)};
  e.analysis = analysis;
  e.thickness = 0.7;
  e.law = constitutive(c, analysis, angle);
  return e;
}

ElementData triangle(AnalysisType analysis, const ElasticConstants& c) {
  ElementData e;
  e.type = ElementType::tri3;
  e.node_count = 3;
  e.x = {Vec2(1.0, 0.2), Vec2(2.3, 0.0), Vec2(2.0, 1.4), Vec2(0, 0)};
  e.analysis = analysis;
  e.law = constitutive(c, analysis, 25.0);
  return e;
}

/// Eigenvalues of the leading n x n block, ascending.
Eigen::VectorXd spectrum(const ElementMatrix& K, int n) {
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(K.topLeftCorner(n, n));
  return solver.eigenvalues();
}

int null_space_dimension(const Eigen::VectorXd& eigenvalues) {
  const double scale = eigenvalues.cwiseAbs().maxCoeff();
  int zero = 0;
  for (double v : eigenvalues) {
    EXPECT_GT(v, -1e-10 * scale) << "negative eigenvalue: not positive semi-definite";
    if (std::abs(v) < 1e-10 * scale) ++zero;
  }
  return zero;
}

struct Case {
  AnalysisType analysis;
  int rigid_modes;  // plane: 2 translations + rotation; axisymmetric: only translation along z
};

class KernelSpectrum : public ::testing::TestWithParam<Case> {};

TEST_P(KernelSpectrum, QuadIsSymmetricSemiDefiniteWithRigidBodyNullSpace) {
  for (const ElasticConstants& c : {steel(), graphite()}) {
    const ElementMatrices m = element_matrices(distorted_quad(GetParam().analysis, c, 30.0));
    EXPECT_LT((m.K - m.K.transpose()).norm(), 1e-12 * m.K.norm());
    EXPECT_EQ(null_space_dimension(spectrum(m.K, 8)), GetParam().rigid_modes);
  }
}

TEST_P(KernelSpectrum, TriangleIsSymmetricSemiDefiniteWithRigidBodyNullSpace) {
  for (const ElasticConstants& c : {steel(), graphite()}) {
    const ElementMatrices m = element_matrices(triangle(GetParam().analysis, c));
    EXPECT_LT((m.K - m.K.transpose()).norm(), 1e-12 * m.K.norm());
    EXPECT_EQ(null_space_dimension(spectrum(m.K, 6)), GetParam().rigid_modes);
  }
}

INSTANTIATE_TEST_SUITE_P(AllAnalyses, KernelSpectrum,
                         ::testing::Values(Case{AnalysisType::plane_stress, 3}, Case{AnalysisType::plane_strain, 3},
                                           Case{AnalysisType::axisymmetric, 1}),
                         [](const auto& param_info) {
                           switch (param_info.param.analysis) {
                             case AnalysisType::plane_stress: return std::string("PlaneStress");
                             case AnalysisType::plane_strain: return std::string("PlaneStrain");
                             default: return std::string("Axisymmetric");
                           }
                         });

TEST(ElementKernel, RigidMotionsProduceNoForceNorStress) {
  const ElementData e = distorted_quad(AnalysisType::plane_strain, graphite(), 40.0);
  const ElementMatrices m = element_matrices(e);
  Vec8 translation, rotation;
  for (int a = 0; a < 4; ++a) {
    translation.segment<2>(2 * a) = Vec2(0.3, -0.2);
    rotation.segment<2>(2 * a) = Vec2(-e.x[a].y(), e.x[a].x()) * 1e-3;
  }
  const double scale = m.K.norm();
  EXPECT_LT((m.K * translation).norm(), 1e-12 * scale);
  EXPECT_LT((m.K * rotation).norm(), 1e-12 * scale);
  EXPECT_LT(element_state(e, std::span<const double>(rotation.data(), 8)).stress.norm(), 1e-6);

  // In axisymmetry only a translation along z is rigid; a uniform u_r stretches the hoop.
  const ElementData axi = distorted_quad(AnalysisType::axisymmetric, steel());
  Vec8 along_z = Vec8::Zero(), along_r = Vec8::Zero();
  for (int a = 0; a < 4; ++a) {
    along_z[2 * a + 1] = 1.0;
    along_r[2 * a] = 1.0;
  }
  EXPECT_LT((element_matrices(axi).K * along_z).norm(), 1e-12 * element_matrices(axi).K.norm());
  EXPECT_GT(element_state(axi, std::span<const double>(along_r.data(), 8)).stress[th], 0.0);
}

/// Q rotates every corner's (u_r, u_z) by +t.
Mat8 corner_rotation(double t) {
  Mat8 Q = Mat8::Zero();
  const double c = std::cos(t), s = std::sin(t);
  for (int a = 0; a < 4; ++a) Q.block<2, 2>(2 * a, 2 * a) << c, -s, s, c;
  return Q;
}

TEST(ElementKernel, RotatingGeometryAndMaterialTogetherRotatesTheStiffness) {
  // An orthotropic element and the same element turned by 35 degrees with its material axes turned
  // along: K' = Q K Q^T, and the rotated thermal load is the rotated load.
  for (AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::plane_strain}) {
    const double degrees = 35.0;
    const double t = degrees * std::numbers::pi / 180.0;
    ElementData base = distorted_quad(analysis, graphite(), 10.0);
    base.dT = {100.0, 120.0, 90.0, 80.0};
    ElementData turned = distorted_quad(analysis, graphite(), 10.0 + degrees);
    turned.dT = base.dT;
    Eigen::Matrix2d R;
    R << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
    for (int a = 0; a < 4; ++a) turned.x[a] = R * base.x[a];

    const ElementMatrices m0 = element_matrices(base);
    const ElementMatrices m1 = element_matrices(turned);
    const Mat8 Q = corner_rotation(t);
    EXPECT_LT((m1.K - Q * m0.K * Q.transpose()).norm(), 1e-9 * m0.K.norm());
    EXPECT_LT((m1.f - Q * m0.f).norm(), 1e-9 * m0.f.norm());
  }
}

TEST(ElementKernel, EdgeLoadsAreConsistentAndRingWeightedInAxisymmetry) {
  const Vec2 a(1.0, 0.0), b(3.0, 0.0);
  const auto plane = edge_traction_loads(a, b, Vec2(0.0, -10.0), AnalysisType::plane_stress, 0.5);
  EXPECT_DOUBLE_EQ(plane[0].y(), -5.0);  // 10 * length 2 * thickness 0.5 / 2
  EXPECT_DOUBLE_EQ(plane[1].y(), -5.0);
  const auto ring = edge_traction_loads(a, b, Vec2(0.0, -10.0), AnalysisType::axisymmetric, 1.0);
  // Total = p * annulus area pi (3^2 - 1^2); the outer node takes more.
  EXPECT_NEAR(ring[0].y() + ring[1].y(), -10.0 * std::numbers::pi * 8.0, 1e-9);
  EXPECT_LT(ring[1].y(), ring[0].y());
}

TEST(ElementKernel, BodyForceTotalsTheWeight) {
  ElementData e = distorted_quad(AnalysisType::axisymmetric, steel());
  e.body_force = Vec2(0.0, -2.0);
  const ElementMatrices m = element_matrices(e);
  // The condensed load still sums to the whole body force: -2 * 2 pi * int r dA, computed by the
  // four triangles around the centre.
  const Vec2 centre = 0.25 * (e.x[0] + e.x[1] + e.x[2] + e.x[3]);
  double volume = 0.0;
  for (int i = 0; i < 4; ++i) {
    const Vec2& p = e.x[i];
    const Vec2& q = e.x[(i + 1) % 4];
    volume += 2.0 * std::numbers::pi * 0.5 * twice_signed_area(p, q, centre) * (p.x() + q.x() + centre.x()) / 3.0;
  }
  double fz = 0.0;
  for (int a = 0; a < 4; ++a) fz += m.f[2 * a + 1];
  EXPECT_NEAR(fz, -2.0 * volume, 1e-10 * volume);
}

TEST(ElementKernel, ConvexityCheckSeesClockwiseAndReflexQuads) {
  std::array<Vec2, 4> x = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  EXPECT_GT(min_twice_area(4, x), 0.0);
  std::swap(x[1], x[3]);  // clockwise
  EXPECT_LT(min_twice_area(4, x), 0.0);
  std::array<Vec2, 4> dart = {Vec2(0, 0), Vec2(2, 0), Vec2(0.2, 0.2), Vec2(0, 2)};  // reflex corner
  EXPECT_LE(min_twice_area(4, dart), 0.0);
}

}  // namespace
}  // namespace saasgaps
