// The conduction kernel on its own: the tensor of a rotated orthotropic conductivity, the 2 pi r
// weighting of axisymmetry, and the constant field (no flux) in the null space of the SAAS quad.
#include "solver/thermal/conduction_kernel.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace saasgaps {
namespace {

TEST(ConductionKernel, TensorTurnsWithTheMaterialAxes) {
  const Eigen::Matrix2d k = Conductivity{4.0, 1.0, 30.0}.tensor();
  const Vec2 e1(std::sqrt(3.0) / 2.0, 0.5);
  const Vec2 e2(-0.5, std::sqrt(3.0) / 2.0);
  EXPECT_NEAR((k * e1 - 4.0 * e1).norm(), 0.0, 1e-15);
  EXPECT_NEAR((k * e2 - 1.0 * e2).norm(), 0.0, 1e-15);
  EXPECT_EQ(k(0, 1), k(1, 0));
}

TEST(ConductionKernel, TriangleMatchesTheClosedFormAndAxisymmetryWeighsBy2PiRc) {
  ConductionData d;
  d.node_count = 3;
  d.x = {Vec2(1.0, 0.0), Vec2(3.0, 0.5), Vec2(1.5, 2.0), Vec2::Zero()};
  d.k = {2.0, 2.0, 0.0};
  d.analysis = AnalysisType::plane_strain;
  d.thickness = 1.0;
  const Eigen::Matrix4d plane = conduction_matrix(d);
  // Closed form: K_ij = k t (b_i b_j + c_i c_j) / 4A, b_i = z_j - z_k, c_i = r_k - r_j.
  const double two_a = (3.0 - 1.0) * (2.0 - 0.0) - (1.5 - 1.0) * (0.5 - 0.0);
  for (int i = 0; i < 3; ++i) {
    const Vec2& pj = d.x[(i + 1) % 3];
    const Vec2& pk = d.x[(i + 2) % 3];
    for (int j = 0; j < 3; ++j) {
      const Vec2& qj = d.x[(j + 1) % 3];
      const Vec2& qk = d.x[(j + 2) % 3];
      const double expected = 2.0 * ((pj.y() - pk.y()) * (qj.y() - qk.y()) + (pk.x() - pj.x()) * (qk.x() - qj.x())) / (2.0 * two_a);
      EXPECT_NEAR(plane(i, j), expected, 1e-14 * std::abs(expected) + 1e-15) << i << ", " << j;
    }
  }
  EXPECT_EQ(plane.row(3).norm() + plane.col(3).norm(), 0.0);
  d.analysis = AnalysisType::axisymmetric;
  const double r_c = (1.0 + 3.0 + 1.5) / 3.0;
  EXPECT_LT((conduction_matrix(d) - 2.0 * std::numbers::pi * r_c * plane).norm(), 1e-14 * plane.norm());
}

TEST(ConductionKernel, QuadHasOnlyTheConstantFieldInItsNullSpace) {
  ConductionData d;
  d.x = {Vec2(1.0, 0.0), Vec2(2.2, 0.1), Vec2(2.0, 1.3), Vec2(0.9, 1.0)};
  d.k = {3.0, 0.5, -40.0};
  for (AnalysisType analysis : {AnalysisType::plane_stress, AnalysisType::axisymmetric}) {
    d.analysis = analysis;
    const Eigen::Matrix4d K = conduction_matrix(d);
    EXPECT_LT((K * Eigen::Vector4d::Ones()).norm(), 1e-14 * K.norm());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(0.5 * (K + K.transpose()));
    EXPECT_LT(std::abs(eig.eigenvalues()[0]), 1e-14 * K.norm());
    EXPECT_GT(eig.eigenvalues()[1], 1e-3 * K.norm());  // one zero eigenvalue only
  }
}

}  // namespace
}  // namespace saasgaps
