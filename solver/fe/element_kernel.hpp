#pragma once
/// Element kernels of the solid (displacement) field: pure functions of coordinates, laws and
/// temperatures that fill an element's stiffness and loads, and give back its strains and stresses.
/// Assembly scatters them; nothing here knows about global numbering. Which kernel an element uses
/// is its family's (element_family.hpp): the report's elements (saas_kernel.hpp), the
/// isoparametric ones (isoparametric_kernel.hpp), the bilinear quad with incompatible modes
/// (incompatible_modes.hpp).
///
/// Degrees of freedom per node are (u_r, u_z), nodes in the family's order:
/// [u_r0, u_z0, u_r1, u_z1, ...], n = 2 x node_count. Strains and stresses are Voigt vectors
/// (rr, zz, rz, th) with engineering shear strain (voigt.hpp).
///
/// Weights: plane analyses integrate over thickness t, axisymmetric ones over the full ring
/// (2 pi r at each point): a force or an energy of an axisymmetric model is that of the whole ring.

#include <array>
#include <span>

#include <Eigen/Core>

#include "solver/base/voigt.hpp"
#include "solver/fe/element_family.hpp"
#include "solver/materials/material.hpp"
#include "solver/model/model.hpp"

namespace saasgaps {

/// Everything an element kernel depends on.
struct ElementData {
  ElementType type = ElementType::saas;
  Integration integration = Integration::full;
  int node_count = 4;
  std::array<Vec2, max_element_nodes> x{};  ///< node coordinates (r, z) in the family's order
  AnalysisType analysis = AnalysisType::plane_stress;
  double thickness = 1.0;
  /// The constitutive law at every material point, unless point_laws gives one per point.
  Constitutive law;
  /// One law per material point of the family (element_family.hpp); empty: `law` everywhere. A
  /// view: the caller keeps the laws alive while the kernel runs.
  std::span<const Constitutive> point_laws;
  std::array<double, max_element_nodes> dT{};  ///< node temperature rise above the reference temperature
  Vec2 body_force{0.0, 0.0};                   ///< force per unit volume along r and z
  double spin = 0.0;                           ///< density * omega^2: adds spin * r per unit volume along r

  [[nodiscard]] const Constitutive& law_at(int point) const {
    return point_laws.empty() ? law : point_laws[static_cast<std::size_t>(point)];
  }
  [[nodiscard]] int dof_count() const { return 2 * node_count; }
};

using ElementMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, max_element_dofs,
                                    max_element_dofs>;
using ElementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, max_element_dofs, 1>;

/// Condensed stiffness and equivalent nodal loads (thermal, initial strain and body force) of one
/// element, n x n and n (n = 2 x node_count; no heap: the capacity is fixed).
struct ElementMatrices {
  ElementMatrix K;
  ElementVector f;
};

/// Strain and stress at one point.
struct ElementState {
  Vec4 strain = Vec4::Zero();  ///< total strain (rr, zz, gamma_rz, th), thermal and initial parts included
  Vec4 stress = Vec4::Zero();  ///< (rr, zz, rz, th)
};

/// The states of one element: at each material point (point_count of them) and at its centre.
struct ElementStates {
  std::array<ElementState, max_material_points> point{};
  int point_count = 1;
  ElementState centre;
};

/// The element's stiffness and loads, by its family's kernel.
ElementMatrices element_matrices(const ElementData& e);

/// The element's states from its nodal displacements u (2 x node_count values).
ElementStates element_states(const ElementData& e, std::span<const double> u);

/// The centre state alone (the report's elements: their one material point).
ElementState element_state(const ElementData& e, std::span<const double> u);

/// The element's internal forces K u - f from the upper triangle of its K (what assembly reads).
/// Up to 8 unknowns on fixed 8 x 8 matrices, zero-padded: the report's elements and the gap
/// elements keep their digits.
ElementVector internal_forces(const ElementMatrices& m, const ElementVector& u);

}  // namespace saasgaps
