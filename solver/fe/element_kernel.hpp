#pragma once
/// Element kernels: pure functions of coordinates, material and temperatures that fill fixed-size
/// matrices. Assembly scatters them; nothing here knows about global numbering.
///
/// The geometry (triangles, the SAAS quad, weights, condensation) is element_geometry.hpp's; this
/// file is the solid (displacement) field on it.
///
/// Degrees of freedom per corner node are (u_r, u_z), corners in counter-clockwise order:
/// [u_r0, u_z0, u_r1, u_z1, ...]. A 3-node element is one constant-strain triangle (CST) and fills
/// the leading 6x6 block. A 4-node element is the SAAS III quadrilateral: four CSTs meeting at a
/// centre node at the mean of the corners; the centre's two DOFs are condensed out statically.
///
/// Weights: plane analyses integrate over thickness t (w = t A); axisymmetric ones over the full ring
/// (w = 2 pi r_c A, with the hoop strain u/r taken at the triangle centroid r_c). A lone axisymmetric
/// triangle samples u/r at three interior points instead (the centroid alone leaves it a spurious
/// zero-energy mode); its stresses are still reported at the centroid.

#include <array>

#include "solver/base/voigt.hpp"
#include "solver/fe/element_geometry.hpp"
#include "solver/materials/material.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// Everything an element kernel depends on.
struct ElementData {
  int node_count = 4;
  std::array<Vec2, 4> x{};  ///< corner coordinates (r, z), counter-clockwise
  AnalysisType analysis = AnalysisType::plane_stress;
  double thickness = 1.0;
  Constitutive law;
  std::array<double, 4> dT{};  ///< corner temperature rise above the reference temperature
  Vec2 body_force{0.0, 0.0};   ///< force per unit volume along r and z
  double spin = 0.0;           ///< density * omega^2: adds spin * r per unit volume along r
};

/// Condensed stiffness and equivalent nodal loads (thermal, initial strain and body force) of one element.
struct ElementMatrices {
  Mat8 K = Mat8::Zero();
  Vec8 f = Vec8::Zero();
};

/// Strain and stress at the element centre: the weighted average of its triangles.
struct ElementState {
  Vec4 strain = Vec4::Zero();  ///< total strain (rr, zz, gamma_rz, th), thermal and initial parts included
  Vec4 stress = Vec4::Zero();  ///< (rr, zz, rz, th)
};

ElementMatrices element_matrices(const ElementData& e);

/// Recovers the centre displacement from the corner displacements u, then the centre state.
ElementState element_state(const ElementData& e, const Vec8& u);

/// Consistent nodal loads of a uniform traction (t_r, t_z) per unit area on edge a-b:
/// plane: t L thickness / 2 each; axisymmetric: 2 pi t L (2 r_a + r_b) / 6 at a, and mirrored at b.
std::array<Vec2, 2> edge_traction_loads(const Vec2& a, const Vec2& b, const Vec2& traction,
                                        AnalysisType analysis, double thickness);

}  // namespace saasgaps
