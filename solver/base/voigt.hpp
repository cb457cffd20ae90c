#pragma once
/// Small fixed-size types shared by the kernels. Stress and strain vectors are in Voigt order
/// (rr, zz, rz, theta) with engineering shear strain gamma_rz. "theta" is the hoop component in
/// axisymmetry and the out-of-plane component in plane analyses.

#include <Eigen/Core>

namespace saasgaps {

using Vec2 = Eigen::Vector2d;
using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat4 = Eigen::Matrix<double, 4, 4>;
using Vec8 = Eigen::Matrix<double, 8, 1>;
using Mat8 = Eigen::Matrix<double, 8, 8>;

inline constexpr int rr = 0;
inline constexpr int zz = 1;
inline constexpr int rz = 2;
inline constexpr int th = 3;

/// In-plane principal stresses and the direction of the larger one.
struct Principal {
  double s1 = 0.0;         ///< larger in-plane principal stress
  double s2 = 0.0;         ///< smaller in-plane principal stress
  double angle_deg = 0.0;  ///< direction of s1, counter-clockwise from +r, in (-90, 90]
};

/// s1,2 = (srr + szz)/2 +- sqrt(((srr - szz)/2)^2 + trz^2), angle = atan2(2 trz, srr - szz) / 2.
Principal principal_in_plane(const Vec4& stress);

/// von Mises: sqrt(((srr - szz)^2 + (szz - sth)^2 + (sth - srr)^2) / 2 + 3 trz^2).
double von_mises(const Vec4& stress);

/// Normal component along a direction at angle_deg from +r: c^2 v_rr + s^2 v_zz + c s v_rz.
/// With engineering shear strain pass shear_factor = 1; for stresses pass 2 (2 c s t_rz).
double normal_component(const Vec4& v, double angle_deg, double shear_factor);

}  // namespace saasgaps
